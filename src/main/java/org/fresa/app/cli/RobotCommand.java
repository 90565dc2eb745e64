package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.fresa.cell.RobotTools;
import org.fresa.cell.TablePlacing;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotService;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.setting.SettingRanges;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa robot FILE --robot NAME|FILE --out DIR [placement] [--formats LIST]}. */
@Command(name = "robot", description = "Toolpaths of a STEP-NC file turned into a robot joint trajectory.")
final class RobotCommand extends FolderCommand {

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file")
    Path file;

    @Mixin
    RobotOptions robot = new RobotOptions();

    @Option(
            names = "--robot-table",
            paramLabel = "X,Y,Z[,RZ]",
            description = "table origin in the robot base frame (mm, deg)")
    String robotTable;

    @Option(
            names = "--table-piece",
            paramLabel = "X,Y,Z[,RX,RY,RZ]",
            description = "workpiece origin in the table frame (mm, deg; R = Rz*Ry*Rx)")
    String tablePiece;

    @Option(
            names = "--spindle",
            paramLabel = "X,Y,Z[,RX,RY,RZ]",
            description = "spindle nose in the flange frame (mm, deg; R = Rz*Ry*Rx); default: the robot file's tool"
                    + " frame, else the flange")
    String spindle;

    @Option(
            names = "--tool-length",
            paramLabel = "MM",
            description = "tool length from the spindle nose to the tip for every tool, overriding the STEP-NC"
                    + " tools'; the TCP is spindle * Tz(tool length)")
    Double toolLength;

    @Option(
            names = "--place",
            paramLabel = "auto",
            description =
                    "auto: search the table placement (X, Y, Z, RZ of --robot-table) that reaches every target"
                            + " with the largest joint-limit margin; exit 1 naming the workingsteps out of reach when none does")
    String place;

    @Option(
            names = "--formats",
            paramLabel = "LIST",
            description = "comma list of csv, xml, rapid, krl, png; default ${DEFAULT-VALUE}")
    String formats = String.join(",", org.fresa.job.JobSettings.RobotSettings.DEFAULTS.formats());

    @Mixin
    StepNcPlanningOptions planning = new StepNcPlanningOptions();

    @Override
    TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException {
        List<String> fmts = RobotService.parseFormats(formats);
        Placement table = robotTable == null
                ? Placement.ORIGIN
                : SettingRanges.Robot.check("--robot-table", PlacementOptions.parseRobotTable(robotTable));
        Placement piece = tablePiece == null
                ? Placement.ORIGIN
                : SettingRanges.Robot.check("--table-piece", PlacementOptions.parseTablePiece(tablePiece));
        PlanningChoices choices = planning.choices();
        RobotTools.Choice tool = RobotOptions.tool(spindle, toolLength);
        TablePlacing placing = place == null ? TablePlacing.GIVEN : TablePlacing.parse("--place", place);
        TaskOutcome o = CliSupport.intoFolder(
                out,
                folder -> RobotService.run(
                        new RobotService.Settings(file, robot.robot, table, piece, fmts, choices, tool, placing),
                        folder,
                        progress));
        if (!json
                && o.summary().get("placement_search") instanceof java.util.Map<?, ?> m
                && String.valueOf(m.get("what")).startsWith("placement found")) {
            // the placement chosen on stdout, where the planner reads it back, also when a workingstep
            // is left out (exit 1); none found: the reason is on stderr
            TerminalProgress.clear(progress);
            out().println(m.get("what"));
        }
        return o;
    }
}
