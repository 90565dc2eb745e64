package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.RegionPocket;
import org.fresa.pocket.ToolTooLargeException;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.Operation;

/**
 * A closed pocket with bosses (ISO 14649-10 its_boss) left standing: the bosses are the islands
 * of the pocket module's region pocketing ({@link RegionPocket}), which clears the region between
 * the pocket's walls and the bosses contour-parallel, from the inside out, each loop entered by a
 * ramp along itself. Each boss must stand from the pocket's floor to at least its top with
 * upright walls; its boundary is placed by its own feature placement (in the workpiece frame)
 * and its profile's placement.
 */
final class BossPockets {

    private BossPockets() {}

    /** The features whose bosses (its_boss) the planner leaves standing. */
    static final java.util.Set<Feature.FeatureType> LEAVES_BOSSES = java.util.EnumSet.of(
            Feature.FeatureType.CLOSED_POCKET,
            Feature.FeatureType.OPEN_POCKET,
            Feature.FeatureType.STEP,
            Feature.FeatureType.PLANAR_FACE);

    /**
     * A step's region in its frame ({@link ToolpathPlanner.StepShape}: x along the open boundary,
     * the wall at y 0, the step at -y), carried past its open side and its open ends by a
     * cutter's diameter and the clearance, so that the loops at the tool's radius from it run in
     * the air there; a closed end keeps the tool within the path's length.
     */
    static Contour stepRegion(ToolpathPlanner.StepShape st, Tooling t) {
        double past = t.diameterMm() + OpenSideMilling.OUTSIDE_MM;
        double x0 = st.openStart() ? -past : 0;
        double x1 = st.lengthMm() + (st.openEnd() ? past : 0);
        double y0 = -(st.widthMm() + past);
        return Contour.polygon(List.of(
                new org.fresa.geom.Vec2(x0, y0),
                new org.fresa.geom.Vec2(x1, y0),
                new org.fresa.geom.Vec2(x1, 0),
                new org.fresa.geom.Vec2(x0, 0)));
    }

    /**
     * A planar face's removal boundary in its frame, each side carried a cutter's diameter and
     * the clearance outwards where the stock does not reach past it (the tool runs in the air
     * there); without a stock outline the tool stays within the boundary.
     */
    static Contour faceRegion(org.fresa.geom.Box2 box, java.util.Optional<Contour> stock, Tooling t, Tolerance tol) {
        double past = t.diameterMm() + OpenSideMilling.OUTSIDE_MM;
        double minX = box.minX();
        double minY = box.minY();
        double maxX = box.maxX();
        double maxY = box.maxY();
        if (stock.isPresent()) {
            org.fresa.geom.Box2 sb = stock.get().bounds();
            minX -= sb.minX() >= minX - tol.linear() ? past : 0;
            minY -= sb.minY() >= minY - tol.linear() ? past : 0;
            maxX += sb.maxX() <= maxX + tol.linear() ? past : 0;
            maxY += sb.maxY() <= maxY + tol.linear() ? past : 0;
        }
        return Contour.polygon(List.of(
                new org.fresa.geom.Vec2(minX, minY),
                new org.fresa.geom.Vec2(maxX, minY),
                new org.fresa.geom.Vec2(maxX, maxY),
                new org.fresa.geom.Vec2(minX, maxY)));
    }

    /**
     * @param pocketFrame the pocket's profile frame in the workpiece frame
     * @throws UnsupportedOperationException for a boss the planner cannot leave standing
     */
    static ToolpathSection section(
            String label,
            Profile pocket,
            Feature f,
            Transform3 pocketFrame,
            Operation op,
            Heights h,
            Tooling t,
            double stepoverMm,
            double axialMm,
            boolean climb,
            Tolerance tol,
            EntryRule entry,
            List<String> problems) {
        List<Contour> islands = islands(f, "pocket", pocketFrame, h, tol);
        return section(
                label,
                "pocket",
                pocket.contour(tol),
                islands,
                tallestTopZ(f, pocketFrame, h),
                op,
                h,
                t,
                stepoverMm,
                axialMm,
                climb,
                tol,
                entry,
                problems);
    }

