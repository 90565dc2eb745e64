package org.fresa.app.cli;

import java.util.concurrent.Callable;
import org.fresa.job.Module;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa bench [--json]}: short versions of the performance benchmarks (issue 11). */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Run short benchmarks and print the figures.")
final class BenchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--json", description = "print the figures as one JSON object")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.unavailable(spec.commandLine().getErr(), Module.BENCH);
    }
}
