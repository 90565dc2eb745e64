package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec3;

/**
 * How the tool enters or leaves the material (ISO 14649-11 plunge strategies). Angles as
 * written (degrees in ISO 14649 files).
 *
 * @param toolOrientation tool_orientation, when given
 * @param angle ramp, helix or zigzag angle
 * @param radiusMm helix radius
 * @param widthMm zigzag width
 */
public record ApproachRetract(
        long instanceId,
        Kind kind,
        String entity,
        Optional<Vec3> toolOrientation,
        OptionalDouble angle,
        OptionalDouble radiusMm,
        OptionalDouble widthMm) {
    public ApproachRetract {
        Objects.requireNonNull(kind);
        Objects.requireNonNull(entity);
        Objects.requireNonNull(toolOrientation);
        Objects.requireNonNull(angle);
        Objects.requireNonNull(radiusMm);
        Objects.requireNonNull(widthMm);
    }

    public enum Kind {
        PLUNGE_TOOLAXIS,
        PLUNGE_RAMP,
        PLUNGE_HELIX,
        PLUNGE_ZIGZAG,
        OTHER
    }
}
