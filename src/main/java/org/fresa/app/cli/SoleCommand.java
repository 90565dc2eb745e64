package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code fresa sole JOB --out DIR}. */
@Command(name = "sole", description = "Sole mould programs: cavity, tread figures, graded sizes, both feet.")
final class SoleCommand extends FolderCommand {

    @Parameters(index = "0", paramLabel = "JOB", description = "sole job file")
    Path job;

    @Override
    TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException {
        org.fresa.io.OutputFolder.of(out, "--out");
        org.fresa.job.Job j = org.fresa.job.JobXml.read(job);
        if (j.sole().isEmpty()) {
            throw new org.fresa.model.CamInputException(job.toString(), "the job has no <sole> settings");
        }
        return CliSupport.intoFolder(out, folder -> org.fresa.job.SoleService.run(j, folder, progress));
    }
}
