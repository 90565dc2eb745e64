package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The top-level command: {@code fresa [COMMAND]}; without a command it opens the desktop application. */
@Command(name = "fresa", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = {"Fresa: CAM for process planners. STEP-NC to robot, pocket milling, sheet cutting, shoe soles.",
                "Without a command, opens the desktop application."},
        subcommands = {GuiCommand.class, RunCommand.class, StepncCommand.class, ToolpathCommand.class,
                RobotCommand.class, PocketCommand.class, CutCommand.class, GradeCommand.class, SoleCommand.class,
                RobotsCommand.class, PostsCommand.class, BenchCommand.class},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:done", "1:the input was read but the job cannot be done as asked (reason on stderr)",
                "2:bad input or usage (file, line and what was expected on stderr)"})
public final class FresaCommand implements Callable<Integer> {

    /** Returned when the desktop application was started and the JVM must stay up. */
    public static final int KEEP_RUNNING = -1;

    @Override
    public Integer call() {
        return GuiCommand.open(null);
    }

    /** Runs the command line and returns the exit status (or {@link #KEEP_RUNNING}). */
    public static int execute(String... args) {
        return execute(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs the command line with the given streams (tests pass their own). */
    public static int execute(PrintWriter out, PrintWriter err, String... args) {
        CommandLine cl = new CommandLine(new FresaCommand());
        cl.setOut(out);
        cl.setErr(err);
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.setParameterExceptionHandler((ex, a) -> {
            err.println("fresa: " + ex.getMessage());
            err.println("Try 'fresa " + commandPath(ex.getCommandLine()) + "--help' for usage.");
            return CliSupport.EXIT_BAD_INPUT;
        });
        cl.setExecutionExceptionHandler((ex, c, p) -> CliSupport.internalError(err, ex));
        return cl.execute(args);
    }

    private static String commandPath(CommandLine cl) {
        String name = cl.getCommandName();
        return "fresa".equals(name) ? "" : name + " ";
    }
}
