package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * A cutting tool (ISO 14649-111): MILLING_CUTTING_TOOL or CUTTING_TOOL with its tool body and
 * dimension. Lengths in mm. Angles as the file writes them: ISO 14649 files use degrees where
 * STEP Modeler (GRIMA) writes radians; {@link #angleUnit()} says which was assumed.
 *
 * @param instanceId the cutting tool instance
 * @param id its_id
 * @param body the tool body's entity name (FACEMILL, TWIST_DRILL, TAPERED_ENDMILL, ...)
 * @param dimensionEntity TOOL_DIMENSION (FDIS) or MILLING_TOOL_DIMENSION (IS), as written
 * @param diameterMm the cutting diameter
 * @param topAngle tool_top_angle (point angle of drills)
 * @param circumferenceAngle tool_circumference_angle
 * @param cuttingEdgeLengthMm cutting_edge_length
 * @param edgeRadiusMm edge_radius (corner radius of the cutting edge)
 * @param edgeCenterVerticalMm edge_center_vertical
 * @param edgeCenterHorizontalMm edge_center_horizontal
 * @param overallAssemblyLengthMm overall_assembly_length of the cutting tool
 * @param toolOffsetLengthMm the first cutting component's tool_offset_length
 * @param teeth number_of_teeth
 * @param handOfCut LEFT, RIGHT or NEUTRAL
 * @param pilotLengthMm the body's last common attribute (pilot_length)
 * @param angleUnit "deg" or "rad"
 */
public record Tool(
        long instanceId,
        String id,
        String body,
        String dimensionEntity,
        OptionalDouble diameterMm,
        OptionalDouble topAngle,
        OptionalDouble circumferenceAngle,
        OptionalDouble cuttingEdgeLengthMm,
        OptionalDouble edgeRadiusMm,
        OptionalDouble edgeCenterVerticalMm,
        OptionalDouble edgeCenterHorizontalMm,
        OptionalDouble overallAssemblyLengthMm,
        OptionalDouble toolOffsetLengthMm,
        OptionalInt teeth,
        Optional<String> handOfCut,
        OptionalDouble pilotLengthMm,
        String angleUnit) {
    public Tool {
        Objects.requireNonNull(id);
        Objects.requireNonNull(body);
        Objects.requireNonNull(dimensionEntity);
        Objects.requireNonNull(diameterMm);
        Objects.requireNonNull(topAngle);
        Objects.requireNonNull(circumferenceAngle);
        Objects.requireNonNull(cuttingEdgeLengthMm);
        Objects.requireNonNull(edgeRadiusMm);
        Objects.requireNonNull(edgeCenterVerticalMm);
        Objects.requireNonNull(edgeCenterHorizontalMm);
        Objects.requireNonNull(overallAssemblyLengthMm);
        Objects.requireNonNull(toolOffsetLengthMm);
        Objects.requireNonNull(teeth);
        Objects.requireNonNull(handOfCut);
        Objects.requireNonNull(pilotLengthMm);
        Objects.requireNonNull(angleUnit);
    }
}
