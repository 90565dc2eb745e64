package org.fresa.app.cli;

import java.io.IOException;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import picocli.CommandLine.Option;

/**
 * A command whose work ends in an outcome: the files it wrote as prose or, with {@code --json}, the
 * outcome's summary as one JSON object on stdout. The commands whose help lists their options in
 * the order a reader needs them ({@code sortOptions = false}) declare {@code --json} themselves, after
 * their own options, since picocli lists a superclass's options first.
 */
abstract class SummaryCommand extends CliCommand {

    @Option(names = "--json", description = "print a JSON summary on stdout")
    boolean json;

    /** The command's work: reads its input, checks its options and writes its files. */
    abstract TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException;

    @Override
    public final Integer call() {
        return run(json, this::work);
    }
}
