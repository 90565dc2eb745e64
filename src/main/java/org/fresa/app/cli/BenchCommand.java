package org.fresa.app.cli;

import org.fresa.bench.Benchmarks;
import org.fresa.io.Json;
import org.fresa.job.TaskOutcome;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code fresa bench [--json]}: short versions of the performance benchmarks. */
@Command(name = "bench", description = "Run short benchmarks and print the figures.")
final class BenchCommand extends CliCommand {

    @Option(names = "--json", description = "print the figures as one JSON object")
    boolean json;

    @Override
    public Integer call() {
        return run(false, progress -> {
            java.nio.file.Path jar = null;
            try {
                java.nio.file.Path self = java.nio.file.Path.of(BenchCommand.class
                        .getProtectionDomain()
                        .getCodeSource()
                        .getLocation()
                        .toURI());
                jar = self.toString().endsWith(".jar") ? self : null;
            } catch (java.net.URISyntaxException | SecurityException e) {
                jar = null;
            }
            java.util.Map<String, Object> figures = Benchmarks.run(jar, progress);
            if (json) {
                out().println(Json.write(figures));
            } else {
                out().print(Benchmarks.table(figures));
            }
            return new TaskOutcome(0, java.util.List.of(), java.util.Map.of(), java.util.List.of());
        });
    }
}
