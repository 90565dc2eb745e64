package org.fresa.app.cli;

import java.nio.file.Path;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.job.ToolpathService;
import org.fresa.post.MillingPost;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa toolpath FILE --out DIR [--post NAME]}. */
@Command(
        name = "toolpath",
        mixinStandardHelpOptions = true,
        description = "Toolpaths of every workingstep of a STEP-NC file, in workplan order, with G-code.")
final class ToolpathCommand extends CliCommand {

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file")
    Path file;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(
            names = "--post",
            paramLabel = "NAME",
            description = "post-processor (fresa posts lists them); default ${DEFAULT-VALUE}")
    MillingPost post = StepNcSettings.DEFAULTS.post();

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Mixin
    StepNcPlanningOptions planning = new StepNcPlanningOptions();

    @Override
    public Integer call() {
        return run(json, progress -> {
            PlanningChoices choices = planning.choices();
            return CliSupport.intoFolder(out, folder -> ToolpathService.run(file, post, choices, folder, progress));
        });
    }
}
