package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fresa.job.Module;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa grade OUTLINE --out DIR [grading options] [--json]}. */
@Command(name = "grade", mixinStandardHelpOptions = true, sortOptions = false,
        description = "A sole outline graded over a range of shoe sizes.")
final class GradeCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "OUTLINE", description = "outline (.dxf or Fresa contour file)")
    Path outline;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--base-size", required = true, paramLabel = "N", description = "size of the drawn outline")
    double baseSize;

    @Option(names = "--sizes", required = true, paramLabel = "A-B", description = "range of sizes to grade")
    String sizes;

    @Option(names = "--half-sizes", description = "include half sizes")
    boolean halfSizes;

    @Option(names = "--system", required = true, paramLabel = "SYS", description = "br, paris, uk, us or mondopoint")
    String system;

    @Option(names = "--length-step", paramLabel = "MM", description = "length step per size (default: the system's)")
    Double lengthStepMm;

    @Option(names = "--width-step", paramLabel = "MM", description = "width step per size (default: the system's)")
    Double widthStepMm;

    @Option(names = "--origin", paramLabel = "X,Y", description = "fixed point of the grading (default: heel centre)")
    String origin;

    @Option(names = "--shrinkage", paramLabel = "S", defaultValue = "0", description = "material shrinkage (fraction)")
    double shrinkage;

    @Option(names = "--shrinkage-mode", paramLabel = "MODE", defaultValue = "multiplicative",
            description = "additive (the thesis) or multiplicative (default)")
    String shrinkageMode;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.unavailable(spec.commandLine().getErr(), Module.GRADING);
    }
}
