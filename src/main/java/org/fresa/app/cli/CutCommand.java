package org.fresa.app.cli;

import java.nio.file.Path;
import org.fresa.cutting.CutProcess;
import org.fresa.cutting.CutSense;
import org.fresa.cutting.KerfCompensation;
import org.fresa.cutting.LeadShape;
import org.fresa.dxf.DrawingUnits;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.post.CuttingPost;
import org.fresa.setting.SettingRanges.Cutting;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa cut DRAWING.dxf --out FILE [cutting options] [--post NAME] [--json]}. */
@Command(
        name = "cut",
        sortOptions = false,
        description = "Sheet cutting path (plasma, laser, waterjet) from a DXF drawing.")
final class CutCommand extends CliCommand {

    private static final CuttingSettings DEFAULTS = CuttingSettings.DEFAULTS;

    @Parameters(index = "0", paramLabel = "DRAWING", description = "DXF drawing (ASCII or binary)")
    Path drawing;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "cutting program to write")
    Path out;

    @Option(names = "--kerf", paramLabel = "W", description = "full kerf width (mm); the path is offset by W/2")
    double kerfMm = DEFAULTS.kerfMm();

    @Option(names = "--process", paramLabel = "P", description = "plasma, laser or waterjet")
    CutProcess process = DEFAULTS.process();

    @Option(names = "--lead-in", paramLabel = "LEN", description = "lead-in length (mm)")
    double leadInMm = DEFAULTS.leadInMm();

    @Option(names = "--lead-out", paramLabel = "LEN", description = "lead-out length (mm)")
    double leadOutMm = DEFAULTS.leadOutMm();

    @Option(names = "--lead", paramLabel = "arc|line", description = "lead shape")
    LeadShape lead = DEFAULTS.lead();

    @Option(
            names = "--tolerance",
            paramLabel = "T",
            description =
                    "widest gap closed between the ends of an outline, in drawing units (default 0.05 mm); each gap closed is listed")
    Double tolerance;

    @Option(names = "--units", paramLabel = "mm|inch|auto", description = "drawing units; auto reads $INSUNITS")
    DrawingUnits units = DEFAULTS.units();

    @Option(names = "--paper-mode", description = "the 2010 paper's rules (largest contour outside, no lead-ins)")
    boolean paperMode;

    @Option(
            names = "--compensation",
            paramLabel = "software|controller",
            description = "software: the path is offset by W/2; controller: the drawn contour with G41/G42 (D = W)")
    KerfCompensation compensation = DEFAULTS.compensation();

    @Option(
            names = "--outer-direction",
            paramLabel = "cw|ccw|process",
            description = "sense of outer contours; process: the process's default (clockwise)")
    CutSense outerDirection = DEFAULTS.outerDirection();

    @Option(
            names = "--hole-direction",
            paramLabel = "cw|ccw|process",
            description = "sense of holes; process: the opposite of the outer contours")
    CutSense holeDirection = DEFAULTS.holeDirection();

    @Option(names = "--overcut", paramLabel = "LEN", description = "run past the start of each cut (mm)")
    double overcutMm = DEFAULTS.overcutMm();

    @Option(
            names = "--no-avoid-cut-parts",
            negatable = false,
            description = "rapid moves go straight, even over parts already cut free")
    boolean straightRapids;

    @Option(names = "--post", paramLabel = "NAME", description = "post-processor; default ${DEFAULT-VALUE}")
    CuttingPost post = DEFAULTS.post();

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return run(json, progress -> {
            CuttingSettings s = new CuttingSettings(
                    drawing,
                    Cutting.KERF.check(kerfMm),
                    process,
                    Cutting.LEAD_IN.check(leadInMm),
                    Cutting.LEAD_OUT.check(leadOutMm),
                    lead,
                    tolerance == null ? DEFAULTS.toleranceMm() : Cutting.TOLERANCE.check(tolerance),
                    units,
                    paperMode,
                    post,
                    compensation,
                    outerDirection,
                    holeDirection,
                    Cutting.OVERCUT.check(overcutMm),
                    !straightRapids);
            return CuttingService.run(s, CliSupport.outFile(out), tolerance != null, progress);
        });
    }
}
