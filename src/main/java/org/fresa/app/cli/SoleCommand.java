package org.fresa.app.cli;

import java.nio.file.Path;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa sole JOB --out DIR}. */
@Command(
        name = "sole",
        mixinStandardHelpOptions = true,
        description = "Sole mould programs: cavity, tread figures, graded sizes, both feet.")
final class SoleCommand extends CliCommand {

    @Parameters(index = "0", paramLabel = "JOB", description = "sole job file")
    Path job;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    @Override
    public Integer call() {
        return run(json, progress -> {
            org.fresa.io.OutputFolder.of(out, "--out");
            org.fresa.job.Job j = org.fresa.job.JobXml.read(job);
            if (j.sole().isEmpty()) {
                throw new org.fresa.model.CamInputException(job.toString(), "the job has no <sole> settings");
            }
            return CliSupport.intoFolder(out, folder -> org.fresa.job.SoleService.run(j, folder, progress));
        });
    }
}
