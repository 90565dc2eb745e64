package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A command of the {@code fresa} command line: it writes to the streams picocli was given (the
 * shell's, or a test's) and runs its work with the rules every command shares ({@link CliSupport#run}).
 * Every command answers {@code --help} and {@code --version}: picocli gives a command the attributes
 * of its superclass's {@code @Command}.
 */
@Command(mixinStandardHelpOptions = true)
abstract class CliCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    /** The command's standard output, where prose and {@code --json} summaries go. */
    final PrintWriter out() {
        return spec.commandLine().getOut();
    }

    /**
     * Runs the command's work with the shared rules and returns the exit status.
     *
     * @param json print the outcome's summary as one JSON object on stdout instead of prose
     */
    final int run(boolean json, CliSupport.Task task) {
        return CliSupport.run(out(), spec.commandLine().getErr(), json, task);
    }
}
