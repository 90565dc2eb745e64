package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.cell.RobotFiles;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RobotViewModelTest {

    static final Tolerance TOL = new Tolerance(1e-9, 1e-12);

    @TempDir
    Path dir;

    @Test
    void theIrb140DhTableIsShownAsTheSpecPrintsIt() {
        RobotViewModel vm = new RobotViewModel();
        assertEquals(6, vm.dhRows().size());
        assertArrayEquals(
                new String[] {"q1", "R", "q1", "352", "70", "-90", "-180", "180"},
                vm.dhRows().get(0));
        assertEquals("q2 - 90", vm.cell(1, RobotViewModel.THETA));
        assertEquals("q5 + 180", vm.cell(4, RobotViewModel.THETA));
    }

    @Test
    void anUntouchedTableIsTheChosenRobot() {
        RobotViewModel vm = new RobotViewModel();
        assertAll(
                () -> assertTrue(vm.messages().isEmpty(), vm.messages().toString()),
                () -> assertFalse(vm.isModified()));
    }

    @Test
    void theAdeptOneShowsItsPrismaticJointAndTheTriceptItsParameters() throws CamInputException {
        RobotViewModel vm = new RobotViewModel();
        vm.choose("adept-one");
        assertEquals("P", vm.cell(2, RobotViewModel.TYPE));
        assertEquals("q3", vm.cell(2, RobotViewModel.D));
        assertEquals("195", vm.cell(2, RobotViewModel.MAX));
        assertFalse(vm.isModified());
        vm.choose("tricept806");
        assertEquals(6, vm.rowCount());
        assertTrue(
                String.join("\n", vm.parameters()).contains("r_p = 200 mm"),
                vm.parameters().toString());
        assertTrue(String.join("\n", vm.parameters()).contains("e_ffl = 250 mm"));
        assertFalse(vm.isModified());
    }

    @Test
    void anExpressionCellChangesTheForwardKinematics() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(1, RobotViewModel.THETA, "q2 - 180/2 + 10");
        vm.setCell(0, RobotViewModel.D, "300 + 52");
        Robot edited = vm.edited().orElseThrow();
        double[] q = {10, 20, -30, 40, 50, 60};
        double[] shifted = {10, 30, -30, 40, 50, 60};
        // theta2 = q2 - 80 is the built-in's theta2 = q2' - 90 with q2' = q2 + 10
        assertTrue(edited.forward(q).eq(Robots.irb140().forward(shifted), TOL));
        assertTrue(vm.isModified());
    }

    @Test
    void anEditedLinkLengthMovesTheFlange() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(1, RobotViewModel.A, "400");
        Transform3 home = vm.edited().orElseThrow().forward(0, 0, 0, 0, 0, 0);
        // at q = 0 the upper arm stands vertical: 40 mm more of it lifts the flange by 40 mm
        assertEquals(712 + 40, home.tz(), 1e-9);
        assertEquals(515, home.tx(), 1e-9);
    }

    @Test
    void theVariableInTheWrongCellIsExplained() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(1, RobotViewModel.THETA, "-90");
        assertTrue(vm.problem(1, RobotViewModel.THETA).orElseThrow().contains("variable belongs here"));
        vm.setCell(1, RobotViewModel.THETA, "q3 - 90");
        assertTrue(vm.problem(1, RobotViewModel.THETA).orElseThrow().contains("joint 2 may use only q2"));
        vm.setCell(1, RobotViewModel.THETA, "2*q2");
        assertTrue(vm.problem(1, RobotViewModel.THETA).orElseThrow().contains("factor 1"));
        vm.setCell(1, RobotViewModel.THETA, "q2 - 90");
        vm.setCell(1, RobotViewModel.D, "q2");
        assertTrue(vm.problem(1, RobotViewModel.D).orElseThrow().contains("q2 belongs in theta"));
        assertTrue(vm.edited().isEmpty());
    }

    @Test
    void limitsMustBeOrderedNumbersInRange() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(2, RobotViewModel.MAX, "-300");
        assertEquals(
                "Joint 3, max: must be more than min (-230 deg)",
                vm.problem(2, RobotViewModel.MAX).orElseThrow());
        vm.setCell(2, RobotViewModel.MAX, "50");
        vm.setCell(3, RobotViewModel.MIN, "-800");
        assertTrue(vm.problem(3, RobotViewModel.MIN).orElseThrow().contains("more than two turns"));
        vm.setCell(3, RobotViewModel.MIN, "abc");
        assertTrue(vm.problem(3, RobotViewModel.MIN).orElseThrow().contains("unknown name 'abc'"));
        vm.setCell(3, RobotViewModel.MIN, "-200");
        assertTrue(vm.messages().isEmpty(), vm.messages().toString());
        vm.setCell(3, RobotViewModel.MIN, "-100");
        assertEquals(-100, vm.edited().orElseThrow().joints().get(3).min());
    }

    @Test
    void makingAJointPrismaticMovesTheVariableIntoD() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(1, RobotViewModel.TYPE, "P");
        assertAll(
                () -> assertEquals("-90", vm.cell(1, RobotViewModel.THETA)),
                () -> assertEquals("q2", vm.cell(1, RobotViewModel.D)));
        vm.setCell(1, RobotViewModel.MIN, "0");
        vm.setCell(1, RobotViewModel.MAX, "500");
        SerialRobot r = (SerialRobot) vm.edited().orElseThrow();
        assertEquals(
                org.fresa.kin.JointType.PRISMATIC, r.chain().joints().get(1).type());
        // 100 mm more along z1 moves the flange by 100 mm
        Transform3 a = r.forward(0, 0, 0, 0, 0, 0);
        Transform3 b = r.forward(0, 100, 0, 0, 0, 0);
        assertEquals(100, a.translationPart().minus(b.translationPart()).norm(), 1e-9);
    }

    @Test
    void theToolFrameIsTheEndEffector() {
        RobotViewModel vm = new RobotViewModel();
        vm.setParameter(3, "150");
        Transform3 home = vm.edited().orElseThrow().forward(0, 0, 0, 0, 0, 0);
        // at q = 0 the tool axis is +x: a 150 mm tool moves the tip from x 515 to 665
        assertEquals(665, home.tx(), 1e-9);
        vm.setParameter(3, "1/");
        assertTrue(vm.parameterProblem(3).orElseThrow().startsWith("Tool Z (mm): "));
    }

    @Test
    void triceptDimensionsAreCheckedAndUsed() throws CamInputException {
        RobotViewModel vm = new RobotViewModel();
        vm.choose("tricept806");
        assertFalse(vm.isEditable(0, RobotViewModel.D));
        vm.setParameter(1, "0");
        assertTrue(vm.parameterProblem(1).orElseThrow().contains("more than 0"));
        vm.setParameter(1, "550");
        TriceptRobot t = (TriceptRobot) vm.edited().orElseThrow();
        assertEquals(550, t.baseRadiusMm());
        vm.setCell(0, RobotViewModel.MAX, "1700");
        assertEquals(1700, vm.edited().orElseThrow().joints().get(0).max());
    }

    @Test
    void aSavedRobotIsWhatTheJobNamesAndReadsBack() throws Exception {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(1, RobotViewModel.THETA, "q2 - 80");
        vm.setParameter(0, "my-arm");
        Path f = dir.resolve("arm.xml");
        vm.save(f);
        Job j = vm.applyTo(Job.empty(JobTask.ROBOT));
        assertEquals(f.toAbsolutePath().toString(), j.robot().orElseThrow().robot());
        Robot back = RobotFiles.load(j.robot().orElseThrow().robot());
        double[] q = {1, 2, 3, 4, 5, 6};
        assertTrue(back.forward(q).eq(vm.edited().orElseThrow().forward(q), TOL));
        assertEquals("my-arm", back.name());
    }

    @Test
    void anEditedBuiltInIsKeptUnderItsOwnNameAndContent() throws Exception {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(0, RobotViewModel.D, "360");
        String choice = vm.keepIn(dir);
        assertTrue(Files.isRegularFile(Path.of(choice)), choice);
        assertTrue(Path.of(choice).getFileName().toString().startsWith("irb140-edited-"), choice);
        assertEquals("irb140-edited", RobotFiles.load(choice).name());
        assertFalse(vm.isModified());
        RobotViewModel other = new RobotViewModel();
        other.setCell(0, RobotViewModel.D, "360");
        assertEquals(choice, other.keepIn(dir));
    }

    @Test
    void anUnknownRobotIsRefusedAndTheShownOneKept() {
        RobotViewModel vm = new RobotViewModel();
        assertThrows(CamInputException.class, () -> vm.choose("no-such-robot"));
        assertEquals("irb140", vm.robot().name());
    }

    @Test
    void theChoiceIsWrittenIntoTheJobsRobotSettings() throws CamInputException {
        RobotViewModel vm = new RobotViewModel();
        vm.choose("tricept806");
        Job j = vm.applyTo(Job.empty(JobTask.ROBOT));
        assertEquals("tricept806", j.robot().orElseThrow().robot());
        assertTrue(vm.fromJob(j).isEmpty());
    }

    @Test
    void theSymbolicForwardKinematicsIsWrittenInTheJointVariables() {
        String text = RobotViewModel.symbolic(Robots.adeptOne());
        assertTrue(text.contains("px = "), text);
        assertTrue(text.contains("q1"), text);
    }

    @Test
    void theSymbolicForwardKinematicsFollowsTheEditedTable() {
        RobotViewModel vm = new RobotViewModel();
        vm.setCell(0, RobotViewModel.A, "71");
        String text = RobotViewModel.symbolic(vm.edited().orElseThrow());
        assertTrue(text.contains("71*"), text);
        assertFalse(RobotViewModel.symbolic(Robots.irb140()).contains("71*"));
    }

    @Test
    void theExportHoldsTheForwardKinematicsAndTheJacobian() {
        String text = RobotViewModel.symbolicExport(Robots.adeptOne());
        assertAll(
                () -> assertTrue(text.contains("px = "), text),
                () -> assertTrue(text.contains("J_vx_q1 = "), text),
                () -> assertTrue(text.contains("J_wz_q4 = "), text),
                // the prismatic q3 moves the flange along the fixed vertical: no turn, no x speed
                () -> assertTrue(text.contains("J_wz_q3 = 0\n"), text),
                () -> assertTrue(text.contains("J_vx_q3 = 0\n"), text));
    }

    @Test
    void theSpindleAndToolLengthGoIntoTheJobAndABadTextKeepsTheLastGoodValue() {
        RobotViewModel vm = new RobotViewModel();
        vm.setSpindle("0,0,150");
        vm.setToolLength("50");
        Job j = vm.applyToolTo(Job.empty(JobTask.ROBOT));
        var r = j.robot().orElseThrow();
        assertEquals(150, r.spindle().orElseThrow().zMm());
        assertEquals(50, r.toolLengthMm().getAsDouble());

        vm.setToolLength("5x");
        assertEquals(
                "Tool length: '5x' is not a number (mm)", vm.toolLengthProblem().orElseThrow());
        vm.setToolLength("-3");
        assertTrue(
                vm.toolLengthProblem().orElseThrow().startsWith("Tool length: expected "),
                vm.toolLengthProblem().get());
        vm.setSpindle("0,0");
        assertTrue(
                vm.spindleProblem().orElseThrow().startsWith("Spindle: expected 3 to 6"),
                vm.spindleProblem().get());
        // the job keeps the last good values while a field is wrong
        var kept = vm.applyToolTo(j).robot().orElseThrow();
        assertEquals(150, kept.spindle().orElseThrow().zMm());
        assertEquals(50, kept.toolLengthMm().getAsDouble());

        // empty fields: the robot file's tool frame and each STEP-NC tool's own length
        vm.setSpindle("");
        vm.setToolLength("");
        var none = vm.applyToolTo(j).robot().orElseThrow();
        assertTrue(none.spindle().isEmpty() && none.toolLengthMm().isEmpty());
    }

    @Test
    void aJobsToolIsShownInTheFields() {
        RobotViewModel vm = new RobotViewModel();
        RobotViewModel other = new RobotViewModel();
        other.setSpindle("0,0,150,0,90,0");
        other.setToolLength("50");
        Job j = other.applyToolTo(Job.empty(JobTask.ROBOT));
        assertTrue(vm.loadTool(j));
        assertEquals("0,0,150,0,90,0", vm.spindleText());
        assertEquals("50", vm.toolLengthText());
        assertFalse(vm.loadTool(j), "the same tool again changes nothing");
    }
}
