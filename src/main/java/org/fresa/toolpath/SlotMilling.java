package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.Feature.SlotEnd;
import org.fresa.stepnc.Feature.SlotEnd.EndType;
import org.fresa.stepnc.Tool;

/**
 * Slots (ISO 14649-10 slot) along a linear, circular or general path, in the slot frame: x along the path from its
 * middle, z the feature axis, the top at z 0 and the floor at minus the feature depth.
 *
 * <p>What each profile becomes:
 * <ul>
 * <li>square-U: the outline the path sweeps, cleared as a pocket in layers of the axial depth;
 * <li>rounded-U (walls down to a half circle of the width), partial circle (its arc as a
 * rounded-U's bottom) and vee (two walls at the included
 * angle, blended by the profile radius): the straight part as a square-U, then thin layers whose
 * outline is as wide as the cutter may reach at that depth without leaving the profile (a ball
 * end mill as wide as the slot follows the middle down to the bottom; a flat or bull-nose cutter
 * leaves steps and stops where its corner meets the walls);
 * <li>tee: with an end mill, the stem (a square-U of the stem width, to the full depth); with a
 * T_SLOT_MILL, the cross bar in one pass along the middle at the floor, the cutter entering and
 * leaving past an open end, where it cuts air;
 * <li>dovetail (a square-U whose sides lean in towards the top at one angle): with an end mill,
 * the neck; with a DOVETAIL_MILL, the undercut sides ({@link DovetailSlot});
 * <li>profiles or ends the planner cannot follow: refused with the reason.
 * </ul>
 * Ends, read as the profile turned about the vertical through the path's end: radiused ends are
 * half circles of each layer's width about the path's ends; flat ends are square to the path,
 * their corners rounded by corner_radius1 (the side left of the path) and corner_radius2; open
 * ends are cut square at the path's end like flat ones: the tool stays within the path's length.
 * Woodruff ends of a square-U slot are cut in layers within the end's arc; loop ends need a
 * closed course (the band about its island). Along a GENERAL_PATH see {@link SlotBands}.
 */
final class SlotMilling {

    /** Height of a layer where a rounded-U or vee profile narrows (mm): the steps a flat cutter leaves. */
    static final double SHAPED_LAYER_MM = 1.0;
    /** How far past an open end a T-slot mill goes down and comes back up, beyond its radius (mm). */
    static final double OPEN_END_CLEARANCE_MM = 2.0;
    /** Below this room beside the cutter (mm), a layer of mixed ends is cut along the middle only. */
    static final double CENTRE_ONLY_MM = 0.01;
    /** Room left beside a cutter that fits only along the middle of an arc's slot (mm), within the 0.01 mm allowed. */
    static final double ARC_CENTRE_ROOM_MM = 0.005;
    /** An arc of a smaller radius (mm) is a point: cut as a straight move to its end. */
    static final double NO_RADIUS_MM = 1e-4;
    /** Largest angle a tee's stem wall may differ from square to the cross bar (deg). */
    static final double SQUARE_TOLERANCE_DEG = 0.01;

    /**
     * Mills one layer outline from a top height down to a bottom height (mm), in the slot frame,
     * leaving the islands (a loop slot's inner wall) standing.
     */
    interface PocketCutter {
        ToolpathSection cut(Profile outline, List<Contour> islands, Heights heights);
    }

    private SlotMilling() {}

