package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fresa.cutting.CuttingOptions;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.SettingRanges.Cutting;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa cut DRAWING.dxf --out FILE [cutting options] [--post NAME] [--json]}. */
@Command(name = "cut", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Sheet cutting path (plasma, laser, waterjet) from a DXF drawing.")
final class CutCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "DRAWING", description = "DXF drawing (ASCII or binary)")
    Path drawing;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "cutting program to write")
    Path out;

    @Option(names = "--kerf", paramLabel = "W", defaultValue = "2", description = "full kerf width (mm); the path is offset by W/2")
    double kerfMm;

    @Option(names = "--process", paramLabel = "P", defaultValue = "plasma", description = "plasma, laser or waterjet")
    String process;

    @Option(names = "--lead-in", paramLabel = "LEN", defaultValue = "3", description = "lead-in length (mm)")
    double leadInMm;

    @Option(names = "--lead-out", paramLabel = "LEN", defaultValue = "1", description = "lead-out length (mm)")
    double leadOutMm;

    @Option(names = "--lead", paramLabel = "arc|line", defaultValue = "arc", description = "lead shape")
    String lead;

    @Option(names = "--tolerance", paramLabel = "T", description = "widest gap closed between the ends of an outline, in drawing units (default 0.05 mm); each gap closed is listed")
    Double tolerance;

    @Option(names = "--units", paramLabel = "mm|inch|auto", defaultValue = "auto", description = "drawing units; auto reads $INSUNITS")
    String units;

    @Option(names = "--paper-mode", description = "the 2010 paper's rules (largest contour outside, no lead-ins)")
    boolean paperMode;

    @Option(names = "--compensation", paramLabel = "software|controller", defaultValue = "software",
            description = "software: the path is offset by W/2; controller: the drawn contour with G41/G42 (D = W)")
    String compensation;

    @Option(names = "--outer-direction", paramLabel = "cw|ccw|process", defaultValue = "process",
            description = "sense of outer contours; process: the process's default (clockwise)")
    String outerDirection;

    @Option(names = "--hole-direction", paramLabel = "cw|ccw|process", defaultValue = "process",
            description = "sense of holes; process: the opposite of the outer contours")
    String holeDirection;

    @Option(names = "--overcut", paramLabel = "LEN", defaultValue = "0", description = "run past the start of each cut (mm)")
    double overcutMm;

    @Option(names = "--no-avoid-cut-parts", negatable = false,
            description = "rapid moves go straight, even over parts already cut free")
    boolean straightRapids;

    @Option(names = "--post", paramLabel = "NAME", defaultValue = "linuxcnc", description = "post-processor; default ${DEFAULT-VALUE}")
    String post;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.run(spec.commandLine().getOut(), spec.commandLine().getErr(), json, progress -> {
            CuttingSettings s = new CuttingSettings(drawing, Cutting.KERF.check(kerfMm),
                    process, Cutting.LEAD_IN.check(leadInMm), Cutting.LEAD_OUT.check(leadOutMm), lead,
                    tolerance == null ? CuttingOptions.DEFAULT_GAP_MM : Cutting.TOLERANCE.check(tolerance), units, paperMode, post, compensation,
                    outerDirection, holeDirection, Cutting.OVERCUT.check(overcutMm), !straightRapids);
            return CuttingService.run(s, CliSupport.outFile(out), tolerance != null, progress);
        });
    }
}
