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
        List<Contour> islands = new ArrayList<>();
        Transform3 toPocket = pocketFrame.inverse();
        for (Feature boss : f.bosses()) {
            if (boss.type() != Feature.FeatureType.BOSS) {
                throw new IllegalArgumentException("its_boss lists a " + boss.entity() + ", not a BOSS");
            }
            org.fresa.stepnc.Profile bp = boss.profile()
                    .orElseThrow(() -> new IllegalArgumentException("boss '" + boss.id() + "' has no boundary"));
            Transform3 bossFrame = toPocket.times(boss.placement()).times(bp.placement());
            if (bossFrame.zAxis().minus(Vec3.UNIT_Z).norm() > 1e-9) {
                throw new UnsupportedOperationException(
                        "boss '" + boss.id() + "' does not stand along the pocket's axis");
            }
            if (bossFrame.translationPart().z() < h.topZ() - tol.linear()) {
                throw new UnsupportedOperationException("boss '" + boss.id() + "' ends "
                        + ToolpathPlanner.mm(
                                h.topZ() - bossFrame.translationPart().z())
                        + " mm below the pocket's top: only bosses as"
                        + " high as the pocket are left standing");
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
        double depth = h.topZ() - h.bottomZ();
        if (!(depth > 0)) {
            throw new IllegalArgumentException("the pocket has no depth");
        }
        if (op.allowanceSideMm().orElse(0) > 0 || op.allowanceBottomMm().orElse(0) > 0) {
            problems.add("workingstep '" + label + "': the pocket with bosses is cut to size: its allowances are not"
                    + " left");
        }
        double fraction = Math.min(1, Math.max(stepoverMm / t.diameterMm(), 1e-3));
        PocketTechnology tech = new PocketTechnology(
                t.diameterMm(),
                fraction,
                0,
                h.topZ(),
                h.bottomZ(),
                axialMm > 0 ? axialMm : depth,
                Math.max(t.spindleRpm(), 1),
                t.feedMmPerMin(),
                t.feedMmPerMin());
        Toolpath path;
        try {
            path = RegionPocket.plan(pocket.contour(tol), islands, tech, climb, entry)
                    .toolpath();
        } catch (ToolTooLargeException e) {
            throw new UnsupportedOperationException(e.getMessage());
        }
        ToolpathSection s = path.sections().get(0);
        return new ToolpathSection(
                label, s.toolAxis(), t.diameterMm(), t.toolNumber(), t.spindleRpm(), s.start(), s.moves());
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