    /**
     * The moves of a slot in its frame.
     *
     * @param course the path in the slot frame: a straight length, or an arc about the frame's origin
     * @param pocket mills an outline as a pocket with the operation's strategy and entry rules
     * @throws UnsupportedOperationException with the reason when the slot cannot be machined with this tool
     */
    static ToolpathSection section(
            String label,
            Feature f,
            Tool tool,
            Tooling t,
            Heights h,
            Course course,
            double axialMm,
            Tolerance tol,
            List<String> problems,
            PocketCutter pocket) {
        org.fresa.stepnc.Profile shape =
                f.profile().orElseThrow(() -> new IllegalArgumentException("the slot has no swept shape"));
        List<SlotEnd> ends = f.slotEnds();
        for (SlotEnd e : ends) {
            switch (e.type()) {
                case WOODRUFF -> {
                    if (!(course instanceof Course.Straight) || !shape.entity().equals("SQUARE_U_PROFILE")) {
                        throw new UnsupportedOperationException("woodruff slot ends are machined on a SQUARE_U_PROFILE"
                                + " slot along a LINEAR_PATH only: its end rises along the path, which layers of a"
                                + " cutter along the feature axis follow there; this slot has a " + shape.entity()
                                + " along a "
                                + f.courseOfTravel().map(p -> p.entity()).orElse("none"));
                    }
                }
                case LOOP -> {
                    if (!(course instanceof Course.General g && g.closed())) {
                        throw new UnsupportedOperationException("loop slot ends are machined along a closed course"
                                + " of travel only (a full turn of a CIRCULAR_PATH, a closed GENERAL_PATH); the path"
                                + " is an open "
                                + f.courseOfTravel().map(p -> p.entity()).orElse("none"));
                    }
                }
                case OTHER ->
                    throw new UnsupportedOperationException("slot end not read: " + e.entity()
                            + "; an end cut square that is not would cut corners the part keeps");
                default -> {}
            }
        }
        if (course instanceof Course.General g && g.closed() && ends.stream().anyMatch(e -> e.type() != EndType.LOOP)) {
            throw new UnsupportedOperationException("the slot's course of travel is closed and its ends are not"
                    + " LOOP_SLOT_END_TYPE: a closed course has no ends");
        }
        boolean closed = course instanceof Course.General g && g.closed();
        if (!closed && ends.isEmpty()) {
            // ISO 14649-10 allows the list empty and says nothing of such ends: square keeps the
            // tool within the course of travel, which any other end would leave too
            problems.add("workingstep '" + label + "': the slot gives no end_conditions: both its ends are cut"
                    + " square, the tool kept within its course of travel");
        } else if (!closed && ends.size() == 1) {
            problems.add("workingstep '" + label + "': the slot gives one end condition ("
                    + ends.get(0).entity() + "): taken for both its ends");
        }
        double depth = -h.bottomZ();
        double r = t.radiusMm();
        double d = t.diameterMm();
        if (shape.entity().contains("DOVETAIL")) {
            throw new UnsupportedOperationException("a " + shape.entity() + " is no ISO 14649-10 profile: a dovetail"
                    + " is a SQUARE_U_PROFILE whose sides meet its base at one angle under 90 deg");
        }
        if (shape instanceof org.fresa.stepnc.Profile.U u
                && shape.entity().equals("SQUARE_U_PROFILE")
                && DovetailSlot.is(u)) {
            DovetailSlot.Shape dovetail = DovetailSlot.shape(u, depth);
            if (tool.body().equals("DOVETAIL_MILL")) {
                if (!(course instanceof Course.Straight straightCourse)) {
                    throw new UnsupportedOperationException("a DOVETAIL_MILL's sides are milled along a LINEAR_PATH"
                            + " only: it enters from an open end and goes along each side");
                }
                return DovetailSlot.sides(label, straightCourse.lengthMm(), dovetail, ends, tool, h, t, tol);
            }
            if (ends.stream().anyMatch(e -> e.type() == EndType.WOODRUFF)) {
                throw new UnsupportedOperationException("woodruff ends on a dovetail are not machined");
            }
            double neck = DovetailSlot.neckHalfWidth(dovetail, tool.body(), label, d, problems);
            return straight(label, course, neck, ends, h, t, tol, pocket);
        }
        if (shape instanceof org.fresa.stepnc.Profile.U u && shape.entity().equals("SQUARE_U_PROFILE")) {
            double w = checkedWidth(u.widthMm(), d, tol);
            squareSides(u, "slot's square U", label, problems);
            double fillet = bottomFillet(u, w, label, problems, tol);
            if (fillet > tol.linear()) {
                double e = cornerRadius(tool, r);
                if (e > fillet + tol.linear()) {
                    throw new UnsupportedOperationException("the cutter's corner radius " + mm(e)
                            + " mm is larger than the square U's " + mm(fillet) + " mm bottom fillets: it would"
                            + " leave them larger than drawn; a cutter with a corner of at most " + mm(fillet)
                            + " mm mills them");
                }
                if (ends.stream().anyMatch(x -> x.type() == EndType.WOODRUFF)) {
                    throw new UnsupportedOperationException("woodruff ends on a square U with bottom fillets are"
                            + " not machined: the fillets would have to follow the end's arc up to the top");
                }
                if (fillet - e > tol.linear()) {
                    return filleted(label, course, w / 2, fillet, e, r, ends, h, t, axialMm, tol, problems, pocket);
                }
            }
            if (ends.stream().anyMatch(e -> e.type() == EndType.WOODRUFF)) {
                return woodruff(
                        label,
                        ((Course.Straight) course).lengthMm(),
                        w / 2,
                        ends,
                        h,
                        t,
                        axialMm,
                        tol,
                        problems,
                        pocket);
            }
            return straight(label, course, w / 2, ends, h, t, tol, pocket);
        }
        if (shape instanceof org.fresa.stepnc.Profile.U u) {
            double w = checkedWidth(u.widthMm(), d, tol);
            return circular(
                    label,
                    course,
                    w / 2,
                    -depth + w / 2,
                    -depth,
                    "rounded-U",
                    tool,
                    r,
                    ends,
                    h,
                    t,
                    axialMm,
                    tol,
                    problems,
                    pocket);
        }
        if (shape instanceof org.fresa.stepnc.Profile.PartialCircular pc) {
            PartialCircle arc = partialCircle(pc, tol);
            checkedWidth(2 * Math.sqrt(Math.max(arc.radius() * arc.radius() - arc.zc() * arc.zc(), 0)), d, tol);
            double bottom = arc.zc() - arc.radius();
            if (depth > tol.linear() && Math.abs(depth + bottom) > tol.linear()) {
                problems.add("workingstep '" + label + "': the depth plane (" + mm(depth) + " mm) and the partial"
                        + " circular profile (" + mm(-bottom) + " mm deep) disagree; the profile is cut");
            } else if (!(depth > tol.linear())) {
                problems.add("workingstep '" + label + "': the depth plane is at the slot's top; the partial circular"
                        + " profile gives its depth, " + mm(-bottom) + " mm");
            }
            return circular(
                    label,
                    course,
                    arc.radius(),
                    arc.zc(),
                    bottom,
                    "partial circle",
                    tool,
                    r,
                    ends,
                    h,
                    t,
                    axialMm,
                    tol,
                    problems,
                    pocket);
        }
        if (shape instanceof org.fresa.stepnc.Profile.Vee v) {
            double angle = v.profileAngleDeg();
            if (!(angle > 0 && angle < 180)) {
                throw new IllegalArgumentException("vee profile_angle " + angle + " deg is outside 0 to 180 deg");
            }
            // tilt_angle is the first wall's angle from the profile's x axis, across the slot: the
            // V stands upright when its bisector is square to it (GRIMA's 90 deg vee has 45)
            double lean = v.tiltAngleDeg() + angle / 2 - 90;
            if (Math.abs(lean) > SQUARE_TOLERANCE_DEG) {
                throw new UnsupportedOperationException(
                        "the vee leans by " + mm(lean) + " deg (tilt_angle " + mm(v.tiltAngleDeg()) + " deg for a "
                                + mm(angle) + " deg vee): the layers follow upright vees only");
            }
            double a = Math.toRadians(angle / 2);
            double rho = Math.max(v.profileRadiusMm().orElse(0), 0);
            double zc = -depth + rho;
            double zApex = zc - rho / Math.sin(a);
            double zTangent = zc - rho * Math.sin(a);
            DoubleUnaryOperator half = z ->
                    z >= zTangent ? (z - zApex) * Math.tan(a) : Math.sqrt(Math.max(rho * rho - (z - zc) * (z - zc), 0));
            if (half.applyAsDouble(0) < r - tol.linear()) {
                throw new UnsupportedOperationException("the tool (" + mm(d) + " mm) is wider than the vee at its top ("
                        + mm(2 * half.applyAsDouble(0)) + " mm)");
            }
            double floor = r >= rho * Math.cos(a) ? zApex + r / Math.tan(a) : zc - Math.sqrt(rho * rho - r * r);
            floor = Math.max(floor, -depth);
            problems.add("workingstep '" + label + "': the " + mm(d) + " mm cutter follows the vee in "
                    + mm(SHAPED_LAYER_MM) + " mm steps down to " + mm(-floor) + " mm of its " + mm(depth) + " mm");
            return shaped(label, course, 0, floor, z -> half.applyAsDouble(z) - r, r, ends, h, t, axialMm, tol, pocket);
        }
        if (shape instanceof org.fresa.stepnc.Profile.Tee tee) {
            if (Math.abs(tee.firstAngleDeg() - 90) > SQUARE_TOLERANCE_DEG
                    || Math.abs(tee.secondAngleDeg() - 90) > SQUARE_TOLERANCE_DEG) {
                throw new UnsupportedOperationException(
                        "the tee's stem walls meet the cross bar at " + mm(tee.firstAngleDeg()) + " and "
                                + mm(tee.secondAngleDeg()) + " deg: only a square stem is machined");
            }
            if (!(tee.crossBarDepthMm() > 0
                    && tee.crossBarDepthMm() < depth
                    && tee.crossBarWidthMm() > tee.widthMm())) {
                throw new IllegalArgumentException("the tee's cross bar (" + mm(tee.crossBarWidthMm()) + " by "
                        + mm(tee.crossBarDepthMm()) + " mm) does not fit under its " + mm(tee.widthMm())
                        + " mm stem in the slot's depth " + mm(depth) + " mm");
            }
            if (tool.body().equals("T_SLOT_MILL")) {
                if (course instanceof Course.Arc arcCourse) {
                    checkTSlotMill(tee, tool, t, tol);
                    return crossBarAlongArc(label, arcCourse, ends, h, t);
                }
                if (!(course instanceof Course.Straight straightCourse)) {
                    throw new UnsupportedOperationException("a T_SLOT_MILL's cross bar is milled along a LINEAR_PATH"
                            + " or a CIRCULAR_PATH only: it enters from an open end and goes along the middle");
                }
                return crossBar(label, straightCourse.lengthMm(), tee, ends, tool, h, t, tol);
            }
            double w = checkedWidth(tee.widthMm(), d, tol);
            problems.add("workingstep '" + label + "': the " + tool.body() + " mills the tee's stem; its cross bar"
                    + " needs a T_SLOT_MILL");
            return straight(label, course, w / 2, ends, h, t, tol, pocket);
        }
        throw new UnsupportedOperationException("slots with a " + shape.entity() + " are not supported yet");
    }

