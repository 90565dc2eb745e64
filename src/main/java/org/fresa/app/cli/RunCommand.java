package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.fresa.io.OutputFolder;
import org.fresa.job.Job;
import org.fresa.job.JobRunner;
import org.fresa.job.JobXml;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa run JOB --out DIR}: a saved job, headless. */
@Command(name = "run", description = "Run a saved job file (the same file the desktop application saves) headless.")
final class RunCommand extends SummaryCommand {

    @Parameters(index = "0", paramLabel = "JOB", description = "job file (.xml, schemas/job.xsd)")
    Path job;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder (created if needed)")
    Path out;

    @Override
    TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException {
        OutputFolder folder = OutputFolder.of(out, "--out");
        Job j = JobXml.read(job);
        return JobRunner.run(j, folder, progress);
    }
}
