package org.fresa.job;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;
import org.fresa.model.CycleTime;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.MillingPost;
import org.fresa.post.NcPost;
import org.fresa.post.NcPosts;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathCsv;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * STEP-NC toolpaths as a task ({@code fresa toolpath}, {@code fresa run} task toolpath): reads
 * the file, plans every workingstep in workplan order and writes {@code toolpath.csv},
 * {@code program.ngc} (the chosen post; {@code program.apt} for {@code apt}) and {@code summary.json} (spec/cli.md). Workingsteps that
 * cannot be planned are reported and the rest written, with exit status 1.
 *
 * <p>Cycle time: feed moves at their feed, rapids at {@link #RAPID_MM_PER_MIN}; no acceleration.
 */
public final class ToolpathService {

    /** Rapid traverse rate assumed for the cycle-time estimate (mm/min). */
    public static final double RAPID_MM_PER_MIN = 10000;

    private ToolpathService() {}

    /** Plans and writes the three files into the folder, with the planner's default choices. */
    public static TaskOutcome run(Path file, MillingPost postName, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        return run(file, postName, PlanningChoices.DEFAULT, out, progress);
    }

    /** A STEP-NC program read and its toolpaths planned: what the STEP-NC tab shows. */
    public record Planned(StepNcProgram program, ToolpathPlanner.Plan plan) {}

    /**
     * Reads the STEP-NC file and plans its toolpaths with the job's choices, as {@code fresa
     * toolpath} and {@code fresa run} do before they write anything.
     */
    public static Planned compute(Path file, PlanningChoices choices, ProgressMonitor progress)
            throws CamInputException, IOException {
        StepNcProgram program = StepNcService.read(file, progress);
        return new Planned(program, plan(program, choices, progress));
    }

    /** The toolpaths of a program read, with the planner's choices. */
    public static ToolpathPlanner.Plan plan(StepNcProgram program, PlanningChoices choices, ProgressMonitor progress) {
        progress.progress(-1, "planning " + program.workingsteps().size() + " workingsteps");
        return ToolpathPlanner.plan(program, Tolerance.DEFAULT, choices);
    }

    /** Plans with these choices and writes the three files into the folder. */
    public static TaskOutcome run(
            Path file, MillingPost postName, PlanningChoices choices, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        NcPost post = postName.ncPost();
        StepNcProgram program = StepNcService.read(file, progress);
        java.util.Optional<String> nothing = program.whyNothingToMachine();
        if (nothing.isPresent()) {
            return nothingToMachine(program, List.of(nothing.get()), out);
        }
        ToolpathPlanner.Plan plan = alongMachineZ(plan(program, choices, progress));
        if (plan.planned() == 0) {
            // every workingstep refused: an empty program would look like a finished job
            return nothingToMachine(program, plan.problems(), out);
        }
        Toolpath path = plan.toolpath();
        out.create();
        out.write("toolpath.csv", os -> {
            Writer w = new OutputStreamWriter(os, StandardCharsets.UTF_8);
            ToolpathCsv.write(path, NcPosts.CHORD_TOLERANCE_MM, w);
            w.flush();
        });
        String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        java.io.StringWriter nc = new java.io.StringWriter();
        post.write(path, name, nc);
        List<String> problems = new ArrayList<>(plan.problems());
        Map<String, Object> summary = summary(program, plan, post);
        boolean refused = false;
        try {
            String programFile = "program." + post.fileExtension();
            ProgramChecks.require(
                    programFile,
                    nc.toString(),
                    ProgramChecks.dialect(post.name()),
                    ProgramChecks.stepnc(program, plan, choices));
            out.writeString(programFile, nc.toString());
        } catch (ProgramChecks.RefusedProgram e) {
            problems.add(e.getMessage());
            summary.put("program_refused", e.failure().message());
            refused = true;
        }
        out.writeString("summary.json", Json.writePretty(summary));
        progress.progress(1, "done");
        int status = !refused && (plan.problems().isEmpty() || plan.planned() == plan.workingsteps()) ? 0 : 1;
        return new TaskOutcome(status, problems, summary, out.written());
    }

    /**
     * What a 3-axis program can hold of a plan: the workingsteps whose tool axis is the machine's
     * spindle, +Z of the workpiece frame. A workingstep on another side of the part (a tool axis
     * along X, -Y, or the underside's -Z) needs the part turned into another setup: run in this
     * program's frame, its tool would be below or inside the part. Those are refused, each with its
     * axis, and summed per axis among the problems ("tool axis (0, -1, 0): a 3-axis program
     * machines along +Z only; 12 workingsteps need another setup"); the robot, which orients the
     * tool, keeps them. The program's {@code toolpath.csv} is the same path as the program, so it
     * holds only the workingsteps kept.
     */
    public static ToolpathPlanner.Plan alongMachineZ(ToolpathPlanner.Plan plan) {
        List<ToolpathSection> kept = new ArrayList<>();
        List<ToolpathPlanner.PlannedStep> keptSteps = new ArrayList<>();
        Map<Long, String> refusals = new LinkedHashMap<>(plan.refusals());
        Map<String, Integer> perAxis = new LinkedHashMap<>();
        List<ToolpathSection> sections = plan.toolpath().sections();
        for (int i = 0; i < sections.size(); i++) {
            ToolpathSection s = sections.get(i);
            ToolpathPlanner.PlannedStep step = plan.steps().get(i);
            if (s.toolAxis().distance(Vec3.UNIT_Z) <= AXIS_TOLERANCE) {
                kept.add(s);
                keptSteps.add(step);
                continue;
            }
            String axis = "tool axis " + ToolpathPlanner.axis(s.toolAxis());
            perAxis.merge(axis, 1, Integer::sum);
            refusals.put(step.workingstepInstanceId(), axis + ": " + THREE_AXIS + "; it needs another setup");
        }
        if (perAxis.isEmpty()) {
            return plan;
        }
        List<String> problems = new ArrayList<>(plan.problems());
        perAxis.forEach((axis, n) -> problems.add(axis + ": " + THREE_AXIS + "; " + n
                + (n == 1 ? " workingstep needs" : " workingsteps need") + " another setup"));
        return new ToolpathPlanner.Plan(
                new Toolpath(kept), problems, plan.workingsteps(), kept.size(), keptSteps, refusals);
    }

    /** Why a 3-axis program leaves a workingstep out. */
    static final String THREE_AXIS = "a 3-axis program machines along +Z only";

    /** How far a section's tool axis may be from +Z and still be the spindle's (the posts' own test). */
    static final double AXIS_TOLERANCE = 1e-9;

    /**
     * A file with nothing to machine writes no program, since an empty one would look like a
     * finished job: only {@code summary.json}, with the reasons.
     */
    static TaskOutcome nothingToMachine(StepNcProgram program, List<String> why, OutputFolder out) throws IOException {
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("schema", program.schema());
        summary.put("workingsteps", program.workingsteps().size());
        summary.put("planned", 0);
        summary.put("problems", why);
        out.create();
        out.writeString("summary.json", Json.writePretty(summary));
        return new TaskOutcome(1, why, summary, out.written());
    }

    /** The job task. */
    public static TaskOutcome run(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        JobSettings.StepNcSettings s = JobRunner.require(job.stepnc(), "stepnc", job);
        return run(s.file(), s.post(), s.choices(), out, progress);
    }

    static Map<String, Object> summary(StepNcProgram program, ToolpathPlanner.Plan plan, NcPost post) {
        Toolpath path = plan.toolpath();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("source", program.source());
        m.put("post", post.name());
        m.put("workingsteps", plan.workingsteps());
        m.put("planned", plan.planned());
        m.put("sections", path.sections().size());
        m.put("moves", path.moveCount());
        m.put("points", ToolpathCsv.rows(path, NcPosts.CHORD_TOLERANCE_MM).size());
        CycleTime total = CycleTime.ZERO;
        List<Object> perSection = new ArrayList<>();
        for (int i = 0; i < path.sections().size(); i++) {
            ToolpathSection s = path.sections().get(i);
            ToolpathPlanner.PlannedStep step = plan.steps().get(i);
            CycleTime t = CycleTime.of(s, RAPID_MM_PER_MIN);
            total = total.plus(t);
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("workingstep", s.label());
            x.put("workingstep_instance", step.workingstepInstanceId());
            x.put("tool", s.toolNumber());
            x.put("tool_diameter_mm", s.toolDiameterMm());
            x.put("spindle_rpm", s.spindleRpm());
            x.put("moves", s.moves().size());
            x.put("feed_mm_per_min", step.feed().feedMmPerMin());
            x.put("feed_read_as", step.feed().readAs());
            step.feed().written().ifPresent(w -> x.put("feed_as_written", w));
            if (step.feed().inferred()) {
                x.put("feed_note", step.feed().note());
            }
            x.put("feed_length_mm", t.feedLengthMm());
            x.put("rapid_length_mm", t.rapidLengthMm());
            if (t.dwellSeconds() > 0) {
                x.put("dwell_time_s", t.dwellSeconds());
            }
            x.put("time_s", t.seconds());
            perSection.add(x);
        }
        m.put("rapid_mm_per_min", RAPID_MM_PER_MIN);
        m.put("feed_length_mm", total.feedLengthMm());
        m.put("rapid_length_mm", total.rapidLengthMm());
        if (total.dwellSeconds() > 0) {
            m.put("dwell_time_s", total.dwellSeconds());
        }
        m.put("cycle_time_s", total.seconds());
        m.put("chord_tolerance_mm", NcPosts.CHORD_TOLERANCE_MM);
        m.put("workingstep_paths", perSection);
        m.put("problems", plan.problems());
        // every workingstep the program does not hold, each with its own reason (the problems sum
        // some of them up, per tool axis or per feed note)
        java.util.Set<Long> held = new java.util.HashSet<>();
        plan.steps().forEach(x -> held.add(x.workingstepInstanceId()));
        List<Object> notPlanned = new ArrayList<>();
        for (org.fresa.stepnc.MachiningWorkingstep w : program.workingsteps()) {
            if (!held.contains(w.instanceId())) {
                Map<String, Object> x = new LinkedHashMap<>();
                x.put("id", w.id());
                x.put("instance", w.instanceId());
                x.put("reason", plan.refusals().getOrDefault(w.instanceId(), "not planned"));
                notPlanned.add(x);
            }
        }
        m.put("not_planned", notPlanned);
        List<Object> skipped = new ArrayList<>();
        for (StepNcProgram.Skipped s : program.skipped()) {
            skipped.add(Map.of("id", s.id(), "reason", s.reason()));
        }
        m.put("skipped", skipped);
        return m;
    }
}
