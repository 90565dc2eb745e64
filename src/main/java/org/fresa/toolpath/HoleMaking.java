package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.Entries;
import org.fresa.pocket.EntryRule;

/**
 * Round holes in the feature frame (axis +Z through {@code center}), written as explicit moves
 * (the posts have no canned cycles, so every control reads the same motions).
 *
 * <ul>
 * <li>{@link #drill}: drilling, center drilling, reaming, boring: feed to the bottom with the
 * reduced feeds of the drilling strategy over the start and end depths ({@link DrillCycle}), out
 * at rapid (drills) or at feed (reamers, boring bars, which must not mark the wall); multistep
 * drilling: after each step the drill lifts by the retract distance (or to the retract height to
 * clear chips) and returns at rapid to 1 mm above the last depth. Dwells at the bottom of each
 * step and of the hole, and a spindle stopped at the bottom for the way out, are moves of
 * their own ({@link org.fresa.model.Move.Dwell}, {@link org.fresa.model.Move.SpindleStop},
 * {@link org.fresa.model.Move.SpindleStart}).
 * <li>{@link #mill}: a hole wider than the milling cutter: helical interpolation at radius
 * (hole - tool) / 2 down to the bottom with at most the axial depth per turn, a full circle at
 * the bottom, then to the centre and out. That clears the hole when it is at most twice the tool
 * diameter; wider holes are circular pockets ({@link PocketMilling}).
 * </ul>
 */
public final class HoleMaking {

    private HoleMaking() {}

    /**
     * Drills with one descent or pecks of {@code peckMm}, out at rapid or, if {@code feedOut}, at
     * the plunge feed; see {@link #drill(String, Vec2, Heights, Tooling, DrillCycle)}.
     *
     * @param peckMm depth of each peck, 0 or less for one feed to the bottom
     * @param feedOut leave at the cutting feed (reaming, boring)
     */
    public static ToolpathSection drill(
            String label, Vec2 center, Heights h, Tooling tool, double peckMm, boolean feedOut) {
        DrillCycle c = peckMm > 0 ? DrillCycle.pecking(peckMm) : DrillCycle.PLAIN;
        return drill(label, center, h, tool, feedOut ? c.withRetractFeed(1) : c);
    }

    /**
     * Drills down the axis (+Z up) from the retract height to {@code h.bottomZ()} (which already
     * holds any tip allowance) with the feed zones of the cycle. With steps, each step is cut, the
     * tool lifts by the retract distance (or to the retract height) and comes back at rapid to
     * 1 mm above the last depth (or the lifted height if nearer). The tool leaves at the retract
     * feed, or at rapid when the cycle has none.
     *
     * <p>The tool waits {@code dwellStepS} at the bottom of each step and {@code dwellBottomS} at
     * the bottom of the hole: the last step is the bottom, so it waits the bottom's time only.
     * With {@code spindleStopAtBottom} (and a spindle speed to start again at) the spindle stops
     * after the bottom dwell, the tool leaves to the retract height with it stopped, and it starts
     * again there, clockwise at the section's speed, before the rapid to the clearance height.
     */
    public static ToolpathSection drill(String label, Vec2 center, Heights h, Tooling tool, DrillCycle c) {
        MoveBuilder b = new MoveBuilder(Vec3.of(center, h.clearanceZ()));
        b.rapid(Vec3.of(center, h.retractZ()));
        double f = tool.plungeFeedMmPerMin();
        // without a speed the section never started the spindle, so there is nothing to reduce
        double rpm = tool.spindleRpm();
        double startSpeed = rpm > 0 ? c.startSpeedFactor() : 1;
        double endSpeed = rpm > 0 ? c.endSpeedFactor() : 1;
        DrillCycle zc = c.withSpeedFactors(startSpeed, endSpeed);
        // ISO 14649-11 drilling_type_strategy: the start zone ends when the full diameter is depth_of_start
        // deep; a zone without a reduction is no zone (NaN: no split, no reduction)
        double startEnd = c.startFeedFactor() == 1 && startSpeed == 1
                ? Double.NaN
                : Math.max(h.bottomZ(), h.topZ() - c.startDepth() - c.tipLength());
        double endStart = c.endFeedFactor() == 1 && endSpeed == 1
                ? Double.NaN
                : Math.min(h.retractZ(), h.bottomZ() + c.endDepth());
        if (c.pecks() && h.topZ() - h.bottomZ() > c.firstPeck()) {
            double depth = h.topZ() - c.firstPeck();
            while (depth > h.bottomZ() + 1e-9) {
                descend(b, center, depth, f, rpm, zc, startEnd, endStart);
                dwell(b, c.dwellStepS());
                double up =
                        c.retractDistance() > 0 ? Math.min(h.retractZ(), depth + c.retractDistance()) : h.retractZ();
                leave(b, center, up, f, c);
                b.rapid(Vec3.of(center, Math.min(up, depth + 1)));
                depth -= c.peck();
            }
        }
        descend(b, center, h.bottomZ(), f, rpm, zc, startEnd, endStart);
        dwell(b, c.dwellBottomS());
        // without a speed the section never started the spindle, so there is no speed to restart at
        boolean stop = c.spindleStopAtBottom() && tool.spindleRpm() > 0;
        if (stop) {
            b.spindleStop();
        }
        leave(b, center, h.retractZ(), f, c);
        if (stop) {
            b.spindleStart(tool.spindleRpm(), true);
        }
        b.rapid(Vec3.of(center, h.clearanceZ()));
        return tool.section(label, Vec3.of(center, h.clearanceZ()), b.moves());
    }

