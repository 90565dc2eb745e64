package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The top-level command: {@code fresa [COMMAND]}; without a command it opens the desktop application. */
@Command(
        name = "fresa",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        sortOptions = false,
        description = {
            "Fresa: CAM for process planners. STEP-NC to robot, pocket milling, sheet cutting, shoe soles.",
            "Without a command, opens the desktop application."
        },
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:done",
            "1:the input was read but the job cannot be done as asked (reason on stderr)",
            "2:bad input or usage (file, line and what was expected on stderr)"
        })
public final class FresaCommand implements Callable<Integer> {

    /**
     * The commands, in the order the help lists them. They are added by {@link #execute}, not
     * declared in the annotation: picocli builds the model of every declared command at start,
     * which in a fresh JVM cost more than a tenth of a second, so a command line that names one
     * command gets only that one (help, version and unknown names get them all).
     */
    static final List<Class<?>> COMMANDS = List.of(
            GuiCommand.class,
            RunCommand.class,
            StepncCommand.class,
            ToolpathCommand.class,
            RobotCommand.class,
            PocketCommand.class,
            CutCommand.class,
            GradeCommand.class,
            SoleCommand.class,
            IkCommand.class,
            RobotsCommand.class,
            PostsCommand.class,
            BenchCommand.class);

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
        Class<?> named = null;
        for (Class<?> c : COMMANDS) {
            if (args.length > 0 && c.getAnnotation(Command.class).name().equals(args[0])) {
                named = c;
            }
        }
        for (Class<?> c : COMMANDS) {
            if (named == null || c == named) {
                cl.addSubcommand(c);
            }
        }
        SettingConverters.register(cl);
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

    /** The command line with every command, as the help lists them; tests walk its options. */
    public static CommandLine withAllCommands() {
        CommandLine cl = new CommandLine(new FresaCommand());
        COMMANDS.forEach(cl::addSubcommand);
        return SettingConverters.register(cl);
    }

    private static String commandPath(CommandLine cl) {
        String name = cl.getCommandName();
        return "fresa".equals(name) ? "" : name + " ";
    }
}
