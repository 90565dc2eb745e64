package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.job.ToolpathService;
import org.fresa.post.MillingPost;
import org.fresa.setting.SettingRanges;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fresa toolpath FILE --out DIR [--post NAME]}. */
@Command(
        name = "toolpath",
        mixinStandardHelpOptions = true,
        description = "Toolpaths of every workingstep of a STEP-NC file, in workplan order, with G-code.")
final class ToolpathCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

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

    @Option(
            names = "--trust-cutting-speed",
            description = "plan a workingstep whose spindle and cutting speed disagree tenfold from the cutting speed"
                    + " (else it is refused)")
    boolean trustCuttingSpeed = StepNcSettings.DEFAULTS.trustCuttingSpeed();

    @Option(
            names = "--breakthrough",
            paramLabel = "MM",
            description = "how far a through hole's drill (full diameter) or milling cutter passes the exit;"
                    + " default ${DEFAULT-VALUE} mm")
    double breakthroughMm = StepNcSettings.DEFAULTS.breakthroughMm();

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
        java.io.PrintWriter o = spec.commandLine().getOut();
        return CliSupport.run(o, spec.commandLine().getErr(), json, progress -> {
            PlanningChoices choices = new PlanningChoices(
                    trustCuttingSpeed,
                    SettingRanges.StepNc.BREAKTHROUGH.check(breakthroughMm),
                    entries.rule(),
                    SettingRanges.StepNc.paths("--paths", paths));
            return CliSupport.intoFolder(out, folder -> ToolpathService.run(file, post, choices, folder, progress));
        });
    }
}
