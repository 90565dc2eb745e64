package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.kin.TrajectoryPoint;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PositionViewModelTest {

    @ParameterizedTest
    @CsvSource(textBlock = """
            abc,  'X: ''abc'' is not a number'
            '',   X is empty: type a number (mm)
            1e9,  X is more than 100 m away
            """)
    void aBadRobotTableFieldIsNamedInTheMessage(String text, String message) {
        PositionViewModel vm = new PositionViewModel();
        vm.setRobotTable(0, text);
        assertEquals(message, vm.problems().get("robot-table.X"));
        assertEquals(1, vm.problems().size());
    }

    @Test
    void anAngleBeyondAFullTurnIsRefused() {
        PositionViewModel vm = new PositionViewModel();
        vm.setTablePiece(4, "400");
        assertEquals("RY must lie within -360..360 deg", vm.problems().get("table-piece.RY"));
    }

    @Test
    void goodFieldsBecomeTheJobsPlacements() {
        PositionViewModel vm = new PositionViewModel();
        String[] rt = {"400", "-200", "500", "15"};
        for (int i = 0; i < rt.length; i++) {
            vm.setRobotTable(i, rt[i]);
        }
        vm.setTablePiece(1, "10");
        vm.setTablePiece(3, "-90");
        assertTrue(vm.problems().isEmpty());
        Job j = vm.applyTo(Job.empty(JobTask.ROBOT));
        var r = j.robot().orElseThrow();
        assertEquals("irb140", r.robot());
        assertEquals(-200, r.robotTable().yMm());
        assertEquals(15, r.robotTable().rzDeg());
        assertEquals(10, r.tablePiece().yMm());
        assertEquals(-90, r.tablePiece().rxDeg());
        PositionViewModel back = new PositionViewModel();
        back.load(r);
        assertEquals("-200", back.robotTable(1));
        assertEquals("-90", back.tablePiece(3));
    }

    @Test
    void example1OnTheIrb140IsReachedAndTheDrawnArmEndsAtTheTarget() throws Exception {
        PositionViewModel vm = new PositionViewModel();
        vm.setRobotTable(0, "400");
        vm.setRobotTable(1, "-200");
        vm.setRobotTable(2, "500");
        vm.setTablePiece(1, "10");
        RobotTrajectoryService.Solved s = PositionViewModel.compute(
                Path.of("samples/stepnc/iso14649-11-example1.stp"),
                "irb140",
                vm.robotTablePlacement(),
                vm.tablePiecePlacement(),
                List.of("csv"),
                ProgressMonitor.NONE);
        vm.setResult(s);
        assertTrue(vm.pointCount() > 10);
        assertEquals(0, s.result().unreachable());
        assertTrue(vm.summary().contains("Unreachable: 0"), vm.summary().toString());
        assertEquals(new Vec3(400, -200, 500), vm.tableOrigin());
        assertEquals(new Vec3(400, -190, 500), vm.pieceOrigin());
        int last = vm.pointCount() - 1;
        vm.select(last + 5);
        assertEquals(last, vm.selected());
        TrajectoryPoint p = s.result().points().get(last);
        List<Vec3> arm = vm.robotLinks().get(0);
        Vec3 tip = arm.get(arm.size() - 1);
        assertEquals(0, tip.minus(p.target().translationPart()).norm(), 1e-6);
        assertEquals(Vec3.ZERO, arm.get(0));
        assertEquals(vm.pointCount(), vm.cellPoints().size());
        assertTrue(vm.selectedText().startsWith("Point " + (last + 1) + " of "), vm.selectedText());
    }

    /**
     * After Compute the Summary lists what fresa run says of the same job (the spindle not given,
     * the feeds read from the file, the relink, the points out of reach), and the Output tab's Save
     * says all of it as the run does, with its exit status: example 2 on the IRB-140 as table 5.1
     * places it, and moved 500 mm further out, where points are out of reach.
     */
    @ParameterizedTest
    @CsvSource({"450, 0, 350", "950, 0, 350"})
    void theSummaryAndSaveSayWhatTheRunSays(double x, double y, double z, @org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        Job sample = org.fresa.job.JobXml.read(Path.of("samples/jobs/example2-irb140.xml"));
        Job job = PositionViewModel.withRobotTable(sample, new org.fresa.model.Placement(x, y, z, 0, 0, 0));
        org.fresa.job.TaskOutcome run = org.fresa.job.RobotService.run(
                job, new org.fresa.io.OutputFolder(dir.resolve("run")), ProgressMonitor.NONE);
        assertTrue(run.problems().size() > 3, run.problems().toString());
        assertEquals(x > 900 ? 1 : 0, run.exitStatus(), "points out of reach: " + run.problems());
        org.fresa.job.JobSettings.RobotSettings r = job.robot().orElseThrow();
        org.fresa.job.JobSettings.StepNcSettings st = job.stepnc().orElseThrow();
        // as the Position tab's Compute does
        PositionViewModel.Planned planned = PositionViewModel.plan(
                st.file(),
                r.robot(),
                new org.fresa.cell.RobotTools.Choice(r.spindle(), r.toolLengthMm()),
                st.choices(),
                ProgressMonitor.NONE);
        RobotTrajectoryService.Solved solved = RobotTrajectoryService.solve(
                planned.request(r.robotTable(), r.tablePiece(), r.formats()), ProgressMonitor.NONE);
        PositionViewModel vm = new PositionViewModel();
        vm.setResult(solved);
        vm.setSaid(org.fresa.job.RobotService.said(planned.planning(), solved));
        List<String> shown =
                vm.said().all().stream().map(WarningList.Warning::text).toList();
        for (String p : run.problems()) {
            // the program check is the Output tab's, which checks the programs it previews and saves
            if (!p.startsWith("robot programs (")) {
                assertTrue(shown.contains(p), "the Summary does not say: " + p + "\n" + shown);
            }
        }
        org.fresa.job.TaskOutcome saved = OutputViewModel.write(
                new RobotRunModel.Run(solved, "example2", planned.planning()),
                r.formats(),
                new org.fresa.io.OutputFolder(dir.resolve("save")));
        assertEquals(run.problems(), saved.problems());
        assertEquals(run.exitStatus(), saved.exitStatus());
    }
}
