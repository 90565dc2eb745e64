package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.job.ToolpathService;
import org.fresa.model.CamInputException;
import org.fresa.post.MillingPost;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa toolpath FILE --out DIR [--post NAME]}. */
@Command(
        name = "toolpath",
        description = "Toolpaths of every workingstep of a STEP-NC file, in workplan order, with G-code.")
final class ToolpathCommand extends FolderCommand {

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file")
    Path file;

    @Option(
            names = "--post",
            paramLabel = "NAME",
            description = "post-processor (fresa posts lists them); default ${DEFAULT-VALUE}")
    MillingPost post = StepNcSettings.DEFAULTS.post();

    @Mixin
    StepNcPlanningOptions planning = new StepNcPlanningOptions();

    @Override
    TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException {
        PlanningChoices choices = planning.choices();
        return CliSupport.intoFolder(out, folder -> ToolpathService.run(file, post, choices, folder, progress));
    }
}