    private static double checkedWidth(double widthMm, double d, Tolerance tol) {
        if (!(widthMm > 0 && widthMm <= ToolpathPlanner.MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "slot width " + widthMm + " mm is outside 0 to " + ToolpathPlanner.MAX_LENGTH_MM + " mm");
        }
        if (d > widthMm + tol.linear()) {
            throw new UnsupportedOperationException(
                    "the tool (" + mm(d) + " mm) is wider than the slot (" + mm(widthMm) + " mm)");
        }
        return widthMm;
    }

    /**
     * A cross-section bounded below by a circle of the radius about (0, zc) in the slot's
     * profile plane, its walls straight and upright above the centre (a rounded-U; a partial
     * circle's arc ends at or above the top), down to the bottom.
     */
    private static ToolpathSection circular(
            String label,
            Course course,
            double big,
            double zc,
            double bottom,
            String name,
            Tool tool,
            double r,
            List<SlotEnd> ends,
            Heights h,
            Tooling t,
            double axialMm,
            Tolerance tol,
            List<String> problems,
            PocketCutter pocket) {
        double d = 2 * r;
        double e = cornerRadius(tool, r);
        if (e > big + tol.linear() || big - e < -tol.linear()) {
            throw new UnsupportedOperationException("the cutter's corner radius " + e + " mm is larger than the" + " "
                    + name + "'s radius " + big + " mm");
        }
        double re = Math.max(big - e, 0);
        double ce = Math.max(r - e, 0);
        double floor = Math.max(zc - e - Math.sqrt(Math.max(re * re - ce * ce, 0)), bottom);
        DoubleUnaryOperator reach =
                z -> z + e >= zc ? big - r : Math.sqrt(Math.max(re * re - (z + e - zc) * (z + e - zc), 0)) - ce;
        if (floor > bottom + tol.linear()) {
            problems.add("workingstep '" + label + "': the " + mm(d) + " mm cutter reaches " + mm(-floor)
                    + " mm of the " + name + "'s " + mm(-bottom)
                    + (zc > tol.linear()
                            ? " mm; a ball end mill no wider than the circle (" + mm(2 * big)
                                    + " mm) reaches the bottom"
                            : " mm; a ball end mill as wide as the slot reaches the bottom"));
        }
        return shaped(label, course, Math.min(0, zc), floor, reach, r, ends, h, t, axialMm, tol, pocket);
    }

    /**
     * Refuses a square U whose sides do not stand square to its bottom: a cutter along the
     * feature axis mills upright walls only. An angle written 0 (a side lying along the bottom,
     * which is no side: GRIMA's writers put 0 for an angle they leave unset) is read as square and
     * reported.
     */
    static void squareSides(org.fresa.stepnc.Profile.U u, String what, String label, List<String> problems) {
        java.util.OptionalDouble[] angles = {u.firstAngleDeg(), u.secondAngleDeg()};
        String[] names = {"first_angle", "second_angle"};
        for (int i = 0; i < 2; i++) {
            if (angles[i].isEmpty()) {
                continue;
            }
            double a = angles[i].getAsDouble();
            if (Math.abs(a) < 1e-9) {
                problems.add("workingstep '" + label + "': the " + what + "'s " + names[i] + " is written 0 deg (a"
                        + " side along its bottom): read as a side square to the bottom");
            } else if (Math.abs(a - 90) > SQUARE_TOLERANCE_DEG) {
                throw new UnsupportedOperationException("the " + what + " has a side at " + mm(a)
                        + " deg to its bottom (" + names[i] + "): only sides square to it are milled"
                        + (Math.abs(a - Math.PI / 2) < 1e-4
                                ? "; the file writes pi / 2, a right angle in radians where ISO 14649 writes 90"
                                : ""));
            }
        }
    }

    /**
     * The radius of the fillets between a square U's bottom and its sides (0 for sharp corners):
     * the larger of the two when they differ, so that the cutter stays out of both (reported).
     */
    private static double bottomFillet(
            org.fresa.stepnc.Profile.U u, double widthMm, String label, List<String> problems, Tolerance tol) {
        double r1 = u.firstRadiusMm().orElse(0);
        double r2 = u.secondRadiusMm().orElse(0);
        if (r1 < 0 || r2 < 0) {
            throw new IllegalArgumentException(
                    "the square U's radii " + r1 + " and " + r2 + " mm must not be negative");
        }
        double fillet = Math.max(r1, r2);
        if (fillet > widthMm / 2 + tol.linear()) {
            throw new IllegalArgumentException("the square U's bottom fillet of " + mm(fillet) + " mm does not fit its "
                    + mm(widthMm) + " mm width");
        }
        if (Math.abs(r1 - r2) > tol.linear()) {
            problems.add("workingstep '" + label + "': the square U's bottom fillets of " + mm(r1) + " and " + mm(r2)
                    + " mm are both milled with the larger");
        }
        return Math.min(fillet, widthMm / 2);
    }

    /**
     * A square U whose bottom fillets are larger than the cutter's corner: upright walls down to
     * the fillets' top, then layers each as wide as the cutter's corner may go there without
     * entering a fillet (steps are left on the fillets, never cut into them), down to the floor or
     * as far as the flat of the cutter's end fits between the fillets.
     */
    private static ToolpathSection filleted(
            String label,
            Course course,
            double halfWidth,
            double fillet,
            double e,
            double r,
            List<SlotEnd> ends,
            Heights h,
            Tooling t,
            double axialMm,
            Tolerance tol,
            List<String> problems,
            PocketCutter pocket) {
        double bottom = h.bottomZ();
        double zc = bottom + fillet;
        double re = fillet - e;
        double ce = Math.max(r - e, 0);
        double flat = halfWidth - fillet;
        // the corner's centre, (ce + reach) from the middle and e above the tip, keeps within
        // re of the fillet's centre, (flat) from the middle at zc
        DoubleUnaryOperator reach = z ->
                z + e >= zc ? halfWidth - r : flat + Math.sqrt(Math.max(re * re - (z + e - zc) * (z + e - zc), 0)) - ce;
        double q = ce - flat;
        double floor = q <= 0 ? bottom : q >= re ? zc - e : zc - e - Math.sqrt(re * re - q * q);
        double layer = axialMm > 0 ? Math.min(axialMm, SHAPED_LAYER_MM) : SHAPED_LAYER_MM;
        problems.add("workingstep '" + label + "': the square U's " + mm(fillet) + " mm bottom fillets are milled by"
                + " the cutter's " + mm(e) + " mm corner in layers of at most " + mm(layer)
                + " mm, leaving steps on them");
        if (floor > bottom + tol.linear()) {
            problems.add("workingstep '" + label + "': the " + mm(2 * r) + " mm cutter reaches " + mm(-floor)
                    + " mm of the square U's " + mm(-bottom) + " mm: its flat end is wider than the floor between"
                    + " the fillets; a cutter whose corner is the fillets' radius reaches the bottom");
        }
        return shaped(label, course, Math.min(0, zc), floor, reach, r, ends, h, t, axialMm, tol, pocket);
    }

