package org.fresa.toolpath;

import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.Tool;

/**
 * The undercut under a step's wall that overhangs its floor (profile_angle under 90 deg, a half
 * dovetail), cut with a DOVETAIL_MILL whose flank leans as the wall: one pass along the wall at
 * the floor, its flank on the wall's foot. In the step's frame (x along the open boundary from
 * its start, the material at +y, the wall's top edge at y 0) the foot lies depth / tan(angle)
 * under the material. The mill goes down where the step is open above it, clear of the wall's
 * top edge (past an open end, else beside the closed one, where an end mill milled the step
 * first: the program check's material model refuses a descent into material not cut), goes
 * under the wall, along it, and back out before it comes up.
 */
final class DovetailStep {

    private DovetailStep() {}

    static ToolpathSection underWall(
            String label, ToolpathPlanner.StepShape st, Tool tool, Heights h, Tooling t, Tolerance tol) {
        if (!st.overhangs()) {
            throw new UnsupportedOperationException("a DOVETAIL_MILL mills a step only under a wall that overhangs"
                    + " its floor; this wall stands at " + ToolpathPlanner.mm(st.wallAngleDeg()) + " deg to it");
        }
        double depth = h.topZ() - h.bottomZ();
        DovetailSlot.Shape shape = new DovetailSlot.Shape(Double.NaN, st.wallAngleDeg(), depth);
        DovetailSlot.checkFlank(shape, "step", "step's wall", tool, t, tol);
        double r = t.radiusMm();
        double clear = r + SlotMilling.OPEN_END_CLEARANCE_MM;
        double under = st.undercutMm(depth) - r;
        double out = -clear;
        double xs = st.openStart() ? -clear : r;
        double xe = st.openEnd() ? st.lengthMm() + clear : st.lengthMm() - r;
        if (!(xe > xs)) {
            throw new UnsupportedOperationException("the dovetail mill (" + ToolpathPlanner.mm(t.diameterMm())
                    + " mm) is longer than the step between its closed ends");
        }
        double z = h.bottomZ();
        MoveBuilder b = new MoveBuilder(new Vec3(xs, out, h.clearanceZ()));
        b.rapid(new Vec3(xs, out, h.retractZ()));
        b.feed(new Vec3(xs, out, z), t.plungeFeedMmPerMin());
        b.feed(new Vec3(xs, under, z), t.feedMmPerMin());
        b.feed(new Vec3(xe, under, z), t.feedMmPerMin());
        b.feed(new Vec3(xe, out, z), t.feedMmPerMin());
        b.rapid(new Vec3(xe, out, h.retractZ()));
        b.rapid(new Vec3(xe, out, h.clearanceZ()));
        return t.section(label, new Vec3(xs, out, h.clearanceZ()), b.moves());
    }
}
