package org.fresa.job;

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
 * Everything a planner sets up, in one immutable value: which task to run and each module's
 * settings. The GUI edits a job by replacing it with modified copies ({@code withPocket(...)});
 * {@code fresa run} executes the same value read from a file.
 *
 * <p>A module's settings are empty until the planner has chosen its input file.
 */
public record Job(String name, JobTask task,
        Optional<StepNcSettings> stepnc,
        Optional<RobotSettings> robot,
        Optional<PocketSettings> pocket,
        Optional<CuttingSettings> cutting,
        Optional<GradingSettings> grading,
        Optional<SoleSettings> sole,
        OutputSettings outputs) {

    public Job {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(task, "task");
        Objects.requireNonNull(stepnc, "stepnc");
        Objects.requireNonNull(robot, "robot");
        Objects.requireNonNull(pocket, "pocket");
        Objects.requireNonNull(cutting, "cutting");
        Objects.requireNonNull(grading, "grading");
        Objects.requireNonNull(sole, "sole");
        Objects.requireNonNull(outputs, "outputs");
    }

    /** A new, empty job. */
    public static Job empty(JobTask task) {
        return new Job("untitled", task, Optional.empty(), Optional.empty(), Optional.empty(), Optional.empty(),
                Optional.empty(), Optional.empty(), OutputSettings.DEFAULT);
    }

    public Job withName(String n) {
        return new Job(n, task, stepnc, robot, pocket, cutting, grading, sole, outputs);
    }

    public Job withTask(JobTask t) {
        return new Job(name, t, stepnc, robot, pocket, cutting, grading, sole, outputs);
    }

    public Job withStepnc(StepNcSettings s) {
        return new Job(name, task, Optional.of(s), robot, pocket, cutting, grading, sole, outputs);
    }

    public Job withRobot(RobotSettings s) {
        return new Job(name, task, stepnc, Optional.of(s), pocket, cutting, grading, sole, outputs);
    }

    public Job withPocket(PocketSettings s) {
        return new Job(name, task, stepnc, robot, Optional.of(s), cutting, grading, sole, outputs);
    }

    public Job withCutting(CuttingSettings s) {
        return new Job(name, task, stepnc, robot, pocket, Optional.of(s), grading, sole, outputs);
    }

    public Job withGrading(GradingSettings s) {
        return new Job(name, task, stepnc, robot, pocket, cutting, Optional.of(s), sole, outputs);
    }

    public Job withSole(SoleSettings s) {
        return new Job(name, task, stepnc, robot, pocket, cutting, grading, Optional.of(s), outputs);
    }

    public Job withOutputs(OutputSettings s) {
        return new Job(name, task, stepnc, robot, pocket, cutting, grading, sole, s);
    }
}
