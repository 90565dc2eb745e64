package org.fresa.job;

import java.io.IOException;
import org.fresa.io.FolderLock;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;

/**
 * Executes a job's task headless: the service behind {@code fresa run} and the GUI's Run action.
 * Each module's command on the command line calls the same module service with a job built from
 * its options, so a job saved in the GUI and the equivalent command give the same files.
 */
public final class JobRunner {
    private JobRunner() {}

    /**
     * Runs the job's tasks, writing their files into the folder, which it holds for the run
     * ({@link FolderLock}). A job that runs one task writes into the folder itself; one that runs
     * several writes each task's files into a subfolder named after the task ({@code robot/},
     * {@code grade/}), so that files of the same name (summary.json, toolpath.csv) stay apart.
     * The outcome is the worst of the tasks', with every problem and file.
     *
     * @throws CamInputException when an input file is bad (nothing is written then)
     * @throws FolderLock.FolderBusyException when another run writes into the folder
     * @throws IOException when an output cannot be written
     */
    @SuppressWarnings("try") // the lock is held for the run, never read
    public static TaskOutcome run(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        try (FolderLock lock = FolderLock.acquire(out)) {
            if (job.runs().size() == 1) {
                return runTask(job, job.task(), out, progress);
            }
            int status = 0;
            java.util.List<String> problems = new java.util.ArrayList<>();
            java.util.Map<String, Object> summary = new java.util.LinkedHashMap<>();
            java.util.List<java.nio.file.Path> files = new java.util.ArrayList<>();
            for (JobTask t : job.runs()) {
                progress.checkCancelled();
                progress.progress(-1, t.id());
                TaskOutcome o = runTask(job, t, new OutputFolder(out.dir().resolve(t.id())), progress);
                status = Math.max(status, o.exitStatus());
                o.problems().forEach(p -> problems.add(t.id() + ": " + p));
                summary.put(t.id(), o.summary());
                files.addAll(o.files());
            }
            return new TaskOutcome(status, problems, summary, files);
        }
    }

    private static TaskOutcome runTask(Job job, JobTask task, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        // the module services read the task from the job: give each the job as if it ran alone
        Job one = job.withTask(task);
        return runOne(one, out, progress);
    }

    private static TaskOutcome runOne(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        switch (job.task()) {
            case STEPNC:
                return StepNcService.run(job, out, progress);
            case TOOLPATH:
                return ToolpathService.run(job, out, progress);
            case ROBOT:
                return RobotService.run(job, out, progress);
            case POCKET: {
                JobSettings.PocketSettings s = require(job.pocket(), "pocket", job);
                out.create();
                // adaptive clearing's slowed moves are a result to review as much as its program
                return PocketService.run(
                        s,
                        out.resolve("pocket." + s.post().fileExtension()),
                        java.util.Optional.empty(),
                        s.strategy().kind() == org.fresa.pocket.PocketStrategy.Kind.ADAPTIVE
                                ? java.util.Optional.of(out.resolve("slowed.csv"))
                                : java.util.Optional.empty(),
                        progress);
            }
            case CUT:
                return CuttingService.run(require(job.cutting(), "cutting", job), out, progress);
            case GRADE:
                return GradingService.run(require(job.grading(), "grading", job), out, progress);
            case SOLE:
                return SoleService.run(job, out, progress);
            default:
                throw new IllegalStateException("unknown task " + job.task());
        }
    }

    /** The settings section the task needs, or a CamInputException naming what is missing. */
    static <T> T require(java.util.Optional<T> section, String element, Job job) throws CamInputException {
        return section.orElseThrow(() -> new CamInputException(
                job.name(), "the job's task is " + job.task().id() + " but it has no <" + element + "> settings"));
    }
}
