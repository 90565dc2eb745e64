package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * A manufacturing feature of ISO 14649-10 (2½D): where it is, how deep, and its outline.
 *
 * <p>Conventions: {@code placement} is the feature frame in the workpiece frame (its z axis
 * points out of the material, the tool comes from +z); {@code depthMm} is how far the feature
 * goes below its placement along -z, from the depth plane (ISO: the depth plane's location in
 * the feature frame, negated); empty when the file has no depth plane (e.g. a through feature
 * that leaves it unset).
 *
 * @param instanceId the instance name in the file
 * @param type the kind of feature
 * @param entity the entity name as written (ROUND_HOLE, CLOSED_POCKET, ...)
 * @param id its_id
 * @param placement feature frame in the workpiece frame
 * @param depthMm feature depth, positive into the material
 * @param depthPlane the depth plane frame in the feature frame
 * @param profile the outline: pocket boundary (closed or open), boss boundary, slot swept
 *                shape, step wall profile, planar face removal boundary; empty for holes
 * @param courseOfTravel of a planar face, slot or step
 * @param diameterMm of a round hole
 * @param bottomCondition the bottom condition's entity name (FLAT_HOLE_BOTTOM,
 *                        THROUGH_BOTTOM_CONDITION, PLANAR_POCKET_BOTTOM_CONDITION, ...)
 * @param planarRadiusMm pocket: radius between floor and walls
 * @param orthogonalRadiusMm pocket: corner radius of the walls (about the feature z axis)
 * @param operationIds the instance names of its_operations, in file order
 * @param slotEnds a slot's end_conditions in file order (the path's start, then its end); empty
 *                 for other features and for a slot whose file gives none
 * @param bosses its_boss (pockets, planar faces, steps) in file order: the material the feature
 *               must leave standing, each a BOSS in the workpiece frame
 * @param taper a round hole's change_in_diameter; empty for a straight hole
 */
public record Feature(
        long instanceId,
        FeatureType type,
        String entity,
        String id,
        Transform3 placement,
        OptionalDouble depthMm,
        Optional<Transform3> depthPlane,
        Optional<Profile> profile,
        Optional<TravelPath> courseOfTravel,
        OptionalDouble diameterMm,
        Optional<String> bottomCondition,
        OptionalDouble planarRadiusMm,
        OptionalDouble orthogonalRadiusMm,
        List<Long> operationIds,
        List<SlotEnd> slotEnds,
        List<Feature> bosses,
        Optional<HoleTaper> taper) {

    public Feature {
        Objects.requireNonNull(type);
        Objects.requireNonNull(entity);
        Objects.requireNonNull(id);
        Objects.requireNonNull(placement);
        Objects.requireNonNull(depthMm);
        Objects.requireNonNull(depthPlane);
        Objects.requireNonNull(profile);
        Objects.requireNonNull(courseOfTravel);
        Objects.requireNonNull(diameterMm);
        Objects.requireNonNull(bottomCondition);
        Objects.requireNonNull(planarRadiusMm);
        Objects.requireNonNull(orthogonalRadiusMm);
        operationIds = List.copyOf(operationIds);
        slotEnds = List.copyOf(slotEnds);
        bosses = List.copyOf(bosses);
        Objects.requireNonNull(taper);
    }

    /**
     * A round hole's change_in_diameter (ISO 14649-10 taper_select): its diameter at the bottom
     * (DIAMETER_TAPER's final_diameter), or the angle its wall leans in from the axis
     * (ANGLE_TAPER), or neither when the binding could not read it (the entity says what it was).
     */
    public record HoleTaper(String entity, OptionalDouble finalDiameterMm, OptionalDouble angleDeg) {
        public HoleTaper {
            Objects.requireNonNull(entity);
            Objects.requireNonNull(finalDiameterMm);
            Objects.requireNonNull(angleDeg);
        }
    }

    /**
     * One end of a slot (ISO 14649-10 slot_end_type).
     *
     * @param type which end
     * @param entity the entity name as written
     * @param firstRadiusMm FLAT_SLOT_END_TYPE's corner_radius1, WOODRUFF_SLOT_END_TYPE's radius
     * @param secondRadiusMm FLAT_SLOT_END_TYPE's corner_radius2
     */
    public record SlotEnd(EndType type, String entity, OptionalDouble firstRadiusMm, OptionalDouble secondRadiusMm) {
        public SlotEnd {
            Objects.requireNonNull(type);
            Objects.requireNonNull(entity);
            Objects.requireNonNull(firstRadiusMm);
            Objects.requireNonNull(secondRadiusMm);
        }

        /** The kinds of slot end. */
        public enum EndType {
            /** the slot runs out of the material: the tool may pass the end */
            OPEN,
            /** a half circle of the slot's width about the path's end */
            RADIUSED,
            /** a wall square to the path, its corners rounded by the two radii where given */
            FLAT,
            /** the slot closes on itself (a closed path) */
            LOOP,
            /** the end rises to the top as an arc of the radius in the path's vertical plane */
            WOODRUFF,
            /** an end entity the binding does not know */
            OTHER
        }
    }

    /** The feature origin in the workpiece frame, mm. */
    public Vec3 location() {
        return placement.translationPart();
    }

    /** The feature z axis (out of the material) in the workpiece frame. */
    public Vec3 axis() {
        return placement.zAxis();
    }

    /** The kinds of feature the binding knows. */
    public enum FeatureType {
        PLANAR_FACE,
        CLOSED_POCKET,
        OPEN_POCKET,
        ROUND_HOLE,
        SLOT,
        STEP,
        BOSS,
        GENERAL_OUTSIDE_PROFILE,
        /** a feature entity the binding does not interpret; see the entity name */
        OTHER
    }
}
