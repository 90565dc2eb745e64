package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Vec2;
import org.fresa.grading.GradingResult;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Grading tab's state, without a screen. */
class GradingViewModelTest {

    private static final Path SOLE = Path.of("samples/grading/sole-40.contour");

    @TempDir
    Path dir;

    @Test
    void gradingTheSampleFillsTheTableWithOneRowPerSize() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        GradingResult r = vm.grade();
        vm.setResult(r);
        List<List<String>> rows = vm.tableRows();
        assertAll(
                () -> assertEquals(9, rows.size()),
                () -> assertEquals("36", rows.get(0).get(0)),
                () -> assertEquals("243.360", rows.get(0).get(1)),
                () -> assertEquals("96.640", rows.get(8).get(2)),
                () -> assertEquals(GradingViewModel.COLUMNS.size(), rows.get(0).size()));
        PlotScene s = vm.scene();
        assertTrue(s.layers().stream().filter(l -> l.name().startsWith("size ")).count() >= 9);
        assertTrue(s.layers().stream().anyMatch(l -> l.name().equals("origin")));
    }

    @Test
    void aWidthFittingShowsTheLastGirthsOfTable31() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        vm.setResult(vm.grade());
        int girth = GradingViewModel.COLUMNS.indexOf("Last girth (mm)");
        assertEquals("", vm.tableRows().get(0).get(girth), "no fitting chosen");
        assertEquals(List.of("", "A", "B", "C", "D", "E", "F", "G", "H"), GradingViewModel.FITTINGS);
        vm.setFitting("D");
        List<List<String>> rows = vm.tableRows();
        // Brazilian 36 is French 38: fitting D 210.0 mm; Brazilian 40 is French 42: 227.0; 41 is beyond the table
        assertAll(
                () -> assertEquals("36", rows.get(0).get(0)),
                () -> assertEquals("210.0", rows.get(0).get(girth)),
                () -> assertEquals("40", rows.get(4).get(0)),
                () -> assertEquals("227.0", rows.get(4).get(girth)),
                () -> assertEquals("", rows.get(5).get(girth)));
        assertThrows(IllegalArgumentException.class, () -> vm.setFitting("K"));
    }

    @Test
    void designatedHeelElementsAreDrawnAndGoIntoTheJob() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        vm.setHeelElements("1,5");
        vm.setHeelGroup("3");
        PlotScene s = vm.scene();
        assertEquals(
                2,
                s.layers().stream()
                        .filter(l -> l.name().equals("heel elements 1,5"))
                        .findFirst()
                        .orElseThrow()
                        .curves()
                        .size());
        var job = vm.applyTo(org.fresa.job.Job.empty(org.fresa.job.JobTask.GRADE));
        var h = job.grading().orElseThrow().coordination().orElseThrow();
        assertAll(() -> assertEquals("1,5", h.heelElements()), () -> assertEquals(3, h.groupSize()));
        GradingViewModel again = new GradingViewModel();
        again.load(job);
        assertEquals("1,5", again.heelElements());
        // graded: 42 to 44 share the heel of 43
        GradingResult r = vm.grade();
        assertEquals(43, r.sizes().get(r.sizes().size() - 1).heelSize().getAsDouble(), 0);
        vm.setHeelElements("1,x");
        CamInputException e = assertThrows(CamInputException.class, vm::settings);
        assertTrue(e.getMessage().contains("Heel elements"), e.getMessage());
    }

    @Test
    void aPickedOriginIsUsedAndClearsTheLastResult() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        vm.setResult(vm.grade());
        vm.pickOrigin(new Vec2(1.23456, 100.0004));
        assertAll(
                () -> assertEquals("1.235,100", vm.origin()),
                () -> assertTrue(vm.result().isEmpty()));
        GradingResult r = vm.grade();
        assertEquals(new Vec2(1.235, 100), r.frame().origin());
    }

    @Test
    void badFieldsAreNamedInTheMessage() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        assertThrows(CamInputException.class, vm::settings);
        vm.openOutline(SOLE);
        vm.setShrinkage("2 %");
        CamInputException e = assertThrows(CamInputException.class, vm::settings);
        assertTrue(e.getMessage().startsWith("Shrinkage"), e.getMessage());
        vm.setShrinkage("0.02");
        vm.setOrigin("1;2");
        assertTrue(
                assertThrows(CamInputException.class, vm::settings).getMessage().startsWith("Origin"));
    }

    @Test
    void settingsGoIntoTheJobAndComeBack() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        vm.setSystem(org.fresa.grading.SizeSystem.PARIS);
        vm.setBaseSize("42");
        vm.setSizes("40-44");
        vm.setHalfSizes(true);
        vm.setLengthStep("6.67");
        vm.setOrigin("0,0");
        vm.setShrinkage("0.02");
        vm.setShrinkageMode(org.fresa.grading.ShrinkageMode.ADDITIVE);
        Job job = vm.applyTo(Job.empty(JobTask.POCKET));
        // the grading settings only: what the job runs stays the planner's choice
        assertEquals(JobTask.POCKET, job.task());
        GradingViewModel other = new GradingViewModel();
        other.load(job);
        assertAll(
                () -> assertEquals(org.fresa.grading.SizeSystem.PARIS, other.system()),
                () -> assertEquals("42", other.baseSize()),
                () -> assertEquals("40-44", other.sizes()),
                () -> assertTrue(other.halfSizes()),
                () -> assertEquals("6.67", other.lengthStep()),
                () -> assertEquals("", other.widthStep()),
                () -> assertEquals("0,0", other.origin()),
                () -> assertEquals("0.02", other.shrinkage()),
                () -> assertEquals(org.fresa.grading.ShrinkageMode.ADDITIVE, other.shrinkageMode()),
                () -> assertEquals(1, other.outline().size()));
    }

    @Test
    void exportWritesTheFilesOfEverySize() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        vm.openOutline(SOLE);
        vm.setSizes("39-41");
        TaskOutcome o = vm.export(dir, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus());
        assertTrue(Files.exists(dir.resolve("size-41.dxf")));
        assertTrue(Files.exists(dir.resolve("grading.png")));
    }

    @Test
    void aRangeTheGradingRefusesMarksTheSizesInItsWordsBeforeGradeRuns() throws Exception {
        GradingViewModel vm = new GradingViewModel();
        assertEquals(java.util.Set.of(GradingViewModel.OUTLINE), vm.problems().keySet());
        vm.openOutline(SOLE);
        assertTrue(vm.problems().isEmpty(), vm.problems().toString());
        vm.setSizes("44-36");
        assertEquals(
                java.util.Map.of(GradingViewModel.SIZES, "Sizes: expected sizes A-B with A <= B, found '44-36'."),
                vm.problems());
        assertTrue(vm.typedSettings().isEmpty());
        vm.setSizes("36-44");
        vm.setBaseSize("4O");
        vm.setShrinkage("0,02");
        vm.setOrigin("10;20");
        var p = vm.problems();
        assertEquals("Base size: '4O' is not a number.", p.get(GradingViewModel.BASE_SIZE));
        assertEquals(
                "Shrinkage: '0,02' is not a number (decimals take a point: 0.02).", p.get(GradingViewModel.SHRINKAGE));
        assertTrue(p.get(GradingViewModel.ORIGIN).startsWith("Origin X,Y: expected X,Y in mm"), p.toString());
        vm.setBaseSize("40");
        vm.setShrinkage("0.7");
        vm.setOrigin("");
        assertEquals(java.util.Set.of(GradingViewModel.SHRINKAGE), vm.problems().keySet());
        assertTrue(
                vm.problems().get(GradingViewModel.SHRINKAGE).startsWith("Shrinkage: shrinkage must be a fraction"),
                vm.problems().toString());
        for (String m : vm.problems().values()) {
            assertTrue(!m.contains("--") && !m.contains("Exception"), m);
        }
        vm.setShrinkage("0.02");
        assertEquals(0.02, vm.typedSettings().orElseThrow().shrinkage());
    }
}