    /**
     * Feeds down to z, split where the feed or the spindle speed of the cycle changes; a speed
     * change is a spindle start at the new speed where the zone begins.
     */
    private static void descend(
            MoveBuilder b,
            Vec2 center,
            double z,
            double f,
            double rpm,
            DrillCycle c,
            double startEnd,
            double endStart) {
        double from = b.at().z();
        double[] ends = {
            Double.isNaN(endStart) || startEnd > endStart ? startEnd : endStart,
            Double.isNaN(endStart) || startEnd > endStart ? endStart : startEnd,
            z
        };
        // pieces of constant (feed, speed) factors, top down, neighbours with equal factors merged
        List<double[]> pieces = new ArrayList<>();
        double lastEnd = from;
        for (double end : ends) {
            if (!(end < lastEnd && end >= z)) {
                continue;
            }
            double mid = (lastEnd + end) / 2;
            double kf = feedFactor(c, mid, startEnd, endStart);
            double ks = speedFactor(c, mid, startEnd, endStart);
            double[] last = pieces.isEmpty() ? null : pieces.get(pieces.size() - 1);
            if (last != null && last[1] == kf && last[2] == ks) {
                last[0] = end;
            } else {
                pieces.add(new double[] {end, kf, ks});
            }
            lastEnd = end;
        }
        if (pieces.isEmpty()) {
            pieces.add(new double[] {z, 1, 1});
        }
        for (double[] p : pieces) {
            if (rpm > 0 && p[0] < b.at().z()) {
                double speed = rpm * p[2];
                if (speed != spindleSpeed(b, rpm)) {
                    b.spindleStart(speed, true);
                }
            }
            b.feed(Vec3.of(center, p[0]), f * p[1]);
        }
    }

    /** The speed the moves so far leave the spindle at: the last spindle start's, else the section's. */
    private static double spindleSpeed(MoveBuilder b, double sectionRpm) {
        List<Move> ms = b.moves();
        for (int i = ms.size() - 1; i >= 0; i--) {
            if (ms.get(i) instanceof Move.SpindleStart on) {
                return on.rpm();
            }
        }
        return sectionRpm;
    }

    private static double feedFactor(DrillCycle c, double z, double startEnd, double endStart) {
        if (z < endStart) {
            return c.endFeedFactor();
        }
        return z > startEnd ? c.startFeedFactor() : 1;
    }

    private static double speedFactor(DrillCycle c, double z, double startEnd, double endStart) {
        if (z < endStart) {
            return c.endSpeedFactor();
        }
        return z > startEnd ? c.startSpeedFactor() : 1;
    }

    private static void dwell(MoveBuilder b, double seconds) {
        if (seconds > 0) {
            b.dwell(seconds);
        }
    }

    private static void leave(MoveBuilder b, Vec2 center, double z, double f, DrillCycle c) {
        if (c.retractFeedFactor() > 0) {
            b.feed(Vec3.of(center, z), f * c.retractFeedFactor());
        } else {
            b.rapid(Vec3.of(center, z));
        }
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
     * @param clockwise turn clockwise seen from +Z (conventional milling of the wall with an M3 spindle)
     * @throws IllegalArgumentException when the tool is wider than the hole
     */
    public static ToolpathSection mill(
            String label,
            Vec2 center,
            double holeDiameterMm,
            Heights h,
            Tooling tool,
            double axialDepthMm,
            boolean clockwise,
            Tolerance tol) {
        return mill(label, center, holeDiameterMm, h, tool, axialDepthMm, clockwise, EntryRule.DEFAULT_ANGLE_DEG, tol);
    }

    /**
     * {@link #mill(String, Vec2, double, Heights, Tooling, double, boolean, Tolerance)} with the
     * helix no steeper than the entry angle asked for.
     *
     * @param entryAngleDeg steepest descent of the helix (deg, in (0, 90])
     */
    public static ToolpathSection mill(
            String label,
            Vec2 center,
            double holeDiameterMm,
            Heights h,
            Tooling tool,
            double axialDepthMm,
            boolean clockwise,
            double entryAngleDeg,
            Tolerance tol) {
        if (!(entryAngleDeg > 0 && entryAngleDeg <= 90)) {
            throw new IllegalArgumentException("entry angle must be in (0, 90] deg: " + entryAngleDeg);
        }
        double rp = (holeDiameterMm - tool.diameterMm()) / 2;
        if (rp < -tol.linear()) {
            throw new IllegalArgumentException(
                    "the tool (D" + tool.diameterMm() + ") is wider than the hole (D" + holeDiameterMm + ")");
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
        // a milling cutter is not taken to cut at its centre: the helix no steeper than the entry angle
        double byAngle = Math.ceil(dz / (2 * Math.PI * rp * Math.tan(Math.toRadians(entryAngleDeg))) - 1e-9);
        if (!(byAngle <= Entries.MAX_STEPS)) {
            throw new IllegalArgumentException("the hole (D" + holeDiameterMm + ") leaves the tool (D"
                    + tool.diameterMm() + ") no helix within " + entryAngleDeg + " deg");
        }
        turns = Math.max(turns, (int) byAngle);
        b.arc(Vec3.of(p0, h.bottomZ()), Vec3.of(center, start), !clockwise, turns - 1, tool.feedMmPerMin());
        b.arc(Vec3.of(p0, h.bottomZ()), Vec3.of(center, h.bottomZ()), !clockwise, 0, tool.feedMmPerMin());
        b.feed(Vec3.of(center, h.bottomZ()), tool.feedMmPerMin());
        b.rapid(Vec3.of(center, h.retractZ()));
        b.rapid(Vec3.of(center, h.clearanceZ()));
        return tool.section(label, Vec3.of(p0, h.clearanceZ()), List.copyOf(b.moves()));
    }
}
