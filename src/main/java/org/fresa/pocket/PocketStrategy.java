package org.fresa.pocket;

import java.util.Objects;
import org.fresa.model.WordedEnum;

/**
 * How a pocket's floor is cleared before the finishing contour: by passes parallel to the walls
 * ({@link Kind#OFFSET}, the thesis's and the default) or by parallel straight lines at an angle
 * ({@link Kind#ZIGZAG}), linked along the pre-finish offset of the walls, or by walks at a constant
 * engagement ({@link Kind#ADAPTIVE}); how much stock is left
 * for a later finish; in which order the offset passes are cut.
 *
 * @param kind the pattern
 * @param angleDeg the zigzag lines' direction, counter-clockwise from +X (deg, -180 to 180); unused by
 *     offset and adaptive
 * @param stockToLeaveMm material left on the walls, the islands and the floor for a later finish
 *     (mm, 0 to {@link #MAX_STOCK_TO_LEAVE_MM}): the passes are planned for walls that much nearer
 *     and a floor that much higher
 * @param order the offset passes' order: from the inside out (the thesis's, the default) or from
 *     the outside in (the finishing pass still last); unused by zigzag and adaptive
 * @param restToolDiameterMm the diameter of a second, smaller tool that cuts only what the first
 *     left and it can reach ({@link RestMachining}), 0 for none (mm); at least
 *     {@link #MIN_REST_TOOL_MM} and smaller than the first tool by more than
 *     {@link #REST_TOOL_MARGIN_MM} ({@link #restToolFits}), checked where the first tool's
 *     diameter is known
 */
public record PocketStrategy(
        Kind kind, double angleDeg, double stockToLeaveMm, Order order, double restToolDiameterMm) {

    /** How much smaller than the first tool a rest tool must be at least (mm): less would find no rest. */
    public static final double REST_TOOL_MARGIN_MM = 0.01;

    /** The smallest rest tool (mm): the smallest tool a pocket may have. */
    public static final double MIN_REST_TOOL_MM = 0.01;

    /** The lines' direction bounds (deg). */
    public static final double MAX_ANGLE_DEG = 180;

    /** The most stock a pocket may leave (mm): a roughing allowance, not a second pocket. */
    public static final double MAX_STOCK_TO_LEAVE_MM = 10;

    /** Today's offset passes, inside out, nothing left. */
    public static final PocketStrategy DEFAULT = new PocketStrategy(Kind.OFFSET, 0);

    /** The order of the offset passes, by the names the command line and the job file use. */
    public enum Order implements WordedEnum {
        /** The innermost pass first, each next pass enclosing the last (the thesis's). */
        INSIDE_OUT,
        /** The outermost roughing pass first, inwards, the finishing pass last. */
        OUTSIDE_IN;

        @Override
        public String toString() {
            return word();
        }
    }

    /** A pattern at an angle, nothing left, inside out. */
    public PocketStrategy(Kind kind, double angleDeg) {
        this(kind, angleDeg, 0, Order.INSIDE_OUT);
    }

    /** A pattern, stock and order with no rest tool. */
    public PocketStrategy(Kind kind, double angleDeg, double stockToLeaveMm, Order order) {
        this(kind, angleDeg, stockToLeaveMm, order, 0);
    }

    /** The same strategy with a rest tool of this diameter (mm), 0 for none. */
    public PocketStrategy withRestTool(double diameterMm) {
        return new PocketStrategy(kind, angleDeg, stockToLeaveMm, order, diameterMm);
    }

    /** Whether a rest tool follows the first. */
    public boolean restTool() {
        return restToolDiameterMm > 0;
    }

    /**
     * Whether a rest tool of this diameter may follow a first tool of that one: at least
     * {@link #MIN_REST_TOOL_MM} and smaller by more than {@link #REST_TOOL_MARGIN_MM}.
     */
    public static boolean restToolFits(double restMm, double firstMm) {
        return restMm >= MIN_REST_TOOL_MM && restMm < firstMm - REST_TOOL_MARGIN_MM;
    }

    /** The patterns, by the names the command line and the job file use. */
    public enum Kind implements WordedEnum {
        /** Passes parallel to the walls, from the inside out. */
        OFFSET,
        /** Parallel lines at an angle, alternating in direction, then the contour passes. */
        ZIGZAG,
        /**
         * Walks that hold the tool's engagement at the stepover's (constant-engagement clearing,
         * {@link AdaptivePocket}), then the contour passes.
         */
        ADAPTIVE;

        @Override
        public String toString() {
            return word();
        }
    }

    public PocketStrategy {
        Objects.requireNonNull(kind, "kind");
        if (!(angleDeg >= -MAX_ANGLE_DEG && angleDeg <= MAX_ANGLE_DEG)) {
            throw new IllegalArgumentException("zigzag angle must be in [-180, 180] deg: " + angleDeg);
        }
        if (!(stockToLeaveMm >= 0 && stockToLeaveMm <= MAX_STOCK_TO_LEAVE_MM)) {
            throw new IllegalArgumentException(
                    "stock to leave must be in [0, " + MAX_STOCK_TO_LEAVE_MM + "] mm: " + stockToLeaveMm);
        }
        Objects.requireNonNull(order, "order");
        if (!(restToolDiameterMm >= 0) || Double.isInfinite(restToolDiameterMm)) {
            throw new IllegalArgumentException("rest tool diameter must be >= 0 mm: " + restToolDiameterMm);
        }
    }

    /**
     * Whether nothing is left, offset passes run inside out and one tool cuts, as the thesis's
     * engine plans them.
     */
    public boolean asThesis() {
        return stockToLeaveMm == 0 && order == Order.INSIDE_OUT && !restTool();
    }

    /** Whether the floor is cleared by walks at a constant engagement ({@link AdaptivePocket}). */
    public boolean adaptive() {
        return kind == Kind.ADAPTIVE;
    }

    /** Whether the floor is cleared by offset passes, the thesis's pattern. */
    public boolean offset() {
        return kind == Kind.OFFSET;
    }

    /** Whether the floor is cleared by zigzag lines. */
    public boolean zigzag() {
        return kind == Kind.ZIGZAG;
    }
}
