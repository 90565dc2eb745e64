package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec3;

/**
 * A machining operation (ISO 14649-10/11): what the tool does on a feature. Lengths in mm.
 *
 * @param instanceId the instance name
 * @param type the kind of operation
 * @param entity the entity name as written
 * @param id its_id (empty string when unset)
 * @param retractPlaneMm retract_plane: height above the feature for rapid moves
 * @param startPoint start_point in the feature frame
 * @param tool the cutting tool
 * @param technology feed and speeds
 * @param strategy milling strategy (its_machining_strategy) or drilling strategy
 * @param approach approach strategy (milling)
 * @param retract retract strategy (milling)
 * @param axialCuttingDepthMm milling: depth per layer
 * @param radialCuttingDepthMm milling: stepover
 * @param allowanceSideMm milling: material left on the walls
 * @param allowanceBottomMm milling: material left on the floor
 * @param cuttingDepthMm drilling: depth of the drilling operation
 * @param overcutLengthMm overcut_length
 * @param drilling drilling-type operations: dwell, retract feed, steps, spindle stop
 * @param toolpaths its explicit toolpaths (its_toolpath), in order; empty when the planner makes them
 */
public record Operation(
        long instanceId,
        OperationType type,
        String entity,
        String id,
        OptionalDouble retractPlaneMm,
        Optional<Vec3> startPoint,
        Optional<Tool> tool,
        Technology technology,
        Optional<Strategy> strategy,
        Optional<ApproachRetract> approach,
        Optional<ApproachRetract> retract,
        OptionalDouble axialCuttingDepthMm,
        OptionalDouble radialCuttingDepthMm,
        OptionalDouble allowanceSideMm,
        OptionalDouble allowanceBottomMm,
        OptionalDouble cuttingDepthMm,
        OptionalDouble overcutLengthMm,
        Optional<DrillingParameters> drilling,
        List<ExplicitToolpath> toolpaths) {

    public Operation {
        Objects.requireNonNull(type);
        Objects.requireNonNull(entity);
        Objects.requireNonNull(id);
        Objects.requireNonNull(retractPlaneMm);
        Objects.requireNonNull(startPoint);
        Objects.requireNonNull(tool);
        Objects.requireNonNull(technology);
        Objects.requireNonNull(strategy);
        Objects.requireNonNull(approach);
        Objects.requireNonNull(retract);
        Objects.requireNonNull(axialCuttingDepthMm);
        Objects.requireNonNull(radialCuttingDepthMm);
        Objects.requireNonNull(allowanceSideMm);
        Objects.requireNonNull(allowanceBottomMm);
        Objects.requireNonNull(cuttingDepthMm);
        Objects.requireNonNull(overcutLengthMm);
        Objects.requireNonNull(drilling);
        toolpaths = List.copyOf(toolpaths);
    }

    public enum OperationType {
        PLANE_ROUGH_MILLING,
        PLANE_FINISH_MILLING,
        SIDE_ROUGH_MILLING,
        SIDE_FINISH_MILLING,
        BOTTOM_AND_SIDE_ROUGH_MILLING,
        BOTTOM_AND_SIDE_FINISH_MILLING,
        DRILLING,
        CENTER_DRILLING,
        MULTISTEP_DRILLING,
        COUNTER_SINKING,
        REAMING,
        BORING,
        BACK_BORING,
        TAPPING,
        THREAD_DRILLING,
        FREEFORM_OPERATION,
        /** an operation entity the binding does not know */
        OTHER;

        public boolean isMilling() {
            return ordinal() <= BOTTOM_AND_SIDE_FINISH_MILLING.ordinal();
        }

        public boolean isDrillingType() {
            return ordinal() >= DRILLING.ordinal() && ordinal() <= THREAD_DRILLING.ordinal();
        }
    }
}
