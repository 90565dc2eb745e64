package org.fresa.job;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobSettings.OutputSettings;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobSettings.RobotSettings;
import org.fresa.job.JobSettings.SoleSettings;
import org.fresa.job.JobSettings.StepNcSettings;

/**
 * Everything a planner sets up, in one immutable value: the settings of every module the
 * planner has set up and which of them {@code fresa run} (and the GUI's Job > Run) executes.
 * The GUI edits a job by replacing it with modified copies ({@code withPocket(...)});
 * {@code fresa run} executes the same value read from a file.
 *
 * <p>A module's settings are empty until the planner has chosen its input file.
 *
 * @param runs the tasks a run executes: at least one, each once, in {@link JobTask} order
 */
public record Job(
        String name,
        List<JobTask> runs,
        Optional<StepNcSettings> stepnc,
        Optional<RobotSettings> robot,
        Optional<PocketSettings> pocket,
        Optional<CuttingSettings> cutting,
        Optional<GradingSettings> grading,
        Optional<SoleSettings> sole,
        OutputSettings outputs) {

    public Job {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(runs, "runs");
        if (runs.isEmpty()) {
            throw new IllegalArgumentException("a job runs at least one task");
        }
        runs = List.copyOf(java.util.EnumSet.copyOf(runs));
        Objects.requireNonNull(stepnc, "stepnc");
        Objects.requireNonNull(robot, "robot");
        Objects.requireNonNull(pocket, "pocket");
        Objects.requireNonNull(cutting, "cutting");
        Objects.requireNonNull(grading, "grading");
        Objects.requireNonNull(sole, "sole");
        Objects.requireNonNull(outputs, "outputs");
    }

    /** A new, empty job that runs the task. */
    public static Job empty(JobTask task) {
        return new Job(
                "untitled",
                List.of(task),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                OutputSettings.DEFAULT);
    }

    public Job withName(String n) {
        return new Job(n, runs, stepnc, robot, pocket, cutting, grading, sole, outputs);
    }

    /** The first task the job runs (the one a job file's {@code task} attribute names). */
    public JobTask task() {
        return runs.get(0);
    }

    /** The same job running this task only. */
    public Job withTask(JobTask t) {
        return withRuns(List.of(t));
    }

    /** The same job running these tasks (in {@link JobTask} order, whatever order they come in). */
    public Job withRuns(java.util.Collection<JobTask> r) {
        return new Job(name, List.copyOf(r), stepnc, robot, pocket, cutting, grading, sole, outputs);
    }

    public Job withStepnc(StepNcSettings s) {
        return new Job(name, runs, Optional.of(s), robot, pocket, cutting, grading, sole, outputs);
    }

    public Job withRobot(RobotSettings s) {
        return new Job(name, runs, stepnc, Optional.of(s), pocket, cutting, grading, sole, outputs);
    }

    public Job withPocket(PocketSettings s) {
        return new Job(name, runs, stepnc, robot, Optional.of(s), cutting, grading, sole, outputs);
    }

    public Job withCutting(CuttingSettings s) {
        return new Job(name, runs, stepnc, robot, pocket, Optional.of(s), grading, sole, outputs);
    }

    public Job withGrading(GradingSettings s) {
        return new Job(name, runs, stepnc, robot, pocket, cutting, Optional.of(s), sole, outputs);
    }

    public Job withSole(SoleSettings s) {
        return new Job(name, runs, stepnc, robot, pocket, cutting, grading, Optional.of(s), outputs);
    }

    public Job withOutputs(OutputSettings s) {
        return new Job(name, runs, stepnc, robot, pocket, cutting, grading, sole, s);
    }
}
