package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.PocketService;
import org.fresa.job.SettingRanges.Pocket;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa pocket CONTOUR --out FILE [technology options] [--post NAME] [--direction D] [--json]}. */
@Command(name = "pocket", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Pocket milling of one closed contour of lines and arcs, from the inside out.")
final class PocketCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CONTOUR", description = ".dad (73-column records), .dxf or Fresa contour file")
    Path contour;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "NC program to write")
    Path out;

    @Option(names = "--tool-diameter", required = true, paramLabel = "D", description = "cutter diameter (mm)")
    double toolDiameterMm;

    @Option(names = "--cut", paramLabel = "P", defaultValue = "0.6", description = "stepover as a fraction of the diameter")
    double cutFraction;

    @Option(names = "--finish", paramLabel = "F", defaultValue = "0.15", description = "finish allowance as a fraction of the diameter")
    double finishFraction;

    @Option(names = "--z-top", paramLabel = "Z", defaultValue = "0", description = "top of the pocket (mm)")
    double zTopMm;

    @Option(names = "--z-bottom", paramLabel = "Z", defaultValue = "-5", description = "floor of the pocket (mm)")
    double zBottomMm;

    @Option(names = "--max-depth", paramLabel = "DZ", defaultValue = "2", description = "largest depth per pass (mm)")
    double maxDepthMm;

    @Option(names = "--rpm", paramLabel = "S", defaultValue = "3000", description = "spindle speed (rpm)")
    double spindleRpm;

    @Option(names = "--feed", paramLabel = "F", defaultValue = "300", description = "roughing feed (mm/min)")
    double feedMmPerMin;

    @Option(names = "--finish-feed", paramLabel = "F", defaultValue = "100", description = "finishing feed (mm/min)")
    double finishFeedMmPerMin;

    @Option(names = "--post", paramLabel = "NAME", defaultValue = "linuxcnc",
            description = "7m, 7m-compat, iso, linuxcnc, fanuc, 840d; default ${DEFAULT-VALUE}")
    String post;

    @Option(names = "--direction", paramLabel = "climb|conventional", defaultValue = "climb",
            description = "milling direction on every post but 7m-compat (which keeps the thesis's conventional"
                    + " passes); default ${DEFAULT-VALUE}")
    String direction;

    @Option(names = "--entry", paramLabel = "auto|helix|ramp|plunge", defaultValue = "auto",
            description = "how the tool enters the material: a helix where it has room, else a zig-zag ramp (auto),"
                    + " helix, ramp, or plunge (centre-cutting tools only); 7m-compat keeps the thesis's plunge;"
                    + " default ${DEFAULT-VALUE}")
    String entry;

    @Option(names = "--entry-angle", paramLabel = "DEG", defaultValue = "3",
            description = "steepest descent of a helix or ramp entry (deg, 0.5 to 90); default ${DEFAULT-VALUE}")
    double entryAngleDeg;

    @Option(names = "--centre-cutting", description = "the cutter cuts at its centre (may plunge)")
    boolean centreCutting;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.run(spec.commandLine().getOut(), spec.commandLine().getErr(), json, progress -> {
            PocketSettings settings = new PocketSettings(contour,
                    Pocket.TOOL_DIAMETER.check(toolDiameterMm), Pocket.CUT.check(cutFraction),
                    Pocket.FINISH.check(finishFraction), Pocket.Z_TOP.check(zTopMm), Pocket.Z_BOTTOM.check(zBottomMm),
                    Pocket.MAX_DEPTH.check(maxDepthMm), Pocket.SPINDLE.check(spindleRpm), Pocket.FEED.check(feedMmPerMin),
                    Pocket.FINISH_FEED.check(finishFeedMmPerMin), post, direction, entry,
                    Pocket.ENTRY_ANGLE.check(entryAngleDeg), centreCutting);
            return PocketService.run(settings, CliSupport.outFile(out), progress);
        });
    }
}