    /**
     * The feature's bosses (its_boss) as islands in a frame whose z axis is the feature's: each
     * must stand upright along it, its top at least as high as the feature's top.
     *
     * @param what the feature's kind in the messages ("pocket", "step", ...)
     * @param frame the frame of the feature's region in the workpiece frame
     * @throws UnsupportedOperationException for a boss the planner cannot leave standing
     */
    static List<Contour> islands(Feature f, String what, Transform3 frame, Heights h, Tolerance tol) {
        List<Contour> islands = new ArrayList<>();
        Transform3 toPocket = frame.inverse();
        for (Feature boss : f.bosses()) {
            if (boss.type() != Feature.FeatureType.BOSS) {
                throw new IllegalArgumentException("its_boss lists a " + boss.entity() + ", not a BOSS");
            }
            org.fresa.stepnc.Profile bp = boss.profile()
                    .orElseThrow(() -> new IllegalArgumentException("boss '" + boss.id() + "' has no boundary"));
            Transform3 bossFrame = toPocket.times(boss.placement()).times(bp.placement());
            if (bossFrame.zAxis().minus(Vec3.UNIT_Z).norm() > 1e-9) {
                throw new UnsupportedOperationException(
                        "boss '" + boss.id() + "' does not stand along the " + what + "'s axis");
            }
            if (bossFrame.translationPart().z() < h.topZ() - tol.linear()) {
                throw new UnsupportedOperationException("boss '" + boss.id() + "' ends "
                        + ToolpathPlanner.mm(
                                h.topZ() - bossFrame.translationPart().z())
                        + " mm below the " + what + "'s top: only bosses as"
                        + " high as the " + what + " are left standing");
            }
            Profile outline;
            try {
                outline = ToolpathPlanner.profile(bp, 0, tol);
            } catch (UnsupportedOperationException e) {
                throw new UnsupportedOperationException("bosses bounded by " + bp.entity() + " are not supported yet");
            }
            List<Curve2> placed = new ArrayList<>();
            for (Curve2 c : outline.contour(tol).curves()) {
                placed.add(inPlane(c, bossFrame));
            }
            islands.add(Contour.of(placed, Tolerance.DRAWING));
        }
        return islands;
    }

    /**
     * The region inside outer less the islands cleared by the region engine, cut to size.
     *
     * @param what the feature's kind in the messages ("pocket", "step", ...)
     * @param outer the region's boundary in the feature's frame (carried into the air beyond an
     *     open side by the caller)
     * @throws UnsupportedOperationException when an island is not inside the region clear of its
     *     boundary, or the tool fits nowhere
     */
    static ToolpathSection section(
            String label,
            String what,
            Contour outer,
            List<Contour> islands,
            double bossesTopZ,
            Operation op,
            Heights h,
            Tooling t,
            double stepoverMm,
            double axialMm,
            boolean climb,
            Tolerance tol,
            EntryRule entry,
            List<String> problems) {
        double depth = h.topZ() - h.bottomZ();
        if (!(depth > 0)) {
            throw new IllegalArgumentException("the " + what + " has no depth");
        }
        if (op.allowanceSideMm().orElse(0) > 0 || op.allowanceBottomMm().orElse(0) > 0) {
            problems.add("workingstep '" + label + "': the " + what + " with bosses is cut to size: its allowances are"
                    + " not left");
        }
        PocketTechnology tech = t.regionTechnology(stepoverMm, h.topZ(), h.bottomZ(), axialMm > 0 ? axialMm : depth);
        Toolpath path;
        try {
            path = RegionPocket.plan(outer, islands, tech, climb, entry).toolpath();
        } catch (ToolTooLargeException e) {
            throw new UnsupportedOperationException(e.getMessage());
        }
        ToolpathSection s = path.sections().get(0);
        Vec3 start = s.start();
        List<org.fresa.model.Move> moves = s.moves();
        if (bossesTopZ > h.topZ() + tol.linear()) {
            // the engine goes from loop to loop in straight lines over the islands at its
            // clearance above the top: raised to the same clearance over the tallest boss
            double safe = h.topZ() + ENGINE_CLEARANCE_MM;
            double lift = bossesTopZ - h.topZ();
            moves = new ArrayList<>();
            for (org.fresa.model.Move m : s.moves()) {
                moves.add(
                        m instanceof org.fresa.model.Move.Rapid r
                                        && Math.abs(r.end().z() - safe) < 1e-9
                                ? new org.fresa.model.Move.Rapid(r.end().plus(new Vec3(0, 0, lift)))
                                : m);
            }
            if (Math.abs(start.z() - safe) < 1e-9) {
                start = start.plus(new Vec3(0, 0, lift));
            }
            problems.add("workingstep '" + label + "': a boss stands " + ToolpathPlanner.mm(lift) + " mm above the "
                    + what + "'s top: the tool goes from loop to loop " + ToolpathPlanner.mm(ENGINE_CLEARANCE_MM)
                    + " mm over it");
        }
        return new ToolpathSection(label, s.toolAxis(), t.diameterMm(), t.toolNumber(), t.spindleRpm(), start, moves);
    }

