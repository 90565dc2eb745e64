package org.fresa.stepnc;

import java.util.List;
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
 * @param curve GENERAL_PATH's swept_path, its lines and arcs in the path frame (empty for the
 *     other paths, and for a curve the binding does not read)
 */
public record TravelPath(
        String entity,
        Transform3 placement,
        OptionalDouble distanceMm,
        Optional<Vec3> direction,
        OptionalDouble radiusMm,
        OptionalDouble sweepAngle,
        List<Profile.Segment> curve) {
    public TravelPath {
        curve = List.copyOf(curve);
        Objects.requireNonNull(entity);
        Objects.requireNonNull(placement);
        Objects.requireNonNull(distanceMm);
        Objects.requireNonNull(direction);
        Objects.requireNonNull(radiusMm);
        Objects.requireNonNull(sweepAngle);
    }

    /** A path that is not a GENERAL_PATH: no curve. */
    public TravelPath(
            String entity,
            Transform3 placement,
            OptionalDouble distanceMm,
            Optional<Vec3> direction,
            OptionalDouble radiusMm,
            OptionalDouble sweepAngle) {
        this(entity, placement, distanceMm, direction, radiusMm, sweepAngle, List.of());
    }
}
