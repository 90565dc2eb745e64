package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec2;
import org.fresa.grading.ArcMode;
import org.fresa.grading.Coordination;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeSystem;
import org.fresa.job.GradingService;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges.Grading;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa grade OUTLINE --out DIR [grading options] [--json]}. */
@Command(name = "grade", sortOptions = false, description = "A sole outline graded over a range of shoe sizes.")
final class GradeCommand extends CliCommand {

    @Parameters(index = "0", paramLabel = "OUTLINE", description = "outline (.dxf or Fresa contour file)")
    Path outline;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--base-size", required = true, paramLabel = "N", description = "size of the drawn outline")
    double baseSize;

    @Option(names = "--sizes", required = true, paramLabel = "A-B", description = "range of sizes to grade")
    String sizes;

    @Option(names = "--half-sizes", description = "include half sizes")
    boolean halfSizes = GradingSettings.DEFAULTS.halfSizes();

    @Option(names = "--system", required = true, paramLabel = "SYS", description = "br, paris, uk, us or mondopoint")
    SizeSystem system;

    @Option(names = "--length-step", paramLabel = "MM", description = "length step per size (default: the system's)")
    Double lengthStepMm;

    @Option(names = "--width-step", paramLabel = "MM", description = "width step per size (default: the system's)")
    Double widthStepMm;

    @Option(names = "--origin", paramLabel = "X,Y", description = "fixed point of the grading (default: heel centre)")
    String origin;

    @Option(names = "--shrinkage", paramLabel = "S", description = "material shrinkage (fraction)")
    double shrinkage = GradingSettings.DEFAULTS.shrinkage();

    @Option(
            names = "--shrinkage-mode",
            paramLabel = "MODE",
            description = "additive (the thesis) or multiplicative (default)")
    ShrinkageMode shrinkageMode = GradingSettings.DEFAULTS.shrinkageMode();

    @Option(
            names = "--arcs",
            paramLabel = "MODE",
            defaultValue = "biarc",
            description = "graded arcs as biarc (within 0.005 mm of the exact ellipse, default) or three-point "
                    + "(the thesis's circle through the graded start, middle and end)")
    String arcs;

    @Option(
            names = "--length-axis",
            paramLabel = "DEG",
            description = "direction of the length axis, heel to toe, in degrees from +x (default: the outline's "
                    + "longer extent)")
    Double lengthAxisDeg;

    @Option(
            names = "--coordination",
            paramLabel = "MM",
            description = "one heel per group of sizes: points up to MM from the origin along the length axis "
                    + "grade as the group's middle size (the thesis's coordination; implies three-point arcs)")
    Double coordinationMm;

    @Option(
            names = "--heel-group",
            paramLabel = "N",
            description = "sizes per heel with --coordination (default ${DEFAULT-VALUE})")
    int heelGroup = org.fresa.job.JobSettings.HeelCoordination.DEFAULT_GROUP_SIZE;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return run(json, progress -> {
            GradingSettings s = new GradingSettings(
                    outline.toAbsolutePath(),
                    Grading.BASE_SIZE.check(baseSize),
                    sizes,
                    halfSizes,
                    system,
                    optional(Grading.LENGTH_STEP, lengthStepMm),
                    optional(Grading.WIDTH_STEP, widthStepMm),
                    origin(),
                    Grading.SHRINKAGE.check(shrinkage),
                    shrinkageMode);
            OptionalDouble axis = optional(Grading.LENGTH_AXIS, lengthAxisDeg);
            Grading.HEEL_GROUP.check(heelGroup);
            GradingService.Options o;
            try {
                o = new GradingService.Options(
                        ArcMode.ofId(arcs),
                        axis,
                        coordinationMm == null
                                ? Optional.empty()
                                : Optional.of(new Coordination(Grading.COORDINATION.check(coordinationMm), heelGroup)));
            } catch (IllegalArgumentException e) {
                throw new CamInputException("options", e.getMessage());
            }
            return CliSupport.intoFolder(out, folder -> GradingService.run(s, o, folder, progress));
        });
    }

    private static OptionalDouble optional(SettingRange range, Double v) throws CamInputException {
        return v == null ? OptionalDouble.empty() : OptionalDouble.of(range.check(v));
    }

    private Optional<Vec2> origin() throws CamInputException {
        if (origin == null) {
            return Optional.empty();
        }
        String[] p = origin.split(",");
        double x;
        double y;
        try {
            if (p.length != 2) {
                throw new NumberFormatException(origin);
            }
            x = Double.parseDouble(p[0].trim());
            y = Double.parseDouble(p[1].trim());
        } catch (NumberFormatException e) {
            throw new CamInputException("--origin", "expected X,Y in mm, found '" + origin + "'");
        }
        return Optional.of(Vec2.of(Grading.ORIGIN_X.check(x), Grading.ORIGIN_Y.check(y)));
    }
}
