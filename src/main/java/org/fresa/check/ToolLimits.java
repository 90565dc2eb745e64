package org.fresa.check;

/**
 * How a tool may enter the material: the steepest descending feed move allowed, and whether it
 * may go straight down (a drill, or a centre-cutting tool asked to plunge).
 *
 * @param entryAngleDeg the steepest descent into the material, degrees from the horizontal, in (0, 90]
 * @param plunge vertical (and any steeper than {@code entryAngleDeg}) feed moves allowed
 * @param kind the tool in the planner's words, for messages ("end mill not cutting at its centre")
 * @param radiusMm the cutter's radius, by which it reaches into the stock beside its axis (0 when unknown)
 */
public record ToolLimits(double entryAngleDeg, boolean plunge, String kind, double radiusMm) {

    /** The entry angle of a tool that does not cut at its centre, unless the job says otherwise. */
    public static final double DEFAULT_ENTRY_ANGLE_DEG = 3;

    public ToolLimits {
        if (!(entryAngleDeg > 0 && entryAngleDeg <= 90)) {
            throw new IllegalArgumentException("entry angle must be in (0, 90] degrees: " + entryAngleDeg);
        }
        java.util.Objects.requireNonNull(kind, "kind");
        if (!(radiusMm >= 0) || Double.isInfinite(radiusMm)) {
            throw new IllegalArgumentException("radius must be >= 0: " + radiusMm);
        }
    }

    /** A milling cutter that does not cut at its centre: ramps of at most 3 degrees. */
    public static ToolLimits notCentreCutting() {
        return new ToolLimits(DEFAULT_ENTRY_ANGLE_DEG, false, "a cutter not cutting at its centre", 0);
    }

    /** A drill (or a centre drill, a reamer, a tap): straight down. */
    public static ToolLimits drill() {
        return new ToolLimits(90, true, "a drill", 0);
    }

    /** A centre-cutting cutter asked to plunge. */
    public static ToolLimits centreCuttingPlunge() {
        return new ToolLimits(90, true, "a centre-cutting cutter asked to plunge", 0);
    }

    /** The same tool with another entry angle. */
    public ToolLimits withEntryAngleDeg(double deg) {
        return new ToolLimits(deg, plunge, kind, radiusMm);
    }

    /** The same tool with its radius. */
    public ToolLimits withRadiusMm(double r) {
        return new ToolLimits(entryAngleDeg, plunge, kind, r);
    }

    /** The same tool in other words. */
    public ToolLimits withKind(String k) {
        return new ToolLimits(entryAngleDeg, plunge, k, radiusMm);
    }
}