    /**
     * A square-U slot with woodruff ends (ISO 14649-10 woodruff_slot_end_type: the end is the
     * arc of a woodruff cutter of the radius, in the path's vertical plane): the floor ends at the
     * path's end and rises beyond it along the arc about the point the radius above the floor
     * there, to the top. A cutter along the feature axis cuts it in layers, each square-ended where
     * the arc is at the layer's bottom, so the tool stays inside the arc and leaves steps along it.
     */
    private static ToolpathSection woodruff(
            String label,
            double length,
            double halfWidth,
            List<SlotEnd> ends,
            Heights h,
            Tooling t,
            double axialMm,
            Tolerance tol,
            List<String> problems,
            PocketCutter pocket) {
        double depth = h.topZ() - h.bottomZ();
        SlotEnd start = ends.isEmpty() ? null : ends.get(0);
        SlotEnd end = ends.size() < 2 ? start : ends.get(1);
        double r0 = woodruffRadius(start, depth);
        double r1 = woodruffRadius(end, depth);
        List<SlotEnd> square = new ArrayList<>();
        for (SlotEnd e : ends) {
            square.add(
                    e.type() == EndType.WOODRUFF
                            ? new SlotEnd(
                                    EndType.FLAT,
                                    e.entity(),
                                    java.util.OptionalDouble.empty(),
                                    java.util.OptionalDouble.empty())
                            : e);
        }
        double step = axialMm > 0 ? Math.min(axialMm, SHAPED_LAYER_MM) : SHAPED_LAYER_MM;
        int n = (int) Math.ceil(depth / step - 1e-9);
        List<ToolpathSection> parts = new ArrayList<>();
        double prev = h.topZ();
        double steps = 0;
        for (int i = 1; i <= n; i++) {
            double z = i == n ? h.bottomZ() : h.topZ() - depth * i / n;
            double e0 = beyond(r0, z - h.bottomZ());
            double e1 = beyond(r1, z - h.bottomZ());
            steps = Math.max(steps, Math.max(beyond(r0, prev - h.bottomZ()) - e0, beyond(r1, prev - h.bottomZ()) - e1));
            Profile outline = outline(length + e0 + e1, halfWidth, t.radiusMm(), square, tol);
            Vec2 shift = new Vec2((e1 - e0) / 2, 0);
            parts.add(pocket.cut(
                    outline instanceof Profile.RoundedRectangle rr
                            ? new Profile.RoundedRectangle(
                                    rr.center().plus(shift), rr.xLengthMm(), rr.yLengthMm(), rr.cornerRadiusMm())
                            : new Profile.General(outline.contour(tol).translated(shift), ContourOffsetter.EXACT),
                    List.of(),
                    new Heights(h.clearanceZ(), h.retractZ(), prev, z)));
            prev = z;
        }
        problems.add("workingstep '" + label + "': the woodruff end is cut in " + n + " layers square to the path,"
                + " each as long as the end's arc at its bottom: steps up to " + mm(steps) + " mm are left along"
                + " the arc, and the " + mm(t.radiusMm()) + " mm corners of the cutter in each layer's ends");
        return join(label, parts);
    }

