package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.cell.RobotTools;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.kin.Reachability;
import org.fresa.kin.TrajectoryPoint;
import org.fresa.kin.TrajectorySolver;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;

/**
 * The live reachability of the Position tab against the full trajectory: the same targets out of
 * reach, in a fraction of the time.
 */
class LiveReachabilityTest {

    private static final Path EXAMPLE2 = Path.of("samples/stepnc/example2.stp");

    private static Reachability checker() {
        return new Reachability(TrajectorySolver.Options.DEFAULT);
    }

    /** The workingsteps and counts of the targets (not the inserted points) a result leaves out of reach. */
    private static List<String> outOfReach(RobotTrajectoryService.Solved s) {
        List<String> out = new ArrayList<>();
        for (TrajectoryPoint p : s.result().points()) {
            if (!p.inserted() && p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                out.add(p.label() + "@" + p.target().translationPart());
            }
        }
        return out;
    }

    @Test
    void example2sReachOnTheIrb140MatchesTheTrajectoryAtEveryPlacementTried() throws Exception {
        RobotTools.Choice tool =
                new RobotTools.Choice(Optional.of(new Placement(0, 0, 150, 0, 0, 0)), OptionalDouble.of(50));
        PositionViewModel.Planned planned = PositionViewModel.plan(
                EXAMPLE2, "irb140", tool, org.fresa.toolpath.PlanningChoices.DEFAULT, ProgressMonitor.NONE);
        Reachability reach = checker();
        Placement piece = new Placement(0, 10, 0, 0, 0, 0);
        RobotTrajectoryService.Solved atJobs = PositionViewModel.reach(
                        planned, new Placement(450, 0, 350, 0, 0, 0), piece, List.of(), reach, () -> false)
                .orElseThrow();
        // the tool drawn on the flange: the 150 mm spindle and the 50 mm cutter of the STEP-NC tool's diameter
        CellScene.ToolShape shape = PositionViewModel.sceneOf(atJobs, 0, Optional.of(planned.spindle()))
                .tool()
                .orElseThrow();
        assertEquals(200, shape.lengthMm(), 1e-6);
        assertEquals(50, shape.cutterLengthMm(), 1e-6);
        assertTrue(shape.diameterMm() > 0);
        PositionViewModel vm = new PositionViewModel();
        vm.setLive(atJobs, PositionViewModel.sceneOf(atJobs, 0), planned.spindle());
        assertTrue(vm.isLive());
        int n = atJobs.targets().size();
        int out = atJobs.result().unreachable();
        String line = vm.reachLine();
        assertTrue(
                out == 0
                        ? line.equals("All " + n + " targets are within reach of irb140.")
                        : line.startsWith(out + " of " + n + " targets out of reach of irb140, in "),
                line);
        assertEquals(6, vm.errorRows().size());
        assertEquals("x (mm)", vm.errorRows().get(0)[0]);
        assertEquals("rz (rad)", vm.errorRows().get(5)[0]);
        StringBuilder report = new StringBuilder();
        // the full trajectory of a mostly unreachable placement takes half a minute: two placements suffice
        for (double x : new double[] {450, 650}) {
            Placement table = new Placement(x, 0, 350, 0, 0, 0);
            long t0 = System.nanoTime();
            RobotTrajectoryService.Solved live = PositionViewModel.reach(
                            planned, table, piece, List.of(), reach, () -> false)
                    .orElseThrow();
            double liveMs = (System.nanoTime() - t0) / 1e6;
            t0 = System.nanoTime();
            RobotTrajectoryService.Solved full =
                    RobotTrajectoryService.solve(planned.request(table, piece, List.of()), ProgressMonitor.NONE);
            double fullMs = (System.nanoTime() - t0) / 1e6;
            assertEquals(live.targets().size(), live.result().points().size());
            assertEquals(outOfReach(full), outOfReach(live), "x = " + x);
            report.append(String.format(
                    Locale.ROOT,
                    "x %.0f: %d of %d out of reach, live %.1f ms, full %.1f ms%n",
                    x,
                    live.result().unreachable(),
                    live.targets().size(),
                    liveMs,
                    fullMs));
        }
        System.out.print(report);
    }

    @Test
    void aStaleCheckStopsWithoutAnAnswer() throws Exception {
        PositionViewModel.Planned planned = PositionViewModel.plan(
                EXAMPLE2,
                "irb140",
                RobotTools.Choice.NONE,
                org.fresa.toolpath.PlanningChoices.DEFAULT,
                ProgressMonitor.NONE);
        assertTrue(PositionViewModel.reach(
                        planned,
                        new Placement(450, 0, 350, 0, 0, 0),
                        Placement.ORIGIN,
                        List.of(),
                        checker(),
                        () -> true)
                .isEmpty());
    }
}
