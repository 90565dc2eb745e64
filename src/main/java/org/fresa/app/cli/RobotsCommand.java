package org.fresa.app.cli;

import java.util.concurrent.Callable;
import org.fresa.job.Module;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa robots}: the built-in robots and their parameters. */
@Command(name = "robots", mixinStandardHelpOptions = true, description = "List the built-in robots and their parameters.")
final class RobotsCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.unavailable(spec.commandLine().getErr(), Module.ROBOT);
    }
}
