package org.fresa.model;

/**
 * One move of the tool tip, from the end of the previous move to {@link #end()}, in the frame of
 * the section that holds it (mm).
 *
 * <p>{@link Dwell}, {@link SpindleStop} and {@link SpindleStart} do not move the tool: their end
 * is where the tool already is, so that every consumer may keep its "at = m.end()" bookkeeping.
 * They are moves rather than a side channel because their place in the sequence is what matters
 * (a dwell at the bottom of a hole, the spindle stopped before a boring bar leaves it).
 */
public sealed interface Move
        permits Move.Rapid, Move.Linear, Move.Circular, Move.Dwell, Move.SpindleStop, Move.SpindleStart {

    org.fresa.geom.Vec3 end();

    /** Positioning at rapid traverse (G00). */
    record Rapid(org.fresa.geom.Vec3 end) implements Move {
        public Rapid {
            java.util.Objects.requireNonNull(end, "end");
        }
    }

    /**
     * A straight cutting move (G01).
     *
     * @param end end point (mm)
     * @param feedMmPerMin feed rate, > 0
     */
    record Linear(org.fresa.geom.Vec3 end, double feedMmPerMin) implements Move {
        public Linear {
            java.util.Objects.requireNonNull(end, "end");
            if (!(feedMmPerMin > 0) || !Double.isFinite(feedMmPerMin)) {
                throw new IllegalArgumentException("feed must be > 0: " + feedMmPerMin);
            }
        }
    }

    /**
     * A circular or helical cutting move (G02/G03) about an axis through {@code center} along
     * {@code normal}: counter-clockwise when seen from the tip of the normal if {@code ccw}. The
     * end may differ from the start along the normal (a helix). A full turn has end = start.
     *
     * @param end end point (mm)
     * @param center a point on the arc's axis, in the plane of the start point (mm)
     * @param normal unit axis of the arc: +Z for arcs in the XY plane (G17), +Y for XZ (G18),
     *     +X for YZ (G19), or another direction for arcs in a general plane
     * @param ccw sense about the normal (G03 when normal is +Z)
     * @param turns extra full turns before the end (0 for an ordinary arc)
     * @param feedMmPerMin feed rate, > 0
     */
    record Circular(
            org.fresa.geom.Vec3 end,
            org.fresa.geom.Vec3 center,
            org.fresa.geom.Vec3 normal,
            boolean ccw,
            int turns,
            double feedMmPerMin)
            implements Move {
        public Circular {
            java.util.Objects.requireNonNull(end, "end");
            java.util.Objects.requireNonNull(center, "center");
            java.util.Objects.requireNonNull(normal, "normal");
            if (Math.abs(normal.norm() - 1) > 1e-9) {
                throw new IllegalArgumentException("arc normal must be a unit vector: " + normal);
            }
            if (turns < 0) {
                throw new IllegalArgumentException("turns must be >= 0: " + turns);
            }
            if (!(feedMmPerMin > 0) || !Double.isFinite(feedMmPerMin)) {
                throw new IllegalArgumentException("feed must be > 0: " + feedMmPerMin);
            }
        }
    }

    /** Whether the move changes the tool's position or path (false for dwells and spindle events). */
    default boolean travels() {
        return this instanceof Rapid || this instanceof Linear || this instanceof Circular;
    }

    /**
     * The tool stays where it is for a time (G04), the spindle running as before.
     *
     * @param end the current position (mm)
     * @param seconds dwell time, >= 0 (ISO 14649 dwell times are in seconds)
     */
    record Dwell(org.fresa.geom.Vec3 end, double seconds) implements Move {
        public Dwell {
            java.util.Objects.requireNonNull(end, "end");
            if (!(seconds >= 0) || !Double.isFinite(seconds)) {
                throw new IllegalArgumentException("dwell must be >= 0 s: " + seconds);
            }
        }
    }

    /**
     * The spindle stops (M05) with the tool where it is; the control waits until it has stopped.
     *
     * @param end the current position (mm)
     */
    record SpindleStop(org.fresa.geom.Vec3 end) implements Move {
        public SpindleStop {
            java.util.Objects.requireNonNull(end, "end");
        }
    }

    /**
     * The spindle starts, or changes speed, with the tool where it is (S.. M03 / M04).
     *
     * @param end the current position (mm)
     * @param rpm spindle speed, > 0
     * @param clockwise M03 when true, M04 otherwise
     */
    record SpindleStart(org.fresa.geom.Vec3 end, double rpm, boolean clockwise) implements Move {
        public SpindleStart {
            java.util.Objects.requireNonNull(end, "end");
            if (!(rpm > 0) || !Double.isFinite(rpm)) {
                throw new IllegalArgumentException("spindle speed must be > 0: " + rpm);
            }
        }
    }
}
