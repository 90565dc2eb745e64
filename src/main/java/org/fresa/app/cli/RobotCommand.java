package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.Callable;
import org.fresa.cell.RobotTools;
import org.fresa.cell.TablePlacing;
import org.fresa.job.RobotService;
import org.fresa.job.TaskOutcome;
import org.fresa.model.Placement;
import org.fresa.setting.SettingRanges;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fresa robot FILE --robot NAME|FILE --out DIR [placement] [--formats LIST]}. */
@Command(
        name = "robot",
        mixinStandardHelpOptions = true,
        description = "Toolpaths of a STEP-NC file turned into a robot joint trajectory.")
final class RobotCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file")
    Path file;

    @Option(
            names = "--robot",
            required = true,
            paramLabel = "NAME|FILE",
            description = "built-in robot (irb140, adept-one, tricept806) or a robot file")
    String robot;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

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

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Option(
            names = "--trust-cutting-speed",
            description = "plan a workingstep whose spindle and cutting speed disagree tenfold from the cutting speed"
                    + " (else it is refused)")
    boolean trustCuttingSpeed;

    @Option(
            names = "--breakthrough",
            paramLabel = "MM",
            description = "how far a through hole's drill (full diameter) or milling cutter passes the exit;"
                    + " default ${DEFAULT-VALUE} mm")
    double breakthroughMm = org.fresa.job.JobSettings.StepNcSettings.DEFAULTS.breakthroughMm();

    @Mixin
    StepNcEntryOptions entries = new StepNcEntryOptions();

    @Option(
            names = "--paths",
            paramLabel = "fresa|thesis",
            defaultValue = "fresa",
            description = "whose path conventions: fresa (exact arcs, gentle entries) or thesis (the 2016 STEP-NC robot"
                    + " thesis's points, docs/thesis-paths.md); default ${DEFAULT-VALUE}")
    String paths;

    @Override
    public Integer call() {
        return CliSupport.run(spec.commandLine().getOut(), spec.commandLine().getErr(), json, progress -> {
            List<String> fmts = RobotService.parseFormats(formats);
            Placement table = robotTable == null
                    ? Placement.ORIGIN
                    : SettingRanges.Robot.check("--robot-table", PlacementOptions.parseRobotTable(robotTable));
            Placement piece = tablePiece == null
                    ? Placement.ORIGIN
                    : SettingRanges.Robot.check("--table-piece", PlacementOptions.parseTablePiece(tablePiece));
            PlanningChoices choices = new PlanningChoices(
                    trustCuttingSpeed,
                    SettingRanges.StepNc.BREAKTHROUGH.check(breakthroughMm),
                    entries.rule(),
                    SettingRanges.StepNc.paths("--paths", paths));
            RobotTools.Choice tool = new RobotTools.Choice(
                    spindle == null ? Optional.empty() : Optional.of(SettingRanges.Robot.parseSpindle(spindle)),
                    toolLength == null
                            ? OptionalDouble.empty()
                            : OptionalDouble.of(SettingRanges.Robot.TOOL_LENGTH.check(toolLength)));
            TablePlacing placing = place == null ? TablePlacing.GIVEN : TablePlacing.parse("--place", place);
            TaskOutcome o = CliSupport.intoFolder(
                    out,
                    folder -> RobotService.run(
                            new RobotService.Settings(file, robot, table, piece, fmts, choices, tool, placing),
                            folder,
                            progress));
            if (!json && o.exitStatus() == 0 && o.summary().get("placement_search") instanceof java.util.Map<?, ?> m) {
                // the placement chosen on stdout, where the planner reads it back (none: the reason is on stderr)
                TerminalProgress.clear(progress);
                spec.commandLine().getOut().println(m.get("what"));
            }
            return o;
        });
    }
}
