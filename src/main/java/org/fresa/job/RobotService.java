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
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.fresa.cell.RobotFiles;
import org.fresa.cell.RobotTools;
import org.fresa.cell.TablePlacing;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.io.Timing;
import org.fresa.kin.Robot;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.model.Toolpath;
import org.fresa.post.NcPosts;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathCsv;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * {@code fresa robot} and the job task {@code robot}: a STEP-NC file's toolpaths
 * placed in the robot cell and turned into a joint trajectory and robot programs.
 * Everything is read and checked before the first file is written.
 */
public final class RobotService {

    /** The formats {@code --formats} accepts. */
    public static final Set<String> FORMATS = Set.of("csv", "xml", "rapid", "krl", "png");

    private static final java.util.concurrent.atomic.AtomicInteger THREADS =
            new java.util.concurrent.atomic.AtomicInteger();

    private RobotService() {}

    /**
     * What the planner asked for.
     *
     * @param choices the toolpath planner's choices where the STEP-NC file is silent or doubtful
     * @param tool the spindle and tool length asked for, else the robot file's and the STEP-NC tools'
     * @param placing whether robotTable is used as given or searched ({@code --place auto})
     */
    public record Settings(
            Path stepnc,
            String robot,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            PlanningChoices choices,
            RobotTools.Choice tool,
            TablePlacing placing) {
        /** @throws IllegalArgumentException for a format not in {@link #FORMATS}: parse with parseFormats */
        public Settings {
            java.util.Objects.requireNonNull(choices, "choices");
            formats = List.copyOf(formats);
            for (String f : formats) {
                if (!FORMATS.contains(f)) {
                    throw new IllegalArgumentException("unknown format '" + f + "'");
                }
            }
            java.util.Objects.requireNonNull(tool, "tool");
            java.util.Objects.requireNonNull(placing, "placing");
        }

        /** The robot -> table placement as given. */
        public Settings(
                Path stepnc,
                String robot,
                Placement robotTable,
                Placement tablePiece,
                List<String> formats,
                PlanningChoices choices,
                RobotTools.Choice tool) {
            this(stepnc, robot, robotTable, tablePiece, formats, choices, tool, TablePlacing.GIVEN);
        }

        /**
         * The planner's default choices; no spindle or tool length given: the robot file's tool frame
         * and the STEP-NC tools' lengths.
         */
        public Settings(Path stepnc, String robot, Placement robotTable, Placement tablePiece, List<String> formats) {
            this(stepnc, robot, robotTable, tablePiece, formats, PlanningChoices.DEFAULT, RobotTools.Choice.NONE);
        }

        /** The planner's choices; the robot file's tool frame and the STEP-NC tools' lengths. */
        public Settings(
                Path stepnc,
                String robot,
                Placement robotTable,
                Placement tablePiece,
                List<String> formats,
                PlanningChoices choices) {
            this(stepnc, robot, robotTable, tablePiece, formats, choices, RobotTools.Choice.NONE);
        }

        /** The planner's default choices with the spindle and tool length asked for. */
        public Settings(
                Path stepnc,
                String robot,
                Placement robotTable,
                Placement tablePiece,
                List<String> formats,
                RobotTools.Choice tool) {
            this(stepnc, robot, robotTable, tablePiece, formats, PlanningChoices.DEFAULT, tool);
        }
    }

    /** Reads --formats, refusing unknown names. */
    public static List<String> parseFormats(String text) throws CamInputException {
        List<String> out = new ArrayList<>();
        for (String f : text.split(",")) {
            String t = f.trim().toLowerCase(java.util.Locale.ROOT);
            if (t.isEmpty()) {
                continue;
            }
            if (!FORMATS.contains(t)) {
                throw new CamInputException(
                        "--formats",
                        "unknown format '" + f.trim() + "': expected a comma list of csv, xml, rapid, krl, png");
            }
            out.add(t);
        }
        return out;
    }

