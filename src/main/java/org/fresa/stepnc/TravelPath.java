package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * A course of travel (LINEAR_PATH, CIRCULAR_PATH, ...) of a planar face, slot or step, in the
 * feature frame.
 *
 * @param entity the entity name as written
 * @param placement the path frame in the feature frame (identity when unset)
 * @param distanceMm LINEAR_PATH's length
 * @param direction LINEAR_PATH's direction in the path frame
 * @param radiusMm CIRCULAR_PATH's radius
 * @param sweepAngle CIRCULAR_PATH's sweep, as written (radians in ISO 14649)
 */
public record TravelPath(
        String entity,
        Transform3 placement,
        OptionalDouble distanceMm,
        Optional<Vec3> direction,
        OptionalDouble radiusMm,
        OptionalDouble sweepAngle) {
    public TravelPath {
        Objects.requireNonNull(entity);
        Objects.requireNonNull(placement);
        Objects.requireNonNull(distanceMm);
        Objects.requireNonNull(direction);
        Objects.requireNonNull(radiusMm);
        Objects.requireNonNull(sweepAngle);
    }
}
