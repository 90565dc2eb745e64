package org.fresa.pocket;

import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * How a pocket's floor is cleared before the finishing contour: by passes parallel to the walls
 * ({@link Kind#OFFSET}, the thesis's and the default) or by parallel straight lines at an angle
 * ({@link Kind#ZIGZAG}), linked along the pre-finish offset of the walls.
 *
 * @param kind the pattern
 * @param angleDeg the zigzag lines' direction, counter-clockwise from +X (deg, -180 to 180); unused by offset
 */
public record PocketStrategy(Kind kind, double angleDeg) {

    /** The lines' direction bounds (deg). */
    public static final double MAX_ANGLE_DEG = 180;

    /** Today's offset passes. */
    public static final PocketStrategy DEFAULT = new PocketStrategy(Kind.OFFSET, 0);

    /** The patterns, by the names the command line and the job file use. */
    public enum Kind {
        /** Passes parallel to the walls, from the inside out. */
        OFFSET,
        /** Parallel lines at an angle, alternating in direction, then the contour passes. */
        ZIGZAG;

        /** The name as written: {@code offset}, {@code zigzag}. */
        public String word() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The kind of a name as written, or empty. */
        public static java.util.Optional<Kind> of(String word) {
            for (Kind k : values()) {
                if (k.word().equals(word)) {
                    return java.util.Optional.of(k);
                }
            }
            return java.util.Optional.empty();
        }

        /** The names, the default first. */
        public static List<String> words() {
            return java.util.Arrays.stream(values()).map(Kind::word).toList();
        }

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
    }

    /** Whether the floor is cleared by zigzag lines. */
    public boolean zigzag() {
        return kind == Kind.ZIGZAG;
    }
}
