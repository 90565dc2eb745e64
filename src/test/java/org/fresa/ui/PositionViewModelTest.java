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
}