    /** How high over the top of its region the region engine takes the tool from loop to loop (mm). */
    static final double ENGINE_CLEARANCE_MM = 5;

    /**
     * The height of the feature's tallest boss's top in the frame, or the feature's top when no
     * boss stands above it.
     */
    static double tallestTopZ(Feature f, Transform3 frame, Heights h) {
        double top = h.topZ();
        Transform3 toFeature = frame.inverse();
        for (Feature boss : f.bosses()) {
            Transform3 at = toFeature.times(boss.placement());
            if (boss.profile().isPresent()) {
                at = at.times(boss.profile().get().placement());
            }
            top = Math.max(top, at.translationPart().z());
        }
        return top;
    }

    /**
     * Refuses a boss that is not inside the region clear of its boundary: the region engine
     * takes islands strictly inside it (a boss against a step's wall would need the wall and the
     * boss as one boundary).
     */
    static void inside(Feature f, String what, Contour outer, List<Contour> islands, Tolerance tol) {
        for (int i = 0; i < islands.size(); i++) {
            Contour island = islands.get(i);
            boolean inside = island.curves().stream()
                    .allMatch(c -> outer.windingNumber(c.start()) != 0 && outer.distanceTo(c.start()) > tol.linear());
            for (Curve2 a : island.curves()) {
                for (Curve2 b : outer.curves()) {
                    inside &= org.fresa.geom.Intersections.of(a, b, tol).isEmpty();
                }
            }
            if (!inside) {
                throw new UnsupportedOperationException(
                        "boss '" + f.bosses().get(i).id() + "' is not inside the " + what
                                + " clear of its boundary: only free-standing bosses are left standing");
            }
        }
    }

    /** A line or arc of a frame whose z axis is the pocket's, in the pocket's xy plane. */
    private static Curve2 inPlane(Curve2 c, Transform3 frame) {
        if (c instanceof org.fresa.geom.Arc2 a) {
            return new org.fresa.geom.Arc2(xy(a.center(), frame), xy(a.start(), frame), xy(a.end(), frame), a.ccw());
        }
        return new org.fresa.geom.Segment2(xy(c.start(), frame), xy(c.end(), frame));
    }

    private static org.fresa.geom.Vec2 xy(org.fresa.geom.Vec2 p, Transform3 frame) {
        Vec3 q = frame.applyToPoint(new Vec3(p.x(), p.y(), 0));
        return new org.fresa.geom.Vec2(q.x(), q.y());
    }
}
