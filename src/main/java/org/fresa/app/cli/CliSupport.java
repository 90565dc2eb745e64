package org.fresa.app.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.CancellationException;
import org.fresa.io.AtomicFiles;
import org.fresa.io.FolderLock;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;

/**
 * The rules every command shares (spec/cli.md): exit statuses, one message on stderr for bad
 * input, {@code --json} summaries on stdout, progress on a terminal only. Commands implement
 * {@link Task} and hand it to {@link #run}.
 */
public final class CliSupport {

    public static final int EXIT_OK = 0;
    public static final int EXIT_NOT_DOABLE = 1;
    public static final int EXIT_BAD_INPUT = 2;

    private CliSupport() {}

    /** A command's work: reads its input, does the job, writes its files. */
    @FunctionalInterface
    public interface Task {
        TaskOutcome run(ProgressMonitor progress) throws CamInputException, java.io.IOException;
    }

    /**
     * Runs a task with the shared rules and returns the exit status.
     *
     * @param json print the outcome's summary as one JSON object on stdout instead of prose
     */
    public static int run(PrintWriter out, PrintWriter err, boolean json, Task task) {
        ProgressMonitor progress = TerminalProgress.forStderr(err);
        try {
            TaskOutcome outcome = task.run(progress);
            TerminalProgress.clear(progress);
            // a problem met at many places is said once, with its count
            java.util.Map<String, Integer> said = new java.util.LinkedHashMap<>();
            for (String p : outcome.problems()) {
                said.merge(p, 1, Integer::sum);
            }
            said.forEach((p, n) -> err.println("fresa: " + p + (n > 1 ? " (" + n + " times)" : "")));
            if (json) {
                out.println(Json.write(outcome.summary()));
            } else {
                for (Path f : outcome.files()) {
                    out.println("wrote " + f);
                }
            }
            out.flush();
            return outcome.exitStatus();
        } catch (CamInputException e) {
            TerminalProgress.clear(progress);
            err.println("fresa: " + e.getMessage());
            return EXIT_BAD_INPUT;
        } catch (java.nio.file.NoSuchFileException e) {
            TerminalProgress.clear(progress);
            err.println("fresa: " + e.getFile() + ": no such file");
            return EXIT_BAD_INPUT;
        } catch (java.io.IOException e) {
            TerminalProgress.clear(progress);
            err.println("fresa: " + e.getMessage());
            return EXIT_NOT_DOABLE;
        } catch (CancellationException e) {
            TerminalProgress.clear(progress);
            err.println("fresa: cancelled");
            return EXIT_NOT_DOABLE;
        } catch (OutOfMemoryError e) {
            // the readers refuse files larger than their share of the heap; this is what is left
            TerminalProgress.clear(progress);
            err.println("fresa: not enough memory for this input (Java heap of "
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MB): give Java more memory, e.g. "
                    + "FRESA_JAVA_OPTS=-Xmx4g, or split the input");
            return EXIT_NOT_DOABLE;
        }
    }

    /** A command's work that writes into an output folder. */
    @FunctionalInterface
    public interface FolderTask {
        TaskOutcome run(OutputFolder folder) throws CamInputException, java.io.IOException;
    }

    /**
     * Runs a task into the {@code --out} folder, which it holds for the run: a path that is not a
     * folder is refused, and so is a folder another run writes into ({@link FolderLock}).
     */
    @SuppressWarnings("try") // the lock is held for the task, never read
    static TaskOutcome intoFolder(Path out, FolderTask task) throws CamInputException, java.io.IOException {
        OutputFolder folder = OutputFolder.of(out, "--out");
        try (FolderLock lock = FolderLock.acquire(folder)) {
            return task.run(folder);
        }
    }

    /** The {@code --out} file of a command that writes one file: a regular file or nothing yet. */
    static Path outFile(Path out) throws CamInputException {
        return AtomicFiles.requireWritable(out, "--out");
    }

    /** A bug, not bad input: a short message for the user, the trace in the log file. */
    static int internalError(PrintWriter err, Exception ex) {
        Path log = org.fresa.io.ErrorLog.record(ex);
        err.println("fresa: internal error: " + ex + (log != null ? " (details in " + log + ")" : ""));
        return EXIT_NOT_DOABLE;
    }
}
