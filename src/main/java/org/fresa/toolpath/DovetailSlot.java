package org.fresa.toolpath;

import java.util.List;
import java.util.OptionalDouble;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.Feature.SlotEnd;
import org.fresa.stepnc.Feature.SlotEnd.EndType;
import org.fresa.stepnc.Profile;
import org.fresa.stepnc.Tool;

/**
 * A dovetail slot: ISO 14649-10 has no dovetail profile, and its square_u_profile (taken from
 * ISO 10303-214, 4.2.497) is one when both sides meet the base (its width) at the same angle
 * under 90 degrees, leaning in towards the top. In the slot frame (x along a straight path from
 * its middle, y across, the top at z 0) the sides run from (+-width / 2, -depth) to
 * (+-neck / 2, 0), the neck being width - 2 depth / tan(angle).
 *
 * <p>A straight tool (an end mill) mills the neck: a square-U as wide as the top, to the floor.
 * A DOVETAIL_MILL (widest at its tip, its flank leaning in by tool_circumference_angle from its
 * axis) cuts the undercut sides: one pass along each side at the floor, its flank on the side,
 * entering and leaving past an open end, where it cuts air, as a T-slot mill does. Its flank
 * must lean as the side leans (within the tolerance over the depth), else it leaves the side
 * stepped or cuts into it; and it must reach the top: its radius there is what is left of it
 * above the neck's wall, so one pass a side clears the undercut whatever the tool's diameter.
 */
final class DovetailSlot {

    private DovetailSlot() {}

    /** Whether the square U's sides lean in towards its top at one angle: a dovetail. */
    static boolean is(Profile.U u) {
        OptionalDouble a = u.firstAngleDeg();
        OptionalDouble b = u.secondAngleDeg();
        // pi / 2 is a right angle a writer put in radians: refused as such, never taken for a dovetail
        return a.isPresent()
                && b.isPresent()
                && Math.abs(a.getAsDouble() - Math.PI / 2) > 1e-4
                && a.getAsDouble() > 0
                && a.getAsDouble() < 90 - SlotMilling.SQUARE_TOLERANCE_DEG
                && Math.abs(a.getAsDouble() - b.getAsDouble()) <= SlotMilling.SQUARE_TOLERANCE_DEG;
    }

    /** The dovetail's shape: its width at the floor, its sides' angle to the base, its depth (mm, deg). */
    record Shape(double widthMm, double angleDeg, double depthMm) {

        /** How far each side leans in from the floor to the top (mm). */
        double undercutMm() {
            return depthMm / Math.tan(Math.toRadians(angleDeg));
        }

        /** The width at the top, the neck a straight tool mills (mm). */
        double neckMm() {
            return widthMm - 2 * undercutMm();
        }
    }

    /**
     * The dovetail of a square U, refused where its neck closes or its corners are blended
     * (a dovetail mill with a matching corner radius is not modelled).
     */
    static Shape shape(Profile.U u, double depthMm) {
        double angle = u.firstAngleDeg().orElseThrow();
        if (u.firstRadiusMm().orElse(0) > 0 || u.secondRadiusMm().orElse(0) > 0) {
            throw new UnsupportedOperationException("a dovetail (square U with sides at " + mm(angle)
                    + " deg to its base) with blended bottom corners is not machined: a dovetail mill's corner"
                    + " radius is not modelled");
        }
        Shape s = new Shape(u.widthMm(), angle, depthMm);
        if (!(s.neckMm() > 0)) {
            throw new IllegalArgumentException("the dovetail's sides, at " + mm(angle) + " deg to its "
                    + mm(u.widthMm()) + " mm base, meet below its top " + mm(depthMm) + " mm up: it has no neck");
        }
        return s;
    }

    /**
     * What a straight tool mills of a dovetail: its neck, as a square U as wide as the top to the
     * floor; the undercut is reported as left for a dovetail mill.
     */
    static double neckHalfWidth(Shape s, String body, String label, double toolDiameterMm, List<String> problems) {
        problems.add("workingstep '" + label + "': the " + body + " mills the dovetail's " + mm(s.neckMm())
                + " mm neck; its sides, undercut by " + mm(s.undercutMm()) + " mm, need a DOVETAIL_MILL");
        if (toolDiameterMm > s.neckMm()) {
            throw new UnsupportedOperationException("the tool (" + mm(toolDiameterMm) + " mm) is wider than the"
                    + " dovetail's neck (" + mm(s.neckMm()) + " mm)");
        }
        return s.neckMm() / 2;
    }

