package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.fresa.job.SettingRanges;
import org.fresa.job.ToolpathService;
import org.fresa.toolpath.PlanningChoices;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa toolpath FILE --out DIR [--post NAME]}. */
@Command(name = "toolpath", mixinStandardHelpOptions = true,
        description = "Toolpaths of every workingstep of a STEP-NC file, in workplan order, with G-code.")
final class ToolpathCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file")
    Path file;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--post", paramLabel = "NAME", defaultValue = "linuxcnc",
            description = "post-processor (fresa posts lists them); default ${DEFAULT-VALUE}")
    String post;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Option(names = "--trust-cutting-speed",
            description = "plan a workingstep whose spindle and cutting speed disagree tenfold from the cutting speed"
                    + " (else it is refused)")
    boolean trustCuttingSpeed;

    @Option(names = "--breakthrough", paramLabel = "MM", defaultValue = "1",
            description = "how far a through hole's drill (full diameter) or milling cutter passes the exit;"
                    + " default ${DEFAULT-VALUE} mm")
    double breakthroughMm;

    @Mixin
    StepNcEntryOptions entries = new StepNcEntryOptions();

    @Override
    public Integer call() {
        java.io.PrintWriter o = spec.commandLine().getOut();
        return CliSupport.run(o, spec.commandLine().getErr(), json, progress -> {
            PlanningChoices choices = new PlanningChoices(trustCuttingSpeed,
                    SettingRanges.StepNc.BREAKTHROUGH.check(breakthroughMm), entries.rule());
            return CliSupport.intoFolder(out, folder -> ToolpathService.run(file, post, choices, folder, progress));
        });
    }
}
