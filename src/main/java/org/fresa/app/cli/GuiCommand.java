package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.fresa.ui.FresaApp;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa gui [JOB]}: the desktop application. */
@Command(
        name = "gui",
        mixinStandardHelpOptions = true,
        description = "Open the desktop application, optionally with a saved job.")
final class GuiCommand implements Callable<Integer> {

    @Parameters(index = "0", arity = "0..1", paramLabel = "JOB", description = "a job file to open")
    Path job;

    @Option(
            names = "--exit-when-shown",
            hidden = true,
            description = "print the time from JVM start to a visible window, then exit (start-up check)")
    boolean exitWhenShown;

    @Override
    public Integer call() {
        if (exitWhenShown) {
            if (!FresaApp.hasDisplay()) {
                System.err.println("fresa: no display");
                return CliSupport.EXIT_BAD_INPUT;
            }
            FresaApp.launch(Optional.ofNullable(job), w -> {
                long ms = java.lang.management.ManagementFactory.getRuntimeMXBean()
                        .getUptime();
                System.out.println(
                        "window '" + w.getTitle() + "' with " + w.tabCount() + " tabs shown after " + ms + " ms");
                System.exit(0);
            });
            return FresaCommand.KEEP_RUNNING;
        }
        return open(job);
    }

    static int open(Path job) {
        if (!FresaApp.hasDisplay()) {
            System.err.println("fresa: no display for the desktop application; run a command instead (fresa --help)");
            return CliSupport.EXIT_BAD_INPUT;
        }
        FresaApp.launch(Optional.ofNullable(job));
        return FresaCommand.KEEP_RUNNING;
    }
}