    /**
     * The dovetail mill's two passes along a straight slot: down past an open end where it cuts
     * air, along one side at the floor to the other end (past it when open, its radius short of
     * a flat end), across, back along the other side, and up outside.
     */
    static ToolpathSection sides(
            String label,
            double lengthMm,
            Shape s,
            List<SlotEnd> ends,
            Tool tool,
            Heights h,
            Tooling t,
            Tolerance tol) {
        double r = t.radiusMm();
        check(s, tool, t, tol);
        SlotMilling.FromAnOpenEnd run = SlotMilling.FromAnOpenEnd.of(
                lengthMm,
                ends,
                r,
                "a DOVETAIL_MILL enters the dovetail from an open end, being wider at its tip than the neck above"
                        + " it; the slot has none");
        SlotEnd far = run.far();
        boolean farFlat = far == null || far.type() == EndType.FLAT && noCorners(far);
        if (!(far != null && far.type() == EndType.OPEN) && !farFlat) {
            throw new UnsupportedOperationException("a dovetail's far end is milled open or flat without corner"
                    + " radii; this one is " + far.entity());
        }
        double outside = run.outsideX();
        double reach = run.reachX();
        double side = s.widthMm() / 2 - r;
        double z = h.bottomZ();
        MoveBuilder b = new MoveBuilder(new Vec3(outside, side, h.clearanceZ()));
        b.rapid(new Vec3(outside, side, h.retractZ()));
        b.feed(new Vec3(outside, side, z), t.plungeFeedMmPerMin());
        b.feed(new Vec3(reach, side, z), t.feedMmPerMin());
        b.feed(new Vec3(reach, -side, z), t.feedMmPerMin());
        b.feed(new Vec3(outside, -side, z), t.feedMmPerMin());
        b.rapid(new Vec3(outside, -side, h.retractZ()));
        b.rapid(new Vec3(outside, -side, h.clearanceZ()));
        return t.section(label, new Vec3(outside, side, h.clearanceZ()), b.moves());
    }

    private static boolean noCorners(SlotEnd e) {
        return e.firstRadiusMm().orElse(0) <= 0 && e.secondRadiusMm().orElse(0) <= 0;
    }

    /**
     * A dovetail mill fits: no wider at its tip than the base, its flank leaning as the sides
     * lean, and its cutting edge, tapering in, still cutting at the top.
     */
    static void check(Shape s, Tool tool, Tooling t, Tolerance tol) {
        if (t.diameterMm() > s.widthMm() + tol.linear()) {
            throw new UnsupportedOperationException("the dovetail mill (" + mm(t.diameterMm()) + " mm) is wider than"
                    + " the dovetail's base (" + mm(s.widthMm()) + " mm)");
        }
        checkFlank(s, "dovetail", "dovetail's sides", tool, t, tol);
    }

    /**
     * A dovetail mill's flank leans as a wall at this angle to its floor leans, and its cutting
     * edge, tapering in, still cuts at the top: the wall is cut as drawn in one pass.
     *
     * @param feature the feature in the messages ("dovetail", "step")
     * @param wall what leans in the messages ("dovetail's sides", "step's wall")
     */
    static void checkFlank(Shape s, String feature, String wall, Tool tool, Tooling t, Tolerance tol) {
        double r = t.radiusMm();
        double side = 90 - s.angleDeg();
        double flank = Math.abs(tool.circumferenceAngle()
                .orElseThrow(() -> new UnsupportedOperationException("the DOVETAIL_MILL gives no"
                        + " tool_circumference_angle: its flank must lean as the " + wall + ", " + mm(side)
                        + " deg from the axis")));
        double off = s.depthMm() * Math.abs(Math.tan(Math.toRadians(flank)) - Math.tan(Math.toRadians(side)));
        if (off > tol.linear()) {
            throw new UnsupportedOperationException("the dovetail mill's flank leans " + mm(flank) + " deg from its"
                    + " axis, the " + wall + " " + mm(side) + " deg (" + mm(s.angleDeg()) + " deg to the base):"
                    + " over the " + mm(s.depthMm()) + " mm depth it would leave or cut " + mm(off) + " mm of it");
        }
        double atTop = r - s.undercutMm();
        if (!(atTop > tol.linear())) {
            throw new UnsupportedOperationException("the dovetail mill (" + mm(t.diameterMm()) + " mm) tapers to"
                    + " nothing below the " + feature + "'s top: it would leave the upper part of the " + wall);
        }
        double edge = tool.cuttingEdgeLengthMm().orElse(Double.POSITIVE_INFINITY);
        if (edge < s.depthMm() - tol.linear()) {
            throw new UnsupportedOperationException("the dovetail mill's cutting edge (" + mm(edge) + " mm) is"
                    + " shorter than the " + feature + " (" + mm(s.depthMm()) + " mm deep)");
        }
    }

    private static String mm(double v) {
        return ToolpathPlanner.mm(v);
    }
}