    /**
     * Reads the inputs, solves and writes every file; see {@link RobotTrajectoryService#write}.
     * The files are rendered in parallel (one thread per core, at most 4).
     */
    public static TaskOutcome run(Settings s, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        ExecutorService pool = Executors.newFixedThreadPool(
                Math.max(1, Math.min(4, Runtime.getRuntime().availableProcessors())), r -> {
                    Thread t = new Thread(r, "fresa-output-" + THREADS.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        try {
            return run(s, out, progress, pool);
        } finally {
            pool.shutdownNow();
        }
    }

    private static TaskOutcome run(Settings s, OutputFolder out, ProgressMonitor progress, ExecutorService pool)
            throws CamInputException, IOException {
        Timing.mark("start");
        Robot robot = RobotFiles.load(s.robot());
        Timing.mark("robot loaded");
        StepNcProgram program = StepNcService.read(s.stepnc(), progress);
        Timing.mark("part 21 read and bound");
        java.util.Optional<String> nothing = program.whyNothingToMachine();
        if (nothing.isPresent()) {
            return ToolpathService.nothingToMachine(program, List.of(nothing.get()), out);
        }
        ToolpathPlanner.Plan plan = ToolpathService.plan(program, s.choices(), progress);
        Timing.mark("toolpaths planned");
        if (plan.planned() == 0) {
            // every workingstep refused: no trajectory and no robot program for nothing
            return ToolpathService.nothingToMachine(program, plan.problems(), out);
        }
        Toolpath path = plan.toolpath();
        RobotTools.Frames tools =
                RobotTools.of(robot, s.tool(), program, plan, s.stepnc().toString());
        Placement robotTable = s.robotTable();
        java.util.Optional<AutoPlacement.Outcome> placed = java.util.Optional.empty();
        if (s.placing() == TablePlacing.AUTO) {
            AutoPlacement.Outcome a = AutoPlacement.search(
                    tools.toolpath(), robot, s.tablePiece(), tools.tcpByLabel(), AutoPlacement.names(plan), progress);
            Timing.mark("placement searched");
            if (!a.found()) {
                // never a partial placement: the planner learns which workingsteps are out of reach
                List<String> problems = placementRefused(Planning.of(tools, plan), a);
                Map<String, Object> summary = new LinkedHashMap<>();
                summary.put("workingsteps", plan.workingsteps());
                summary.put("planned_workingsteps", plan.planned());
                summary.put("placement_search", a.summary());
                summary.put("problems", problems);
                out.create();
                out.writeString("summary.json", Json.writePretty(summary));
                return new TaskOutcome(1, problems, summary, out.written());
            }
            placed = java.util.Optional.of(a);
            robotTable = a.robotTable();
        }
        RobotTrajectoryService.Request req = new RobotTrajectoryService.Request(
                tools.toolpath(),
                robot,
                robotTable,
                s.tablePiece(),
                NcPosts.CHORD_TOLERANCE_MM * 10,
                s.formats(),
                org.fresa.kin.TrajectorySolver.Options.DEFAULT,
                tools.tcpByLabel());
        out.create();
        TaskOutcome o;
        RobotTrajectoryService.Solved solved;
        out.beginParallel(pool);
        try {
            // toolpath.csv does not depend on the robot: it is written while the IK runs
            out.write("toolpath.csv", os -> {
                Writer w = new OutputStreamWriter(os, StandardCharsets.UTF_8);
                ToolpathCsv.write(path, NcPosts.CHORD_TOLERANCE_MM, w);
                w.flush();
            });
            solved = RobotTrajectoryService.solve(req, progress);
            Timing.mark("trajectory solved");
            // the inverse kinematics is done; the charts and programs take a while yet
            progress.progress(-1, "writing the files");
            String name = s.stepnc().getFileName().toString().replaceFirst("\\.[^.]*$", "");
            o = RobotTrajectoryService.write(
                    solved,
                    name,
                    out,
                    ProgramChecks.stepnc(program, plan, s.choices()),
                    placed.isPresent() ? Map.of("placement_search", placed.get().summary()) : Map.of());
            Timing.mark("files asked for");
            out.finishParallel();
            Timing.mark("files written");
        } finally {
            out.abandonParallel();
        }
        return outcome(Planning.of(tools, plan), o, out.written());
    }

    /**
     * What the planning of a robot job says before a point is solved: the tool frames' warnings
     * (a spindle not given, a tool length taken from the file) and the planner's problems, in that
     * order, and how many workingsteps are planned of how many (a run that leaves one out exits 1).
     */
    public record Planning(List<String> warnings, int workingsteps, int planned) {
        public Planning {
            warnings = List.copyOf(warnings);
        }

        /** The planning of these tool frames and this plan. */
        public static Planning of(RobotTools.Frames tools, ToolpathPlanner.Plan plan) {
            List<String> w = new ArrayList<>(tools.warnings());
            w.addAll(plan.problems());
            return new Planning(w, plan.workingsteps(), plan.planned());
        }
    }

    /**
     * What a run says when the placement search ({@code --place auto}, a job's {@code place="auto"})
     * finds no placement reaching every target, which writes no trajectory: the planning's
     * warnings, then which workingsteps are out of reach.
     */
    public static List<String> placementRefused(Planning p, AutoPlacement.Outcome a) {
        List<String> out = new ArrayList<>(p.warnings());
        out.add(a.sentence());
        return out;
    }

    /**
     * A run's outcome from what its planning said and what writing the solved trajectory said
     * ({@link RobotTrajectoryService#write}): the planning's warnings first, exit 1 when either
     * fails or a workingstep is not planned. {@link #run} and the Output tab's Save both end here.
     */
    public static TaskOutcome outcome(Planning p, TaskOutcome written, List<Path> files) {
        List<String> problems = new ArrayList<>(p.warnings());
        problems.addAll(written.problems());
        Map<String, Object> summary = new LinkedHashMap<>(written.summary());
        summary.put("workingsteps", p.workingsteps());
        summary.put("planned_workingsteps", p.planned());
        int status = written.exitStatus() == 0 && p.planned() == p.workingsteps() ? 0 : 1;
        return new TaskOutcome(status, problems, summary, files);
    }

    /**
     * What a run says of a trajectory solved at the job's placements before its programs are
     * checked: the planning's warnings, then the unreachable points and the solver's notes
     * ({@link RobotTrajectoryService#problems}). The Position tab shows them after Compute.
     */
    public static List<String> said(Planning p, RobotTrajectoryService.Solved solved) {
        List<String> out = new ArrayList<>(p.warnings());
        out.addAll(RobotTrajectoryService.problems(solved, java.util.Optional.empty()));
        return out;
    }

    /** The job task. */
    public static TaskOutcome run(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        JobSettings.StepNcSettings st = JobRunner.require(job.stepnc(), "stepnc", job);
        JobSettings.RobotSettings r = JobRunner.require(job.robot(), "robot", job);
        List<String> formats = parseFormats(String.join(",", r.formats()));
        return run(
                new Settings(
                        st.file(),
                        r.robot(),
                        r.robotTable(),
                        r.tablePiece(),
                        formats,
                        st.choices(),
                        new RobotTools.Choice(r.spindle(), r.toolLengthMm()),
                        r.placing()),
                out,
                progress);
    }
}
