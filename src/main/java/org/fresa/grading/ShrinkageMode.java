package org.fresa.grading;

import java.util.Locale;

/**
 * How the material shrinkage allowance S (a fraction, 0.02 = 2 %) enters the scale factors.
 *
 * <ul>
 *   <li>{@link #ADDITIVE}: the thesis's eq. (4.10), factor = ALFA + S. It equals the
 *       multiplicative form only at the pattern's own size.
 *   <li>{@link #MULTIPLICATIVE} (the default): factor = ALFA * (1 + S), which is what a mould
 *       needs: the cavity is the graded sole enlarged by the shrinkage, at every size.
 * </ul>
 */
public enum ShrinkageMode {
    ADDITIVE,
    MULTIPLICATIVE;

    /** The factor with shrinkage, from the grading factor alone. */
    public double apply(double factor, double shrinkage) {
        return this == ADDITIVE ? factor + shrinkage : factor * (1 + shrinkage);
    }

    /** The inverse of {@link #apply}. */
    public double remove(double factor, double shrinkage) {
        return this == ADDITIVE ? factor - shrinkage : factor / (1 + shrinkage);
    }

    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    @Override
    public String toString() {
        return id();
    }

    /** @throws IllegalArgumentException for a name that is not a mode */
    public static ShrinkageMode ofId(String id) {
        for (ShrinkageMode m : values()) {
            if (m.id().equals(id.trim().toLowerCase(Locale.ROOT))) {
                return m;
            }
        }
        throw new IllegalArgumentException("expected additive or multiplicative, found '" + id + "'");
    }
}
