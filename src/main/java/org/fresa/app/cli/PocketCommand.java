package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.Optional;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.PocketService;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.PocketPost;
import org.fresa.setting.SettingRanges.Pocket;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code fresa pocket CONTOUR --out FILE [technology options] [--post NAME] [--direction D] [--report FILE]
 * [--strategy offset|zigzag] [--angle DEG] [--stock-to-leave MM] [--order inside-out|outside-in]
 * [--rest-tool D] [--thesis-name NAME] [--json]}.
 */
@Command(
        name = "pocket",
        sortOptions = false,
        description = "Pocket milling of one closed contour of lines and arcs, from the inside out.")
final class PocketCommand extends CliCommand {

    private static final PocketSettings DEFAULTS = PocketSettings.DEFAULTS;

    @Parameters(
            index = "0",
            paramLabel = "CONTOUR",
            description = ".dad (73-column records), .dxf or Fresa contour file")
    Path contour;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "NC program to write")
    Path out;

    @Option(names = "--tool-diameter", required = true, paramLabel = "D", description = "cutter diameter (mm)")
    double toolDiameterMm;

    @Option(names = "--cut", paramLabel = "P", description = "stepover as a fraction of the diameter")
    double cutFraction = DEFAULTS.cutFraction();

    @Option(names = "--finish", paramLabel = "F", description = "finish allowance as a fraction of the diameter")
    double finishFraction = DEFAULTS.finishFraction();

    @Option(names = "--z-top", paramLabel = "Z", description = "top of the pocket (mm)")
    double zTopMm = DEFAULTS.zTopMm();

    @Option(names = "--z-bottom", paramLabel = "Z", description = "floor of the pocket (mm)")
    double zBottomMm = DEFAULTS.zBottomMm();

    @Option(names = "--max-depth", paramLabel = "DZ", description = "largest depth per pass (mm)")
    double maxDepthMm = DEFAULTS.maxDepthPerPassMm();

    @Option(names = "--rpm", paramLabel = "S", description = "spindle speed (rpm)")
    double spindleRpm = DEFAULTS.spindleRpm();

    @Option(names = "--feed", paramLabel = "F", description = "roughing feed (mm/min)")
    double feedMmPerMin = DEFAULTS.feedMmPerMin();

    @Option(names = "--finish-feed", paramLabel = "F", description = "finishing feed (mm/min)")
    double finishFeedMmPerMin = DEFAULTS.finishFeedMmPerMin();

    @Option(
            names = "--post",
            paramLabel = "NAME",
            description = "7m, 7m-compat, iso, linuxcnc, fanuc, 840d, apt (APT / CL data); default ${DEFAULT-VALUE}")
    PocketPost post = DEFAULTS.post();

    @Option(
            names = "--direction",
            paramLabel = "climb|conventional",
            description = "milling direction on every post but 7m-compat (which keeps the thesis's conventional"
                    + " passes); default ${DEFAULT-VALUE}")
    MillingDirection direction = DEFAULTS.direction();

    @Option(
            names = "--entry",
            paramLabel = "auto|helix|ramp|plunge",
            description = "how the tool enters the material: a helix where it has room, else a zig-zag ramp (auto),"
                    + " helix, ramp, or plunge (centre-cutting tools only); 7m-compat keeps the thesis's plunge;"
                    + " default ${DEFAULT-VALUE}")
    EntryRule.Kind entry = DEFAULTS.entry();

    @Option(
            names = "--entry-angle",
            paramLabel = "DEG",
            description = "steepest descent of a helix or ramp entry (deg, 0.5 to 90); default ${DEFAULT-VALUE}")
    double entryAngleDeg = DEFAULTS.entryAngleDeg();

    @Option(names = "--centre-cutting", description = "the cutter cuts at its centre (may plunge)")
    boolean centreCutting;

    @Option(
            names = "--strategy",
            paramLabel = "offset|zigzag|adaptive",
            description = "how the floor is cleared: passes parallel to the walls (offset), parallel lines at"
                    + " --angle then the contour passes (zigzag), or walks that hold the tool's engagement at the"
                    + " stepover then the contour passes (adaptive; where the geometry forces a wider cut the feed"
                    + " drops in proportion); zigzag and adaptive: G-code and APT posts only; default"
                    + " ${DEFAULT-VALUE}")
    PocketStrategy.Kind strategy = DEFAULTS.strategy().kind();

    @Option(
            names = "--angle",
            paramLabel = "DEG",
            description = "direction of the zigzag lines, counter-clockwise from +X (deg, -180 to 180);"
                    + " default ${DEFAULT-VALUE}")
    double angleDeg = DEFAULTS.strategy().angleDeg();

    @Option(
            names = "--stock-to-leave",
            paramLabel = "MM",
            description = "material left on the walls, islands and floor for a later finish (mm, 0 to 10; G-code and"
                    + " APT posts); default ${DEFAULT-VALUE}")
    double stockToLeaveMm = DEFAULTS.strategy().stockToLeaveMm();

    @Option(
            names = "--order",
            paramLabel = "inside-out|outside-in",
            description = "order of the offset passes (the finishing pass last either way; outside-in on G-code and"
                    + " APT posts); default ${DEFAULT-VALUE}")
    PocketStrategy.Order order = DEFAULTS.strategy().order();

    @Option(
            names = "--rest-tool",
            paramLabel = "D",
            description =
                    "a second, smaller tool (T2, diameter in mm, at least 0.01 and below --tool-diameter less 0.01)"
                            + " that cuts only what the first left and it can reach (G-code and APT posts); default none")
    Double restToolDiameterMm;

    @Option(
            names = "--report",
            paramLabel = "FILE",
            description = "also write the thesis's technology printout (GOTA.BAS's LPRINT block) to FILE")
    java.nio.file.Path report;

    @Option(
            names = "--slowed",
            paramLabel = "FILE",
            description = "adaptive only: also write the moves whose feed dropped as CSV to FILE, one row a move"
                    + " (layer, line or arc, start, end, length, feed, fraction of --feed)")
    java.nio.file.Path slowed;

    @Option(
            names = "--thesis-name",
            paramLabel = "NAME",
            description = "write the program beside --out as N01NAME.DAD, the thesis's output name (NAME: 1 to 5"
                    + " letters or digits)")
    String thesisName;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return run(json, progress -> {
            PocketSettings settings = new PocketSettings(
                            contour,
                            Pocket.TOOL_DIAMETER.check(toolDiameterMm),
                            Pocket.CUT.check(cutFraction),
                            Pocket.FINISH.check(finishFraction),
                            Pocket.Z_TOP.check(zTopMm),
                            Pocket.Z_BOTTOM.check(zBottomMm),
                            Pocket.MAX_DEPTH.check(maxDepthMm),
                            Pocket.SPINDLE.check(spindleRpm),
                            Pocket.FEED.check(feedMmPerMin),
                            Pocket.FINISH_FEED.check(finishFeedMmPerMin),
                            post,
                            direction,
                            entry,
                            Pocket.ENTRY_ANGLE.check(entryAngleDeg),
                            centreCutting,
                            Optional.empty(),
                            PocketStrategy.DEFAULT)
                    .withStrategy(new PocketStrategy(
                            strategy,
                            Pocket.ANGLE.check(angleDeg),
                            Pocket.STOCK_TO_LEAVE.check(stockToLeaveMm),
                            order,
                            restToolDiameterMm == null
                                    ? 0
                                    : PocketService.restToolRange(toolDiameterMm)
                                            .check(restToolDiameterMm)));
            java.nio.file.Path file = CliSupport.outFile(out);
            String thesisFile = null;
            if (thesisName != null) {
                thesisFile = org.fresa.pocket.compat.PocketReport.thesisFileName(thesisName);
                java.nio.file.Path folder = file.toAbsolutePath().getParent();
                file = CliSupport.outFile(folder.resolve(thesisFile));
            }
            java.util.Optional<java.nio.file.Path> printout = java.util.Optional.ofNullable(report);
            if (printout.isPresent()) {
                org.fresa.io.AtomicFiles.requireWritable(printout.get(), "--report");
            }
            java.util.Optional<java.nio.file.Path> slowedCsv = java.util.Optional.ofNullable(slowed);
            if (slowedCsv.isPresent()) {
                org.fresa.io.AtomicFiles.requireWritable(slowedCsv.get(), "--slowed");
            }
            org.fresa.job.TaskOutcome o = PocketService.run(settings, file, printout, slowedCsv, progress);
            if (thesisFile == null || o.exitStatus() != 0) {
                return o;
            }
            java.util.Map<String, Object> summary = new java.util.LinkedHashMap<>(o.summary());
            summary.put("thesis_name", thesisFile);
            return new org.fresa.job.TaskOutcome(o.exitStatus(), o.problems(), summary, o.files());
        });
    }
}
