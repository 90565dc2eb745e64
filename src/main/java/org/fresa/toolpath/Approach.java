package org.fresa.toolpath;

/**
 * How the tool enters the material at the start of a layer (ISO 14649 approach strategies),
 * from the clearance height down to the layer.
 */
public sealed interface Approach permits Approach.Plunge, Approach.Ramp, Approach.Helix {

    /** Straight down along the tool axis at the plunge feed. */
    record Plunge() implements Approach {}

    /**
     * Down a zig-zag ramp along the pass's first straight element, at most {@code angleDeg} from
     * the floor; a plunge where the first element is not straight.
     */
    record Ramp(double angleDeg) implements Approach {
        public Ramp {
            if (!(angleDeg > 0 && angleDeg <= 90)) {
                throw new IllegalArgumentException("ramp angle must be in (0, 90]: " + angleDeg);
            }
        }
    }

    /**
     * Down a helix of the given radius about a point beside the pass start, at most
     * {@code angleDeg} steep; a plunge where the helix does not fit inside the tool-centre region.
     */
    record Helix(double radiusMm, double angleDeg) implements Approach {
        public Helix {
            if (!(radiusMm > 0) || !(angleDeg > 0 && angleDeg < 90)) {
                throw new IllegalArgumentException("bad helix: radius " + radiusMm + ", angle " + angleDeg);
            }
        }
    }
}
