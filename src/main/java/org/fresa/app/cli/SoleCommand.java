package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fresa sole JOB --out DIR}. */
@Command(
        name = "sole",
        mixinStandardHelpOptions = true,
        description = "Sole mould programs: cavity, tread figures, graded sizes, both feet.")
final class SoleCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "JOB", description = "sole job file")
    Path job;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        java.io.PrintWriter o = spec.commandLine().getOut();
        return CliSupport.run(o, spec.commandLine().getErr(), json, progress -> {
            org.fresa.io.OutputFolder.of(out, "--out");
            org.fresa.job.Job j = org.fresa.job.JobXml.read(job);
            if (j.sole().isEmpty()) {
                throw new org.fresa.model.CamInputException(job.toString(), "the job has no <sole> settings");
            }
            return CliSupport.intoFolder(out, folder -> org.fresa.job.SoleService.run(j, folder, progress));
        });
    }
}
