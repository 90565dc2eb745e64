package org.fresa.job;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.cell.RobotFiles;
import org.fresa.cell.RobotTools;
import org.fresa.geom.Transform3;
import org.fresa.kin.PlacementSearch;
import org.fresa.kin.Robot;
import org.fresa.kin.ToolTarget;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.NcPosts;
import org.fresa.setting.SettingRanges;
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * The placement search of {@code fresa robot --place auto}, the job's {@code place="auto"} and the
 * Position tab's "Place automatically": the part's targets (with each workingstep's TCP) placed on
 * the table by the table -> piece placement, and the robot -> table placement searched by
 * {@link PlacementSearch}. The chosen placement is rounded to 0.1 mm and 0.1 deg, as a planner
 * would type it, and it is the rounded one that is checked and used.
 */
public final class AutoPlacement {

    private AutoPlacement() {}

    /**
     * What the search gave.
     *
     * @param result the search's answer
     * @param robotTable the placement found (rounded), or the best one tried when none reaches everything
     * @param seconds the search's wall-clock time
     * @param cpuSeconds the search's CPU time (its thread's; on a shared machine the wall clock
     *     also counts the time it waited for a core)
     */
    public record Outcome(PlacementSearch.Result result, Placement robotTable, double seconds, double cpuSeconds) {

        /** Whether every target is reached from {@link #robotTable}. */
        public boolean found() {
            return result.found().isPresent();
        }

        /** One sentence for the planner: the placement chosen, or why there is none. */
        public String sentence() {
            PlacementSearch.Result r = result;
            if (found()) {
                return String.format(
                        Locale.ROOT,
                        "placement found: --robot-table %s reaches all %d targets with a"
                                + " joint-limit margin of %.1f %% (%d placements tried in %.1f s, %.1f s of CPU)",
                        text(robotTable),
                        r.targets(),
                        100 * r.minMargin(),
                        r.placementsTried(),
                        seconds,
                        cpuSeconds);
            }
            StringBuilder sb = new StringBuilder("no table placement tried reaches every target");
            if (!r.outOfReachEverywhere().isEmpty()) {
                sb.append("; out of reach from every placement tried: ")
                        .append(String.join(", ", r.outOfReachEverywhere()));
            }
            if (!r.notTogether().isEmpty()) {
                sb.append("; reachable alone but not together with the rest: ")
                        .append(String.join(", ", r.notTogether()));
            }
            for (String n : r.notes()) {
                sb.append("; ").append(n);
            }
            sb.append(String.format(
                    Locale.ROOT,
                    " (the best placement tried, --robot-table %s, reaches %d of %d"
                            + " targets; %d placements tried in %.1f s, %.1f s of CPU)",
                    text(robotTable),
                    r.reached(),
                    r.targets(),
                    r.placementsTried(),
                    seconds,
                    cpuSeconds));
            return sb.toString();
        }

        /** The figures for summary.json. */
        public Map<String, Object> summary() {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("found", found());
            m.put("robot_table", List.of(robotTable.xMm(), robotTable.yMm(), robotTable.zMm(), robotTable.rzDeg()));
            m.put("targets", result.targets());
            m.put("reached", result.reached());
            m.put("min_joint_margin", Double.isFinite(result.minMargin()) ? result.minMargin() : null);
            m.put("out_of_reach_everywhere", result.outOfReachEverywhere());
            m.put("reachable_alone_only", result.notTogether());
            m.put("notes", result.notes());
            m.put("placements_tried", result.placementsTried());
            m.put("search_s", seconds);
            m.put("search_cpu_s", cpuSeconds);
            m.put("what", sentence());
            return m;
        }
    }

    /** x,y,z,rz as {@code --robot-table} takes it. */
    public static String text(Placement p) {
        return String.format(Locale.ROOT, "%s,%s,%s,%s", num(p.xMm()), num(p.yMm()), num(p.zMm()), num(p.rzDeg()));
    }

    private static String num(double v) {
        String s = String.format(Locale.ROOT, "%.1f", v);
        return s.endsWith(".0") ? s.substring(0, s.length() - 2) : s.equals("-0") ? "0" : s;
    }

    /**
     * Searches the robot -> table placement for a toolpath.
     *
     * @param toolpath the toolpath in the workpiece frame
     * @param tcpByLabel each section label's TCP in the flange frame (absent: the robot's own tool)
     * @param names the name the result gives each section (a workingstep's id and entity, as
     *     workingsteps may share an id), one per section
     */
    public static Outcome search(
            Toolpath toolpath,
            Robot robot,
            Placement tablePiece,
            Map<String, Transform3> tcpByLabel,
            List<String> names,
            ProgressMonitor progress) {
        long t0 = System.nanoTime();
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long c0 = mx.getCurrentThreadCpuTime();
        if (names.size() != toolpath.sections().size()) {
            throw new IllegalArgumentException("one name per section: " + names.size() + " for "
                    + toolpath.sections().size());
        }
        List<ToolpathSection> named = new ArrayList<>();
        Map<String, Transform3> tcps = new java.util.HashMap<>();
        for (int i = 0; i < names.size(); i++) {
            ToolpathSection sec = toolpath.sections().get(i);
            named.add(sec.withLabel(names.get(i)));
            tcps.put(names.get(i), tcpByLabel.getOrDefault(sec.label(), robot.tool()));
        }
        List<ToolTarget> inTable = RobotTrajectoryService.targets(
                new Toolpath(named), tablePiece.toTransform(), NcPosts.CHORD_TOLERANCE_MM * 10);
        Map<Transform3, Robot> byTcp = new java.util.HashMap<>();
        byTcp.put(robot.tool(), robot);
        PlacementSearch search = new PlacementSearch(
                robot,
                label -> byTcp.computeIfAbsent(tcps.getOrDefault(label, robot.tool()), robot::withTool),
                new PlacementSearch.Bounds(SettingRanges.CELL_SIZE_MM));
        PlacementSearch.Result r = search.search(inTable, (fraction, what) -> {
            progress.checkCancelled();
            progress.progress(fraction, what);
        });
        PlacementSearch.TablePlacement p = r.found().orElse(r.best());
        Placement rounded = new Placement(round(p.xMm()), round(p.yMm()), round(p.zMm()), 0, 0, round(p.rzDeg()));
        if (r.found().isPresent()) {
            // the rounded placement is the one used: check it on every target
            PlacementSearch.Result check = search.check(
                    inTable,
                    new PlacementSearch.TablePlacement(rounded.xMm(), rounded.yMm(), rounded.zMm(), rounded.rzDeg()));
            if (check.found().isPresent()) {
                r = new PlacementSearch.Result(
                        check.found(),
                        check.best(),
                        r.targets(),
                        r.reached(),
                        check.minMargin(),
                        List.of(),
                        List.of(),
                        r.placementsTried() + 1,
                        r.notes());
            } else {
                rounded = new Placement(p.xMm(), p.yMm(), p.zMm(), 0, 0, p.rzDeg());
            }
        }
        return new Outcome(r, rounded, (System.nanoTime() - t0) / 1e9, (mx.getCurrentThreadCpuTime() - c0) / 1e9);
    }

    /**
     * The search for a STEP-NC file as {@code fresa robot} plans it with the job's choices (the
     * Position tab's button): the toolpath placed is the one Compute solves.
     */
    public static Outcome search(
            Path stepnc,
            PlanningChoices choices,
            String robotName,
            Placement tablePiece,
            RobotTools.Choice tool,
            ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        Robot robot = RobotFiles.load(robotName);
        ToolpathService.Planned planned = ToolpathService.compute(stepnc, choices, progress);
        var program = planned.program();
        ToolpathPlanner.Plan plan = planned.plan();
        if (plan.planned() == 0) {
            throw new CamInputException(stepnc.toString(), "no workingstep could be planned: nothing to place");
        }
        RobotTools.Frames tools = RobotTools.of(robot, tool, program, plan, stepnc.toString());
        return search(tools.toolpath(), robot, tablePiece, tools.tcpByLabel(), names(plan), progress);
    }

    /** Each planned workingstep's id with its entity ({@code Pocket_RGH (#1234)}): ids repeat in a file. */
    public static List<String> names(ToolpathPlanner.Plan plan) {
        List<String> out = new ArrayList<>();
        for (ToolpathPlanner.PlannedStep s : plan.steps()) {
            out.add(s.label() + " (#" + s.workingstepInstanceId() + ")");
        }
        return out;
    }

    private static double round(double v) {
        double r = Math.rint(v * 10) / 10;
        return r == 0 ? 0 : r;
    }
}