    /** A woodruff end's radius, 0 for any other end (which stays at the path's end). */
    private static double woodruffRadius(SlotEnd e, double depth) {
        if (e == null || e.type() != EndType.WOODRUFF) {
            return 0;
        }
        double radius = e.firstRadiusMm()
                .orElseThrow(() -> new IllegalArgumentException("the woodruff slot end has no radius"));
        if (!(radius > 0 && radius <= ToolpathPlanner.MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("woodruff slot end radius " + radius + " mm is outside 0 to "
                    + ToolpathPlanner.MAX_LENGTH_MM + " mm");
        }
        if (radius < depth) {
            throw new UnsupportedOperationException("the woodruff end's radius (" + mm(radius) + " mm) is less than"
                    + " the slot's depth (" + mm(depth) + " mm): its arc does not reach the top");
        }
        return radius;
    }

    /** How far beyond the path's end a woodruff end of the radius reaches at the height above the floor. */
    private static double beyond(double radius, double above) {
        if (radius <= 0) {
            return 0;
        }
        double dz = radius - above;
        return Math.sqrt(Math.max(radius * radius - dz * dz, 0));
    }

    /** A partial circle's radius and the height of its centre above the slot's top (mm). */
    record PartialCircle(double radius, double zc) {}

    /**
     * The arc of a PARTIAL_CIRCULAR_PROFILE in the slot: its axis along the path (square to the
     * feature's), its ends level on either side of its lowest point, at or above the slot's top.
     */
    static PartialCircle partialCircle(org.fresa.stepnc.Profile.PartialCircular pc, Tolerance tol) {
        double radius = pc.radiusMm();
        if (!(radius > 0 && radius <= ToolpathPlanner.MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("partial circular profile radius " + radius + " mm is outside 0 to "
                    + ToolpathPlanner.MAX_LENGTH_MM + " mm");
        }
        double sweep = pc.sweepAngleDeg();
        if (!(sweep > 0 && sweep <= 180 + SQUARE_TOLERANCE_DEG)) {
            throw new UnsupportedOperationException("the partial circular profile sweeps " + mm(sweep) + " deg: more"
                    + " than a half circle is wider below the top than at it, which a cutter along the feature axis"
                    + " cannot reach");
        }
        org.fresa.geom.Transform3 pl = pc.placement();
        Vec3 axis = pl.zAxis();
        if (Math.abs(axis.z()) > 1e-9) {
            throw new UnsupportedOperationException("the partial circular profile's axis is not square to the"
                    + " feature's: the slot's cross-section must stand upright");
        }
        Vec3 x = pl.applyToDirection(Vec3.UNIT_X);
        Vec3 y = axis.cross(x);
        double a = Math.toRadians(sweep);
        Vec3 endDir = x.times(Math.cos(a)).plus(y.times(Math.sin(a)));
        double zc = pl.translationPart().z();
        // the file's numbers are written to a few decimals: level as a drawing is
        if (Math.abs(x.z() - endDir.z()) * radius > Tolerance.DRAWING.linear()) {
            throw new UnsupportedOperationException("the partial circular profile's ends are not level ("
                    + mm(zc + radius * x.z()) + " and " + mm(zc + radius * endDir.z())
                    + " mm): only an arc symmetric about the slot's middle is cut");
        }
        Vec3 middle = x.times(Math.cos(a / 2)).plus(y.times(Math.sin(a / 2)));
        if (middle.z() > -0.5) {
            throw new UnsupportedOperationException(
                    "the partial circular profile's arc does not pass below its" + " centre: it is no slot's floor");
        }
        double zEnds = zc + radius * x.z();
        if (zEnds < -tol.linear()) {
            throw new UnsupportedOperationException("the partial circular profile's ends are " + mm(-zEnds)
                    + " mm below the slot's top: the cross-section does not reach the top");
        }
        return new PartialCircle(radius, zc);
    }

    /** The cutter's corner radius: a ball end mill's is its radius. */
    private static double cornerRadius(Tool tool, double r) {
        if (tool.body().equals("BALL_ENDMILL")) {
            return r;
        }
        double e = tool.edgeRadiusMm().orElse(0);
        return e > 0 ? Math.min(e, r) : 0;
    }

    private static ToolpathSection straight(
            String label,
            Course course,
            double halfWidth,
            List<SlotEnd> ends,
            Heights h,
            Tooling t,
            Tolerance tol,
            PocketCutter pocket) {
        return join(
                label,
                List.of(pocket.cut(
                        course.outline(halfWidth, t.radiusMm(), ends, tol),
                        course.islands(halfWidth, t.radiusMm(), tol),
                        h)));
    }

    /**
     * The straight-walled part down to zStraight as a square-U, then layers down to the floor,
     * each as wide as the cutter may reach there.
     *
     * @param reach how far the cutter's centre may go from the middle with its tip at z (mm)
     */
    private static ToolpathSection shaped(
            String label,
            Course course,
            double zStraight,
            double floor,
            DoubleUnaryOperator reach,
            double r,
            List<SlotEnd> ends,
            Heights h,
            Tooling t,
            double axialMm,
            Tolerance tol,
            PocketCutter pocket) {
        List<ToolpathSection> parts = new ArrayList<>();
        double top = h.topZ();
        if (zStraight < top - tol.linear()) {
            double z = Math.max(zStraight, floor);
            double half = Math.max(reach.applyAsDouble(z), 0) + r;
            parts.add(pocket.cut(
                    course.outline(half, r, ends, tol),
                    course.islands(half, r, tol),
                    new Heights(h.clearanceZ(), h.retractZ(), top, z)));
            top = z;
        }
        double step = axialMm > 0 ? Math.min(axialMm, SHAPED_LAYER_MM) : SHAPED_LAYER_MM;
        if (top - floor > tol.linear()) {
            int n = (int) Math.ceil((top - floor) / step - 1e-9);
            double prev = top;
            for (int i = 1; i <= n; i++) {
                double z = i == n ? floor : top - (top - floor) * i / n;
                double half = Math.max(reach.applyAsDouble(z), 0) + r;
                parts.add(pocket.cut(
                        course.outline(half, r, ends, tol),
                        course.islands(half, r, tol),
                        new Heights(h.clearanceZ(), h.retractZ(), prev, z)));
                prev = z;
            }
        }
        return join(label, parts);
    }

    /**
     * A loop slot's layer: the band between its outer wall and the island inside it, cleared
     * contour-parallel by the pocket module's region pocketing, each loop entered by a ramp along
     * itself.
     *
     * @param stepoverMm the radial step between loops
     * @param climb whether the cutter climbs (it turns counter-clockwise about the island)
     */
    static ToolpathSection band(
            String label,
            Contour outer,
            List<Contour> islands,
            Heights h,
            Tooling t,
            double stepoverMm,
            double axialMm,
            boolean climb,
            org.fresa.pocket.EntryRule entry) {
        double depth = h.topZ() - h.bottomZ();
        if (!(depth > 0)) {
            throw new IllegalArgumentException("the loop slot's layer has no depth");
        }
        org.fresa.pocket.PocketTechnology tech =
                t.regionTechnology(stepoverMm, h.topZ(), h.bottomZ(), axialMm > 0 ? axialMm : depth);
        org.fresa.model.Toolpath path;
        try {
            path = org.fresa.pocket.RegionPocket.plan(outer, islands, tech, climb, entry)
                    .toolpath();
        } catch (org.fresa.pocket.ToolTooLargeException e) {
            throw new UnsupportedOperationException(e.getMessage());
        }
        ToolpathSection s = path.sections().get(0);
        return new ToolpathSection(
                label, s.toolAxis(), t.diameterMm(), t.toolNumber(), t.spindleRpm(), s.start(), s.moves());
    }

    /** One section of the parts in order, the tool going from the end of each to the start of the next at clearance. */
    private static ToolpathSection join(String label, List<ToolpathSection> parts) {
        List<Move> moves = new ArrayList<>();
        ToolpathSection first = parts.get(0);
        Vec3 at = first.start();
        for (int i = 0; i < parts.size(); i++) {
            ToolpathSection s = parts.get(i);
            if (i > 0) {
                moves.add(new Move.Rapid(s.start()));
            }
            for (Move m : s.moves()) {
                // the loops of a layer narrowed to the cutter's width close on arcs of no radius,
                // which go nowhere and which a control refuses
                if (m instanceof Move.Circular c && c.center().distance(at) < NO_RADIUS_MM) {
                    moves.add(new Move.Linear(c.end(), c.feedMmPerMin()));
                    at = m.end();
                    continue;
                }
                moves.add(m);
                at = m.end();
            }
        }
        return new ToolpathSection(
                label,
                first.toolAxis(),
                first.toolDiameterMm(),
                first.toolNumber(),
                first.spindleRpm(),
                first.start(),
                moves);
    }

    /**
     * A slot's course of travel in the slot frame (z the feature axis), which gives the outline
     * the tool may sweep at a half width.
     */
    sealed interface Course {
        /** The outline at this half width, with the slot's ends. */
        Profile outline(double halfWidth, double toolRadius, List<SlotEnd> ends, Tolerance tol);

        /** What stands inside the outline at this half width: nothing but for a loop. */
        default List<Contour> islands(double halfWidth, double toolRadius, Tolerance tol) {
            return List.of();
        }

        /**
         * A LINEAR_PATH: x along it from its middle.
         *
         * @param lengthMm the path's length
         */
        record Straight(double lengthMm) implements Course {
            @Override
            public Profile outline(double halfWidth, double toolRadius, List<SlotEnd> ends, Tolerance tol) {
                return SlotMilling.outline(lengthMm, halfWidth, toolRadius, ends, tol);
            }
        }

        /**
         * A CIRCULAR_PATH: an arc about the frame's origin, from the point on its x axis at the
         * radius, counter-clockwise about its z for a positive sweep (clockwise for a negative one).
         *
         * @param radiusMm the path's radius
         * @param sweepRad the signed sweep, less than a full turn
         */
        record Arc(double radiusMm, double sweepRad) implements Course {
            public Arc {
                if (!(radiusMm > 0 && radiusMm <= ToolpathPlanner.MAX_LENGTH_MM)) {
                    throw new IllegalArgumentException("the circular path's radius " + radiusMm + " mm is outside 0 to "
                            + ToolpathPlanner.MAX_LENGTH_MM + " mm");
                }
                if (!(Math.abs(sweepRad) > 1e-9 && Math.abs(sweepRad) < 2 * Math.PI - 1e-9)) {
                    throw new UnsupportedOperationException("the circular path's sweep_angle " + sweepRad
                            + " (radians) is not between 0 and a full turn: a closed course is a loop, not machined");
                }
            }

            @Override
            public Profile outline(double halfWidth, double toolRadius, List<SlotEnd> ends, Tolerance tol) {
                // where the cutter fits only along the middle, the pocket's inset of an outline as
                // wide as the cutter is a curve of no area: a hair of room keeps it a loop along the
                // middle, the tool leaving the slot's walls by no more than that hair
                return arcOutline(this, Math.max(halfWidth, toolRadius + ARC_CENTRE_ROOM_MM), ends, tol);
            }
        }

        /**
         * A GENERAL_PATH: its lines and arcs in the slot frame, open; or closed (a loop: the
         * band between its walls, counter-clockwise), as is a full turn of a CIRCULAR_PATH.
         */
        record General(List<Curve2> path, boolean closed) implements Course {
            public General {
                path = List.copyOf(path);
                if (path.isEmpty()) {
                    throw new IllegalArgumentException("the slot's general path has no curve");
                }
            }

            @Override
            public Profile outline(double halfWidth, double toolRadius, List<SlotEnd> ends, Tolerance tol) {
                double hw = withRoom(halfWidth, toolRadius);
                Contour c = closed ? SlotBands.closedOuter(path, hw, tol) : SlotBands.openOutline(path, hw, ends, tol);
                return new Profile.General(c, ContourOffsetter.EXACT);
            }

            @Override
            public List<Contour> islands(double halfWidth, double toolRadius, Tolerance tol) {
                return closed ? List.of(SlotBands.closedInner(path, withRoom(halfWidth, toolRadius), tol)) : List.of();
            }
        }
    }

    /**
     * Where the cutter fits only along the middle, the pocket's inset of an outline as wide as
     * the cutter is a curve of no area: a hair of room keeps it a loop along the middle, the tool
     * leaving the slot's walls by no more than that hair.
     */
    private static double withRoom(double halfWidth, double toolRadius) {
        return Math.max(halfWidth, toolRadius + ARC_CENTRE_ROOM_MM);
    }

    /**
     * The outline of a slot along an arc at one half width: an annular sector between the
     * radii less and more the half width, its ends square to the path (open, flat) or half
     * circles of the half width about the path's end points (radiused); arcs stay arcs.
     */
    static Profile arcOutline(Course.Arc c, double halfWidth, List<SlotEnd> ends, Tolerance tol) {
        SlotEnd first = ends.isEmpty() ? null : ends.get(0);
        SlotEnd last = ends.size() < 2 ? first : ends.get(1);
        double rIn = c.radiusMm() - halfWidth;
        double rOut = c.radiusMm() + halfWidth;
        if (!(rIn > tol.linear())) {
            throw new UnsupportedOperationException("the slot (" + mm(2 * halfWidth) + " mm wide here) is wider than"
                    + " twice its circular path's radius (" + mm(c.radiusMm()) + " mm)");
        }
        // counter-clockwise from a0 to a1; a clockwise path is the same outline with its ends swapped
        double a0 = Math.min(0, c.sweepRad());
        double a1 = Math.max(0, c.sweepRad());
        SlotEnd atA0 = c.sweepRad() > 0 ? first : last;
        SlotEnd atA1 = c.sweepRad() > 0 ? last : first;
        // corner_radius1 is on the path's left: towards the centre on a counter-clockwise path
        boolean leftIsInner = c.sweepRad() > 0;
        double in0 = cornerRadius(atA0, leftIsInner, halfWidth);
        double out0 = cornerRadius(atA0, !leftIsInner, halfWidth);
        double in1 = cornerRadius(atA1, leftIsInner, halfWidth);
        double out1 = cornerRadius(atA1, !leftIsInner, halfWidth);
        // a corner's fillet touches the wall this far round from the end: sin = r / (its centre's radius)
        double dOut0 = Math.asin(out0 / (rOut - out0));
        double dOut1 = Math.asin(out1 / (rOut - out1));
        double dIn0 = Math.asin(in0 / (rIn + in0));
        double dIn1 = Math.asin(in1 / (rIn + in1));
        if (a1 - dOut1 < a0 + dOut0 || a1 - dIn1 < a0 + dIn0) {
            throw new UnsupportedOperationException(
                    "the flat ends' corner radii do not fit along the slot's " + mm(Math.toDegrees(a1 - a0)) + " deg");
        }
        List<Curve2> cs = new ArrayList<>();
        Vec2 o = Vec2.ZERO;
        cs.add(new Arc2(o, polar(rOut, a0 + dOut0), polar(rOut, a1 - dOut1), true));
        if (isRadiused(atA1)) {
            cs.add(new Arc2(polar(c.radiusMm(), a1), polar(rOut, a1), polar(rIn, a1), true));
        } else {
            double lOut = Math.sqrt((rOut - out1) * (rOut - out1) - out1 * out1);
            double lIn = Math.sqrt((rIn + in1) * (rIn + in1) - in1 * in1);
            if (out1 > 0) {
                cs.add(new Arc2(polar(rOut - out1, a1 - dOut1), polar(rOut, a1 - dOut1), polar(lOut, a1), true));
            }
            if (lOut - lIn > 1e-12) {
                cs.add(new Segment2(polar(lOut, a1), polar(lIn, a1)));
            }
            if (in1 > 0) {
                cs.add(new Arc2(polar(rIn + in1, a1 - dIn1), polar(lIn, a1), polar(rIn, a1 - dIn1), true));
            }
        }
        cs.add(new Arc2(o, polar(rIn, a1 - dIn1), polar(rIn, a0 + dIn0), false));
        if (isRadiused(atA0)) {
            cs.add(new Arc2(polar(c.radiusMm(), a0), polar(rIn, a0), polar(rOut, a0), true));
        } else {
            double lOut = Math.sqrt((rOut - out0) * (rOut - out0) - out0 * out0);
            double lIn = Math.sqrt((rIn + in0) * (rIn + in0) - in0 * in0);
            if (in0 > 0) {
                cs.add(new Arc2(polar(rIn + in0, a0 + dIn0), polar(rIn, a0 + dIn0), polar(lIn, a0), true));
            }
            if (lOut - lIn > 1e-12) {
                cs.add(new Segment2(polar(lIn, a0), polar(lOut, a0)));
            }
            if (out0 > 0) {
                cs.add(new Arc2(polar(rOut - out0, a0 + dOut0), polar(lOut, a0), polar(rOut, a0 + dOut0), true));
            }
        }
        return new Profile.General(Contour.of(cs, Tolerance.DRAWING), ContourOffsetter.EXACT);
    }

    /**
     * A flat end's corner radius on one side of the path (corner_radius1 on its left), no more
     * than the half width; 0 for other ends.
     */
    private static double cornerRadius(SlotEnd e, boolean left, double halfWidth) {
        if (e == null || e.type() != EndType.FLAT) {
            return 0;
        }
        double r = left ? e.firstRadiusMm().orElse(0) : e.secondRadiusMm().orElse(0);
        return Math.min(Math.max(r, 0), halfWidth);
    }

    private static Vec2 polar(double r, double a) {
        return new Vec2(r * Math.cos(a), r * Math.sin(a));
    }

    /**
     * The outline the tool may sweep at one height: the path's length by twice the half width,
     * its ends radiused (half circles of the half width), flat with their corner radii, or square.
     */
    static Profile outline(double length, double halfWidth, double toolRadius, List<SlotEnd> ends, Tolerance tol) {
        SlotEnd start = ends.isEmpty() ? null : ends.get(0);
        SlotEnd end = ends.size() < 2 ? start : ends.get(1);
        double half = length / 2;
        if (isSquare(start) && isSquare(end)) {
            // the outline the square-U slots were always milled to
            return new Profile.RoundedRectangle(Vec2.ZERO, length, 2 * halfWidth, 0);
        }
        if (isRadiused(start) && isRadiused(end)) {
            return new Profile.RoundedRectangle(Vec2.ZERO, length + 2 * halfWidth, 2 * halfWidth, halfWidth);
        }
        if (halfWidth - toolRadius < CENTRE_ONLY_MM) {
            // the cutter fits only along the middle: a strip as wide as the cutter whose ends
            // keep its centre within each end's reach (a radiused end's centre, a flat end less
            // the radius), which the cutter's disc sweeps without leaving the outline
            double x0 = isRadiused(start) ? -half : -half + toolRadius;
            double x1 = isRadiused(end) ? half : half - toolRadius;
            return new Profile.RoundedRectangle(
                    new Vec2((x0 + x1) / 2, 0), x1 - x0 + 2 * toolRadius, 2 * toolRadius, 0);
        }
        List<Curve2> cs = new ArrayList<>();
        Vec2 at = new Vec2(-half, -halfWidth);
        at = cap(cs, at, new Vec2(half, 0), new Vec2(1, 0), halfWidth, end, tol);
        cs.add(new Segment2(at, new Vec2(-half, halfWidth)));
        at = new Vec2(-half, halfWidth);
        at = cap(cs, at, new Vec2(-half, 0), new Vec2(-1, 0), halfWidth, start, tol);
        if (at.distance(new Vec2(-half, -halfWidth)) > 1e-12) {
            cs.add(new Segment2(at, new Vec2(-half, -halfWidth)));
        }
        return new Profile.General(Contour.of(cs, Tolerance.DRAWING), ContourOffsetter.EXACT);
    }

    private static boolean isSquare(SlotEnd e) {
        return e == null
                || e.type() == EndType.OPEN
                || e.type() == EndType.FLAT
                        && !(e.firstRadiusMm().orElse(0) > 0)
                        && !(e.secondRadiusMm().orElse(0) > 0);
    }

    private static boolean isRadiused(SlotEnd e) {
        return e != null && e.type() == EndType.RADIUSED;
    }

    /**
     * Adds, counter-clockwise from the point along the right-hand wall, the wall up to the end and
     * the end itself about the path's end point c (u: the outward direction along the path).
     *
     * @return the point where the left-hand wall starts back
     */
    private static Vec2 cap(List<Curve2> cs, Vec2 from, Vec2 c, Vec2 u, double hw, SlotEnd e, Tolerance tol) {
        Vec2 n = new Vec2(-u.y(), u.x()); // to the left of the outward direction
        Vec2 right = c.minus(n.times(hw));
        Vec2 left = c.plus(n.times(hw));
        if (isRadiused(e)) {
            if (from.distance(right) > 1e-12) {
                cs.add(new Segment2(from, right));
            }
            cs.add(new Arc2(c, right, left, true));
            return left;
        }
        // outward along the path, the right-hand corner is the path's left side when coming back: radius 2 then 1
        double rRight = isSquare(e)
                ? 0
                : Math.min(
                        Math.max(
                                u.x() > 0
                                        ? e.secondRadiusMm().orElse(0)
                                        : e.firstRadiusMm().orElse(0),
                                0),
                        hw);
        double rLeft = isSquare(e)
                ? 0
                : Math.min(
                        Math.max(
                                u.x() > 0
                                        ? e.firstRadiusMm().orElse(0)
                                        : e.secondRadiusMm().orElse(0),
                                0),
                        hw);
        Vec2 a = right.minus(u.times(rRight));
        if (from.distance(a) > 1e-12) {
            cs.add(new Segment2(from, a));
        }
        Vec2 b = right.plus(n.times(rRight));
        if (rRight > 0) {
            cs.add(new Arc2(a.plus(n.times(rRight)), a, b, true));
        }
        Vec2 c2 = left.minus(n.times(rLeft));
        if (b.distance(c2) > 1e-12) {
            cs.add(new Segment2(b, c2));
        }
        Vec2 d2 = left.minus(u.times(rLeft));
        if (rLeft > 0) {
            cs.add(new Arc2(c2.minus(u.times(rLeft)), c2, d2, true));
        }
        return d2;
    }

    /**
     * Where a cutter wider than the slot above it runs along a straight slot (x from its middle):
     * down past an open end, where it cuts air (outsideX), to the far end (reachX: past it when
     * open, the cutter's radius short of a flat end, a radiused end's centre), and back.
     */
    record FromAnOpenEnd(double outsideX, double reachX, SlotEnd far) {

        /**
         * @throws UnsupportedOperationException with noOpenEnd when neither end is open
         */
        static FromAnOpenEnd of(double lengthMm, List<SlotEnd> ends, double radiusMm, String noOpenEnd) {
            SlotEnd start = ends.isEmpty() ? null : ends.get(0);
            SlotEnd end = ends.size() < 2 ? start : ends.get(1);
            boolean startOpen = start != null && start.type() == EndType.OPEN;
            boolean endOpen = end != null && end.type() == EndType.OPEN;
            if (!startOpen && !endOpen) {
                throw new UnsupportedOperationException(noOpenEnd);
            }
            double sign = startOpen ? -1 : 1; // the side the cutter enters from
            SlotEnd far = startOpen ? end : start;
            double half = lengthMm / 2;
            double outside = sign * (half + radiusMm + OPEN_END_CLEARANCE_MM);
            double reach;
            if (far != null && far.type() == EndType.OPEN) {
                reach = -outside;
            } else if (far != null && far.type() == EndType.RADIUSED) {
                reach = -sign * half;
            } else {
                reach = -sign * (half - radiusMm);
            }
            return new FromAnOpenEnd(outside, reach, far);
        }
    }

    /**
     * The tee's cross bar with a T-slot mill: down past an open end where the cutter cuts air,
     * along the middle at the floor to the other end (past it when open, the cutter's radius short
     * of a flat end, to a radiused end's centre), and back out the same way.
     */
    private static ToolpathSection crossBar(
            String label,
            double length,
            org.fresa.stepnc.Profile.Tee tee,
            List<SlotEnd> ends,
            Tool tool,
            Heights h,
            Tooling t,
            Tolerance tol) {
        checkTSlotMill(tee, tool, t, tol);
        FromAnOpenEnd run = FromAnOpenEnd.of(
                length, ends, t.radiusMm(), "a T_SLOT_MILL enters the cross bar from an open end; the slot has none");
        double outside = run.outsideX();
        double reach = run.reachX();
        double z = h.bottomZ();
        MoveBuilder b = new MoveBuilder(new Vec3(outside, 0, h.clearanceZ()));
        b.rapid(new Vec3(outside, 0, h.retractZ()));
        b.feed(new Vec3(outside, 0, z), t.plungeFeedMmPerMin());
        b.feed(new Vec3(reach, 0, z), t.feedMmPerMin());
        b.feed(new Vec3(outside, 0, z), t.feedMmPerMin());
        b.rapid(new Vec3(outside, 0, h.retractZ()));
        b.rapid(new Vec3(outside, 0, h.clearanceZ()));
        return t.section(label, new Vec3(outside, 0, h.clearanceZ()), b.moves());
    }

    /** A T-slot mill fits the cross bar: as wide as the bar, its edge as deep as the bar. */
    private static void checkTSlotMill(org.fresa.stepnc.Profile.Tee tee, Tool tool, Tooling t, Tolerance tol) {
        if (t.diameterMm() > tee.crossBarWidthMm() + tol.linear()) {
            throw new UnsupportedOperationException("the T-slot mill (" + mm(t.diameterMm()) + " mm) is wider than the"
                    + " cross bar (" + mm(tee.crossBarWidthMm()) + " mm)");
        }
        if (t.diameterMm() < tee.widthMm() - tol.linear()) {
            throw new UnsupportedOperationException("the T-slot mill (" + mm(t.diameterMm()) + " mm) is narrower than"
                    + " the stem (" + mm(tee.widthMm()) + " mm) it must pass");
        }
        // one pass along the middle: a narrower cutter would have to move aside in the stem, as far
        // as its neck lets it, and ISO 14649-111 gives a T-slot mill no neck
        if (t.diameterMm() < tee.crossBarWidthMm() - tol.linear()) {
            throw new UnsupportedOperationException("the T-slot mill (" + mm(t.diameterMm()) + " mm) is narrower than"
                    + " the cross bar (" + mm(tee.crossBarWidthMm()) + " mm): along the middle it leaves "
                    + mm((tee.crossBarWidthMm() - t.diameterMm()) / 2) + " mm of the bar on each side, and the file"
                    + " gives no neck to say how far it may move aside in the " + mm(tee.widthMm()) + " mm stem; a"
                    + " T-slot mill as wide as the bar mills it");
        }
        double edge = tool.cuttingEdgeLengthMm().orElse(Double.POSITIVE_INFINITY);
        if (edge < tee.crossBarDepthMm() - tol.linear()) {
            throw new UnsupportedOperationException("the T-slot mill's cutting edge (" + mm(edge) + " mm) is shorter"
                    + " than the cross bar (" + mm(tee.crossBarDepthMm()) + " mm)");
        }
    }

    /**
     * The tee's cross bar along an arc with a T-slot mill: down beyond an open end, on the
     * path's tangent there, where the cutter cuts air; straight to the end, along the middle arc
     * at the floor to the other end (out past it when open, to a radiused end's centre, or where
     * the cutter's disc touches a flat end), and back out the same way.
     */
    private static ToolpathSection crossBarAlongArc(
            String label, Course.Arc c, List<SlotEnd> ends, Heights h, Tooling t) {
        double r = t.radiusMm();
        SlotEnd start = ends.isEmpty() ? null : ends.get(0);
        SlotEnd end = ends.size() < 2 ? start : ends.get(1);
        boolean startOpen = start != null && start.type() == EndType.OPEN;
        boolean endOpen = end != null && end.type() == EndType.OPEN;
        if (!startOpen && !endOpen) {
            throw new UnsupportedOperationException(
                    "a T_SLOT_MILL enters the cross bar from an open end; the slot has" + " none");
        }
        double radius = c.radiusMm();
        if (r >= radius) {
            throw new UnsupportedOperationException("the T-slot mill (" + mm(t.diameterMm()) + " mm) is wider than"
                    + " its circular path (" + mm(2 * radius) + " mm)");
        }
        // the end entered from, and the angle turned from it to the far end (counter-clockwise +)
        double aIn = startOpen ? 0 : c.sweepRad();
        double turn = startOpen ? c.sweepRad() : -c.sweepRad();
        SlotEnd far = startOpen ? end : start;
        double sign = Math.signum(turn);
        Vec2 in = polar(radius, aIn);
        // the path's direction into the slot there: along the turn
        Vec2 into = new Vec2(-Math.sin(aIn) * sign, Math.cos(aIn) * sign);
        Vec2 outside = in.minus(into.times(r + OPEN_END_CLEARANCE_MM));
        double aFar;
        if (far != null && far.type() == EndType.OPEN) {
            aFar = aIn + turn;
        } else if (far != null && far.type() == EndType.RADIUSED) {
            aFar = aIn + turn;
        } else {
            aFar = aIn + turn - sign * Math.asin(r / radius);
        }
        if ((aFar - aIn) * sign <= 0) {
            throw new UnsupportedOperationException("the T-slot mill does not fit along the slot's arc");
        }
        double z = h.bottomZ();
        Vec3 o3 = Vec3.of(outside, h.clearanceZ());
        Vec3 centre = Vec3.of(Vec2.ZERO, z);
        MoveBuilder b = new MoveBuilder(o3);
        b.rapid(Vec3.of(outside, h.retractZ()));
        b.feed(Vec3.of(outside, z), t.plungeFeedMmPerMin());
        b.feed(Vec3.of(in, z), t.feedMmPerMin());
        b.arc(Vec3.of(polar(radius, aFar), z), centre, sign > 0, 0, t.feedMmPerMin());
        if (far != null && far.type() == EndType.OPEN) {
            Vec2 at = polar(radius, aFar);
            Vec2 on = new Vec2(-Math.sin(aFar) * sign, Math.cos(aFar) * sign);
            b.feed(Vec3.of(at.plus(on.times(r + OPEN_END_CLEARANCE_MM)), z), t.feedMmPerMin());
            b.feed(Vec3.of(at, z), t.feedMmPerMin());
        }
        b.arc(Vec3.of(in, z), centre, sign < 0, 0, t.feedMmPerMin());
        b.feed(Vec3.of(outside, z), t.feedMmPerMin());
        b.rapid(Vec3.of(outside, h.retractZ()));
        b.rapid(o3);
        return t.section(label, o3, b.moves());
    }

    private static String mm(double v) {
        return ToolpathPlanner.mm(v);
    }
}
