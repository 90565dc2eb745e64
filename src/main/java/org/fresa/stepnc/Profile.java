package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * An ISO 14649-10 profile: the outline of a pocket or boss, the cross-section of a slot or step,
 * the removal boundary of a planar face. Lengths in mm, angles in radians as the file writes
 * them. The placement is the profile's frame in the feature frame (identity when the file leaves
 * it unset, and when it repeats the feature's own placement, as GRIMA's writers do); closed
 * profiles are centred on their frame's origin, as ISO 14649-10 defines them.
 */
public sealed interface Profile {

    /** The entity name as written in the file. */
    String entity();

    /** The profile frame in the feature frame. */
    Transform3 placement();

    /** RECTANGULAR_CLOSED_PROFILE: x along the length, y along the width, centred. */
    record Rectangular(String entity, Transform3 placement, double widthMm, double lengthMm) implements Profile {
        public Rectangular {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /** CIRCULAR_CLOSED_PROFILE, centred. */
    record Circular(String entity, Transform3 placement, double diameterMm) implements Profile {
        public Circular {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /**
     * NGON_PROFILE.
     *
     * @param circumscribed true: the n-gon surrounds a circle of the diameter (across flats);
     *                      false: its corners lie on that circle
     */
    record Ngon(String entity, Transform3 placement, double diameterMm, int sides, boolean circumscribed)
            implements Profile {
        public Ngon {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /**
     * GENERAL_CLOSED_PROFILE or GENERAL_PROFILE: a chain of lines and arcs in the profile frame
     * (a POLYLINE gives lines only, a COMPOSITE_CURVE of trimmed lines and circles keeps its arcs).
     *
     * @param closed whether the chain ends where it starts
     */
    record General(String entity, Transform3 placement, String curveEntity, List<Segment> segments, boolean closed)
            implements Profile {
        public General {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
            Objects.requireNonNull(curveEntity);
            segments = List.copyOf(segments);
        }
    }

    /** LINEAR_PROFILE: a straight open profile of the given length along x. */
    record Linear(String entity, Transform3 placement, double lengthMm) implements Profile {
        public Linear {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /**
     * SQUARE_U_PROFILE and ROUNDED_U_PROFILE (radii and angles empty for the rounded form, whose
     * bottom is a half circle of the width). A square U's radii blend its bottom into each side, and
     * its angles are each side's to the bottom in degrees (90 for a side square to it): the first
     * side is the one that meets the profile's x axis at a positive value.
     */
    record U(
            String entity,
            Transform3 placement,
            double widthMm,
            OptionalDouble firstRadiusMm,
            OptionalDouble firstAngleDeg,
            OptionalDouble secondRadiusMm,
            OptionalDouble secondAngleDeg)
            implements Profile {
        public U {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /**
     * VEE_PROFILE: two straight walls meeting at the included angle, blended at the bottom by the
     * profile radius (a sharp V without it); the tilt is the first wall's angle from the profile's
     * x axis (across the slot), so an upright V has tilt 90 - angle / 2. Angles in degrees,
     * converted from radians where the file's writer uses them.
     */
    record Vee(
            String entity,
            Transform3 placement,
            OptionalDouble profileRadiusMm,
            double profileAngleDeg,
            double tiltAngleDeg)
            implements Profile {
        public Vee {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
            Objects.requireNonNull(profileRadiusMm);
        }
    }

    /**
     * TEE_PROFILE: a stem of the width from the top down to a cross bar of cross_bar_width by
     * cross_bar_depth at the bottom of the feature (the T upside down, as a T-slot is cut); the
     * angles are those of the stem's walls with the cross bar (90 for a straight stem), in degrees.
     */
    record Tee(
            String entity,
            Transform3 placement,
            double widthMm,
            double crossBarWidthMm,
            double crossBarDepthMm,
            OptionalDouble radiusMm,
            double firstAngleDeg,
            double secondAngleDeg)
            implements Profile {
        public Tee {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
            Objects.requireNonNull(radiusMm);
        }
    }

    /**
     * PARTIAL_CIRCULAR_PROFILE: an arc of the radius about the placement's origin, from the
     * placement's x axis counter-clockwise about its z axis by the sweep; for a slot the z axis
     * runs along the path and the arc is the slot's cross-section. The sweep in degrees,
     * converted from radians where the file's writer uses them.
     */
    record PartialCircular(String entity, Transform3 placement, double radiusMm, double sweepAngleDeg)
            implements Profile {
        public PartialCircular {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /** A profile the binding does not turn into geometry (a dovetail, ...). */
    record Other(String entity, Transform3 placement, long instanceId) implements Profile {
        public Other {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(placement);
        }
    }

    /** One element of a general profile, in the profile frame (z is normally 0). */
    sealed interface Segment {
        Vec3 start();

        Vec3 end();
    }

    record Line(Vec3 start, Vec3 end) implements Segment {}

    /** A circular arc about the profile's z axis. */
    record Arc(Vec3 start, Vec3 end, Vec3 center, double radiusMm, boolean ccw) implements Segment {}
}
