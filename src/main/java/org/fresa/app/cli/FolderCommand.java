package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import picocli.CommandLine.Option;

/**
 * A command that writes its files into an output folder ({@code --out DIR}, held for the run by
 * {@link CliSupport#intoFolder}) and says what it did as prose or, with {@code --json}, as one
 * JSON summary on stdout.
 */
abstract class FolderCommand extends CliCommand {

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    /** The command's work: reads its input, checks its options and writes into {@link #out}. */
    abstract TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException;

    @Override
    public final Integer call() {
        return run(json, this::work);
    }
}
