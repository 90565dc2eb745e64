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

    /**
     * Plans with these choices and writes the three files into the folder. Each workingstep's
     * section is written to {@code toolpath.csv} and the program as soon as it is planned, and only
     * its summary line is kept, so a file of tens of thousands of workingsteps is planned in a small
     * heap; the program is checked as written, in full, before it is renamed into place.
     */
    public static TaskOutcome run(
            Path file, MillingPost postName, PlanningChoices choices, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        NcPost post = postName.ncPost();
        // planning reads only the features of the instance table: the rest of a large file's can go
        StepNcProgram program = StepNcService.read(file, progress).forPlanning();
        java.util.Optional<String> nothing = program.whyNothingToMachine();
        if (nothing.isPresent()) {
            return nothingToMachine(program, List.of(nothing.get()), out);
        }
        progress.progress(-1, "planning " + program.workingsteps().size() + " workingsteps");
        String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        String programFile = "program." + post.fileExtension();
        SummaryLines lines = new SummaryLines();
        List<String> problems = new ArrayList<>();
        Map<Long, String> refusals;
        int workingsteps;
        String refusal = null;
        out.create();
        try (OutputFolder.Staged csvFile = out.stage("toolpath.csv");
                OutputFolder.Staged ncFile = out.stage(programFile)) {
            Writer csvText = new OutputStreamWriter(csvFile.out(), StandardCharsets.UTF_8);
            Writer ncText = new OutputStreamWriter(ncFile.out(), StandardCharsets.UTF_8);
            ToolpathCsv.Sections csv = ToolpathCsv.begin(NcPosts.CHORD_TOLERANCE_MM, csvText);
            NcPost.Program nc = post.begin(name, ncText);
            ProgramChecks.StepNcLimits limits = new ProgramChecks.StepNcLimits(program, choices);
            Map<Long, String> axisRefusals = new LinkedHashMap<>();
            Map<String, Integer> perAxis = new LinkedHashMap<>();
            ToolpathPlanner.Outcome planned =
                    ToolpathPlanner.plan(program, Tolerance.DEFAULT, choices, (ws, section, step) -> {
                        // what a 3-axis program can hold, as alongMachineZ says
                        if (section.toolAxis().distance(Vec3.UNIT_Z) > AXIS_TOLERANCE) {
                            String axis = "tool axis " + ToolpathPlanner.axis(section.toolAxis());
                            perAxis.merge(axis, 1, Integer::sum);
                            axisRefusals.put(
                                    step.workingstepInstanceId(),
                                    axis + ": " + THREE_AXIS + "; it needs another setup");
                            return;
                        }
                        int rows = csv.section(section);
                        nc.section(section);
                        limits.add(ws, section);
                        lines.add(section, step, rows);
                    });
            problems.addAll(planned.problems());
            problems.addAll(anotherSetup(perAxis));
            refusals = new LinkedHashMap<>(planned.refusals());
            workingsteps = planned.workingsteps();
            refusals.putAll(axisRefusals);
            if (lines.sections() > 0) {
                csvText.flush();
                nc.end();
                csvFile.commit();
                try {
                    ProgramChecks.require(
                            programFile, ncFile.written(), ProgramChecks.dialect(post.name()), limits.limits());
                    ncFile.commit();
                } catch (ProgramChecks.RefusedProgram e) {
                    refusal = e.getMessage();
                    lines.refused(e.failure().message());
                }
            }
        }
        if (lines.sections() == 0) {
            // every workingstep refused: an empty program would look like a finished job
            return nothingToMachine(program, problems, out);
        }
        Map<String, Object> summary = lines.summary(program, post, workingsteps, problems, refusals);
        out.write("summary.json", os -> {
            Writer w = new OutputStreamWriter(os, StandardCharsets.UTF_8);
            Json.writePretty(summary, w);
        });
        progress.progress(1, "done");
        int status = refusal == null && (problems.isEmpty() || lines.sections() == workingsteps) ? 0 : 1;
        List<String> told = new ArrayList<>(problems);
        if (refusal != null) {
            told.add(refusal);
        }
        return new TaskOutcome(status, told, summary, out.written());
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
        problems.addAll(anotherSetup(perAxis));
        return new ToolpathPlanner.Plan(
                new Toolpath(kept), problems, plan.workingsteps(), kept.size(), keptSteps, refusals);
    }

    /** The problem line of each tool axis a 3-axis program leaves out, with its count of workingsteps. */
    private static List<String> anotherSetup(Map<String, Integer> perAxis) {
        List<String> out = new ArrayList<>();
        perAxis.forEach((axis, n) -> out.add(axis + ": " + THREE_AXIS + "; " + n
                + (n == 1 ? " workingstep needs" : " workingsteps need") + " another setup"));
        return out;
    }

    /**
     * What {@link #run} says of a program planned whole (the STEP-NC tab's plan), in its words and
     * order: why there is nothing to machine, or the planner's problems, the workingsteps a 3-axis
     * program leaves for another setup ({@link #alongMachineZ}), then the program check's refusal
     * of the program the post writes of the rest; empty when the run says nothing.
     *
     * @param file the STEP-NC file, whose name the program carries
     */
    public static List<String> problems(Path file, Planned planned, MillingPost postName, PlanningChoices choices)
            throws IOException {
        StepNcProgram program = planned.program();
        java.util.Optional<String> nothing = program.whyNothingToMachine();
        if (nothing.isPresent()) {
            return List.of(nothing.get());
        }
        ToolpathPlanner.Plan kept = alongMachineZ(planned.plan());
        List<String> out = new ArrayList<>(kept.problems());
        if (kept.planned() == 0) {
            return out;
        }
        NcPost post = postName.ncPost();
        String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        java.io.StringWriter text = new java.io.StringWriter();
        post.write(kept.toolpath(), name, text);
        try {
            ProgramChecks.require(
                    "program." + post.fileExtension(),
                    text.toString(),
                    ProgramChecks.dialect(post.name()),
                    ProgramChecks.stepnc(program, kept, choices));
        } catch (ProgramChecks.RefusedProgram e) {
            out.add(e.getMessage());
        }
        return out;
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

    /**
     * {@code summary.json} gathered a section at a time: one line per section written, the totals,
     * and at the end what the program does not hold.
     */
    static final class SummaryLines {
        private final List<Object> perSection = new ArrayList<>();
        private final java.util.Set<Long> held = new java.util.HashSet<>();
        private CycleTime total = CycleTime.ZERO;
        private long moves;
        private long points;
        private String refused;

        void add(ToolpathSection s, ToolpathPlanner.PlannedStep step, int rows) {
            CycleTime t = CycleTime.of(s, RAPID_MM_PER_MIN);
            total = total.plus(t);
            moves += s.moves().size();
            points += rows;
            held.add(step.workingstepInstanceId());
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

        int sections() {
            return perSection.size();
        }

        /** The program failed its check: the failure's message. */
        void refused(String message) {
            refused = message;
        }

        Map<String, Object> summary(
                StepNcProgram program,
                NcPost post,
                int workingsteps,
                List<String> problems,
                Map<Long, String> refusals) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("source", program.source());
            m.put("post", post.name());
            m.put("workingsteps", workingsteps);
            m.put("planned", perSection.size());
            m.put("sections", perSection.size());
            m.put("moves", number(moves));
            m.put("points", number(points));
            m.put("rapid_mm_per_min", RAPID_MM_PER_MIN);
            m.put("feed_length_mm", total.feedLengthMm());
            m.put("rapid_length_mm", total.rapidLengthMm());
            if (total.dwellSeconds() > 0) {
                m.put("dwell_time_s", total.dwellSeconds());
            }
            m.put("cycle_time_s", total.seconds());
            m.put("chord_tolerance_mm", NcPosts.CHORD_TOLERANCE_MM);
            m.put("workingstep_paths", perSection);
            m.put("problems", problems);
            // every workingstep the program does not hold, each with its own reason (the problems sum
            // some of them up, per tool axis or per feed note)
            List<Object> notPlanned = new ArrayList<>();
            for (org.fresa.stepnc.MachiningWorkingstep w : program.workingsteps()) {
                if (!held.contains(w.instanceId())) {
                    Map<String, Object> x = new LinkedHashMap<>();
                    x.put("id", w.id());
                    x.put("instance", w.instanceId());
                    x.put("reason", refusals.getOrDefault(w.instanceId(), "not planned"));
                    notPlanned.add(x);
                }
            }
            m.put("not_planned", notPlanned);
            List<Object> skipped = new ArrayList<>();
            for (StepNcProgram.Skipped s : program.skipped()) {
                skipped.add(Map.of("id", s.id(), "reason", s.reason()));
            }
            m.put("skipped", skipped);
            if (refused != null) {
                m.put("program_refused", refused);
            }
            return m;
        }

        /** A count as the summary has always written it: an int while it fits. */
        private static Number number(long n) {
            return n <= Integer.MAX_VALUE ? Integer.valueOf((int) n) : Long.valueOf(n);
        }
    }
}
