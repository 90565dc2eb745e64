package org.fresa.app.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * A command that writes its files into an output folder ({@code --out DIR}, held for the run by
 * {@link CliSupport#intoFolder}) and says what it did as prose or, with {@code --json}, as one
 * JSON summary on stdout.
 */
abstract class FolderCommand extends SummaryCommand {

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "output folder")
    Path out;
}
