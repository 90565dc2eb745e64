package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;

/**
 * Round holes in the feature frame (axis +Z through {@code center}), written as explicit moves
 * (the posts have no canned cycles, so every control reads the same motions).
 *
 * <ul>
 * <li>{@link #drill}: drilling, center drilling, reaming, boring: feed to the bottom, out at
 * rapid (drills) or at feed (reamers, boring bars, which must not mark the wall); with a peck
 * depth, multistep drilling: after each peck the drill goes back to the retract height to clear
 * chips and returns at rapid to 1 mm above the last depth.
 * <li>{@link #mill}: a hole wider than the milling cutter: helical interpolation at radius
 * (hole - tool) / 2 down to the bottom with at most the axial depth per turn, a full circle at
 * the bottom, then to the centre and out. That clears the hole when it is at most twice the tool
 * diameter; wider holes are circular pockets ({@link PocketMilling}).
 * </ul>
 */
public final class HoleMaking {

    private HoleMaking() {
    }

    /**
     * @param peckMm depth of each peck, 0 or less for one feed to the bottom
     * @param feedOut leave at the cutting feed (reaming, boring)
     */
    public static ToolpathSection drill(String label, Vec2 center, Heights h, Tooling tool, double peckMm,
            boolean feedOut) {
        MoveBuilder b = new MoveBuilder(Vec3.of(center, h.clearanceZ()));
        b.rapid(Vec3.of(center, h.retractZ()));
        double f = tool.plungeFeedMmPerMin();
        if (peckMm > 0 && h.topZ() - h.bottomZ() > peckMm) {
            double depth = h.topZ();
            while (depth - peckMm > h.bottomZ() + 1e-9) {
                if (depth < h.topZ()) {
                    b.rapid(Vec3.of(center, Math.min(h.retractZ(), depth + 1)));
                }
                depth -= peckMm;
                b.feed(Vec3.of(center, depth), f);
                b.rapid(Vec3.of(center, h.retractZ()));
            }
            b.rapid(Vec3.of(center, Math.min(h.retractZ(), depth + 1)));
        }
        b.feed(Vec3.of(center, h.bottomZ()), f);
        if (feedOut) {
            b.feed(Vec3.of(center, h.retractZ()), f);
        } else {
            b.rapid(Vec3.of(center, h.retractZ()));
        }
        b.rapid(Vec3.of(center, h.clearanceZ()));
        return new ToolpathSection(label, Vec3.UNIT_Z, tool.diameterMm(), tool.toolNumber(), tool.spindleRpm(),
                Vec3.of(center, h.clearanceZ()), b.moves());
    }

    /** Whether {@link #mill} clears a hole of this diameter with this tool (hole <= 2 D). */
    public static boolean helicalClears(double holeDiameterMm, double toolDiameterMm) {
        return holeDiameterMm <= 2 * toolDiameterMm;
    }

    /**
     * Helical milling of a hole of the given diameter; a hole no wider than the tool (within the
     * tolerance) is plunged in steps of the axial depth instead.
     *
     * @param axialDepthMm largest descent per turn; 0 or less for one turn
     * @param clockwise turn clockwise seen from +Z (climb milling with an M3 spindle)
     * @throws IllegalArgumentException when the tool is wider than the hole
     */
    public static ToolpathSection mill(String label, Vec2 center, double holeDiameterMm, Heights h, Tooling tool,
            double axialDepthMm, boolean clockwise, Tolerance tol) {
        double rp = (holeDiameterMm - tool.diameterMm()) / 2;
        if (rp < -tol.linear()) {
            throw new IllegalArgumentException("the tool (D" + tool.diameterMm() + ") is wider than the hole (D"
                    + holeDiameterMm + ")");
        }
        if (rp <= tol.linear()) {
            return drill(label, center, h, tool, axialDepthMm, false);
        }
        Vec2 p0 = center.plus(new Vec2(rp, 0));
        MoveBuilder b = new MoveBuilder(Vec3.of(p0, h.clearanceZ()));
        b.rapid(Vec3.of(p0, h.retractZ()));
        double start = Math.min(h.retractZ(), h.topZ() + PocketMilling.LIFT_MM);
        b.rapid(Vec3.of(p0, start));
        double dz = start - h.bottomZ();
        int turns = axialDepthMm > 0 ? Math.max(1, (int) Math.ceil(dz / axialDepthMm - 1e-9)) : 1;
        b.arc(Vec3.of(p0, h.bottomZ()), Vec3.of(center, start), !clockwise, turns - 1, tool.feedMmPerMin());
        b.arc(Vec3.of(p0, h.bottomZ()), Vec3.of(center, h.bottomZ()), !clockwise, 0, tool.feedMmPerMin());
        b.feed(Vec3.of(center, h.bottomZ()), tool.feedMmPerMin());
        b.rapid(Vec3.of(center, h.retractZ()));
        b.rapid(Vec3.of(center, h.clearanceZ()));
        return new ToolpathSection(label, Vec3.UNIT_Z, tool.diameterMm(), tool.toolNumber(), tool.spindleRpm(),
                Vec3.of(p0, h.clearanceZ()), List.copyOf(b.moves()));
    }
}
