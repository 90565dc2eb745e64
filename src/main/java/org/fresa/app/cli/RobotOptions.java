package org.fresa.app.cli;

import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.cell.RobotTools;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRanges;
import picocli.CommandLine.Option;

/**
 * What {@code fresa robot} and {@code fresa ik} share: the robot, and the reading of the tool it
 * carries. The two commands word {@code --spindle} and {@code --tool-length} each for its own case
 * (the robot's tool length overrides the STEP-NC tools'), so only the reading is shared.
 */
final class RobotOptions {

    @Option(
            names = "--robot",
            required = true,
            paramLabel = "NAME|FILE",
            description = "built-in robot (irb140, adept-one, tricept806) or a robot file")
    String robot;

    /**
     * The tool asked for on the command line; what is not given comes from the robot file or the
     * STEP-NC tools.
     *
     * @param spindle {@code --spindle X,Y,Z[,RX,RY,RZ]} (mm, deg), or null
     * @param toolLengthMm {@code --tool-length}, or null
     * @throws CamInputException naming the option whose value is not numbers in range
     */
    static RobotTools.Choice tool(String spindle, Double toolLengthMm) throws CamInputException {
        return new RobotTools.Choice(
                spindle == null ? Optional.empty() : Optional.of(SettingRanges.Robot.parseSpindle(spindle)),
                toolLengthMm == null
                        ? OptionalDouble.empty()
                        : OptionalDouble.of(SettingRanges.Robot.TOOL_LENGTH.check(toolLengthMm)));
    }
}
