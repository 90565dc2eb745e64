package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.io.OutputFolder;
import org.fresa.job.Job;
import org.fresa.job.JobRunner;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.sole.Foot;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SoleViewModelTest {

    @Test
    void everyMacroOfTheLibraryHasAPreviewOfItsThesisCall() {
        SoleViewModel vm = new SoleViewModel();
        assertEquals(18 + 5, vm.macros().size(), "the thesis's 18 and the special designs F-J");
        for (String m : vm.macros()) {
            vm.selectMacro(m);
            assertTrue(vm.parametersText().startsWith(m), m);
            PlotScene s = vm.preview();
            if (m.equals("LOGO")) {
                // its outlines come from the job's drawing: the library says so instead of a preview
                assertTrue(s.title().contains("drawing") && vm.parametersText().contains("group J"), s.title());
                continue;
            }
            assertEquals(m, s.title());
            boolean aux = m.equals("PRIM") || m.equals("NOVO");
            assertEquals(aux, s.layers().get(0).curves().isEmpty(), m);
        }
    }

    @Test
    void theSampleJobGivesItsSizesAndAPlotPerSizeAndFoot() throws Exception {
        SoleViewModel vm = new SoleViewModel();
        vm.load(JobXml.read(Path.of("samples/jobs/sole-men40.xml")));
        assertEquals("", vm.problem());
        assertEquals(List.of("38", "39", "40", "41", "42"), vm.sizes());
        assertEquals("40", vm.size());
        vm.selectSize("42");
        vm.selectFoot(Foot.LEFT);
        PlotScene s = vm.scene();
        assertTrue(s.title().contains("42") && s.title().contains("left"));
        assertFalse(s.layers().stream()
                .filter(l -> l.style() == PlotScene.Style.FEED)
                .findFirst()
                .orElseThrow()
                .curves()
                .isEmpty());
    }

    @Test
    void aCavityToolTooLargeForASizeIsSaidWhenTheSizeIsShown(@TempDir Path dir) throws Exception {
        SoleViewModel vm = new SoleViewModel();
        vm.load(JobXml.read(Path.of("samples/jobs/sole-men40.xml")));
        assertTrue(vm.sizeProblem().isEmpty(), vm.sizeProblem().toString());
        // a 55 mm cavity tool: the toe arc of size 40 (54.7 mm across at the base size, graded
        // with the shrinkage) is too tight for its centre, as Generate says
        String xml = java.nio.file.Files.readString(Path.of("samples/jobs/sole-men40.xml"))
                .replace("../", Path.of("samples").toAbsolutePath() + "/")
                .replace("cavityTool=\"em25\"", "cavityTool=\"em56\"")
                .replace(
                        "<tool id=\"em25\"",
                        "<tool id=\"em56\" number=\"9\" diameterMm=\"56\" spindleRpm=\"1000\""
                                + " feedMmPerMin=\"200\" plungeFeedMmPerMin=\"80\"/>\n    <tool id=\"em25\"");
        Path job = java.nio.file.Files.writeString(dir.resolve("sole.xml"), xml);
        vm.load(JobXml.read(job));
        assertEquals("", vm.problem());
        vm.selectSize("40");
        String said = vm.sizeProblem().orElseThrow();
        assertTrue(said.startsWith("size 40: the 56.000 mm cavity tool is not smaller than the outline's arc 8"), said);
        assertTrue(said.endsWith("(Generate refuses this size)"), said);
    }

    @Test
    void aJobWithoutSoleSettingsSaysSo() {
        SoleViewModel vm = new SoleViewModel();
        vm.load(Job.empty(JobTask.SOLE));
        assertTrue(vm.problem().contains("no sole settings"));
        assertTrue(vm.sizes().isEmpty());
    }

    private static final double EPS = 1e-6;

    @Test
    void theMouldBlockViewShowsThePairWhereTheEquationsPutIt() throws Exception {
        SoleViewModel vm = sample();
        PlotScene s = vm.pairScene();
        assertTrue(
                s.title().contains("right ZP (296.200, 77.880)") && s.title().contains("left ZP (153.800, 77.880)"),
                s.title());
        Box2 right = bounds(s, "right outline");
        Box2 left = bounds(s, "left outline");
        // the patterns' inner tangents stand D = 20 apart about x = DLM + E = 225, widened by the
        // job's rounded XTANP 60 against the outline's 59.72 (times 1.02 on each side)
        double gap = 20 + 2 * (60 - 59.723) * 1.02;
        assertEquals(gap, right.minX() - left.maxX(), 0.02);
        assertEquals(450, right.minX() + left.maxX(), 1e-6, "mirror images about x = 225");
        // CM 350 from S 11, the pattern of 275.4 mm centred: margins (350 - 275.4) / 2 = 37.3 at both ends
        assertEquals(11 + (350 - 275.4) / 2, right.minY(), 0.02);
        Box2 block = bounds(s, "block edges y = S, S + CM; mirror line x = DLM + E");
        assertEquals(11, block.minY(), 1e-9);
        assertEquals(361, block.maxY(), 1e-9);
        assertTrue(
                bounds(s, "left tread").width() > 50 && bounds(s, "left tread").maxX() < 225,
                "the tread is drawn, left of the mirror line");
    }

    private static Box2 bounds(PlotScene s, String layer) {
        Box2 b = null;
        for (Curve2 c : s.layers().stream()
                .filter(l -> l.name().equals(layer))
                .findFirst()
                .orElseThrow()
                .curves()) {
            b = b == null ? c.bounds() : b.union(c.bounds());
        }
        return b;
    }

    private static SoleViewModel sample() throws Exception {
        SoleViewModel vm = new SoleViewModel();
        vm.load(JobXml.read(Path.of("samples/jobs/sole-men40.xml")));
        assertEquals("", vm.problem());
        return vm;
    }

    /** Every tread feed move of the scene starts and ends inside its outline. */
    private static void assertTreadInsideOutline(PlotScene s) {
        var outline = s.layers().stream()
                .filter(l -> l.style() == PlotScene.Style.OUTLINE)
                .findFirst()
                .orElseThrow();
        Contour c = Contour.of(outline.curves(), Tolerance.DEFAULT);
        for (PlotScene.Layer l : s.layers()) {
            if (l.style() != PlotScene.Style.FEED) {
                continue;
            }
            for (Curve2 k : l.curves()) {
                for (Vec2 v : List.of(k.start(), k.end())) {
                    assertTrue(c.contains(v, Tolerance.DEFAULT), "outside the outline: " + v);
                }
            }
        }
    }

    private static long feedCurves(PlotScene s) {
        return s.layers().stream()
                .filter(l -> l.style() == PlotScene.Style.FEED)
                .mapToLong(l -> l.curves().size())
                .sum();
    }

    @Test
    void placingAFigurePutsTheCentreOfItsGroovesOnThePointAndAddsADesign() throws Exception {
        SoleViewModel vm = sample();
        int before = vm.designs().size();
        long feedsBefore = feedCurves(vm.scene());
        vm.selectMacro("SUB4");
        assertEquals(Optional.empty(), vm.place(Vec2.of(10, 120)));
        assertEquals(before + 1, vm.designs().size());
        assertEquals(before, vm.selected());
        assertEquals("SUB4 1", vm.designs().get(before).name());
        // the plot of the base size carries the 2 % shrinkage; the job frame does not
        Vec2 at = vm.position(before);
        assertAll(() -> assertEquals(10 / 1.02, at.x(), EPS), () -> assertEquals(120 / 1.02, at.y(), EPS));
        PlotScene s = vm.scene();
        assertTrue(feedCurves(s) > feedsBefore, "the new ring is cut");
        assertTreadInsideOutline(s);
    }

    @Test
    void continuousFiguresAreNotPlacedOnTheirOwn() throws Exception {
        SoleViewModel vm = sample();
        vm.selectMacro("SUB7B");
        assertTrue(vm.place(Vec2.of(0, 100)).orElseThrow().contains("carries on a groove"));
        assertEquals(8, vm.designs().size());
    }

    @Test
    void movingAndNudgingShiftThePlacedFigureInMillimetres() throws Exception {
        SoleViewModel vm = sample();
        vm.selectMacro("SUB4");
        vm.place(Vec2.of(10, 120));
        int i = vm.selected();
        assertEquals(Optional.empty(), vm.moveSelectedTo(Vec2.of(-5, 60)));
        assertEquals(-5 / 1.02, vm.position(i).x(), EPS);
        assertEquals(60 / 1.02, vm.position(i).y(), EPS);
        assertEquals(Optional.empty(), vm.moveSelectedBy(1, 0));
        assertEquals(Optional.empty(), vm.moveSelectedBy(0, -10));
        assertAll(
                () -> assertEquals(-5 / 1.02 + 1, vm.position(i).x(), EPS),
                () -> assertEquals(60 / 1.02 - 10, vm.position(i).y(), EPS));
        assertTreadInsideOutline(vm.scene());
    }

    @Test
    void aPointOnTheLeftFootOfAnotherSizeMapsBackToTheJobFrame() throws Exception {
        SoleViewModel vm = sample();
        vm.selectSize("42");
        vm.selectFoot(Foot.LEFT);
        vm.selectMacro("SUB4");
        vm.place(Vec2.of(10, 120));
        // mirrored back about x = 0 and ungraded (size 42 is longer and wider than 40)
        Vec2 at = vm.position(vm.selected());
        assertTrue(at.x() < -9 && at.x() > -11, at.toString());
        assertTrue(at.y() < 120 && at.y() > 110, at.toString());
        assertTreadInsideOutline(vm.scene());
    }

    @Test
    void aDragOnTheLeftFootMovesTheFigureTheMirroredWay() throws Exception {
        SoleViewModel vm = sample();
        vm.selectFoot(Foot.LEFT);
        Vec2 d = vm.deltaToJobFrame(Vec2.of(5, 2));
        assertAll(() -> assertEquals(-5 / 1.02, d.x(), EPS), () -> assertEquals(2 / 1.02, d.y(), EPS));
    }

    @Test
    void aFigureUnderThePointIsSelectedAndNothingElsewhere() throws Exception {
        SoleViewModel vm = sample();
        assertTrue(vm.selectAt(Vec2.of(-32, 161)));
        assertEquals("inner circle", vm.designs().get(vm.selected()).name());
        assertTrue(vm.scene().layers().stream().anyMatch(l -> l.style() == PlotScene.Style.WARNING));
        assertFalse(vm.selectAt(Vec2.of(500, 500)));
        assertEquals(-1, vm.selected());
    }

    @Test
    void patternsOtherThanCopiesAreNotMovedButSaySo() throws Exception {
        SoleViewModel vm = sample();
        vm.select(3);
        assertTrue(vm.moveSelectedBy(1, 0).orElseThrow().contains("linear pattern"));
        vm.select(0);
        Vec2 was = vm.position(0);
        assertEquals(Optional.empty(), vm.moveSelectedBy(2, 3));
        assertEquals(was.x() + 2, vm.position(0).x(), EPS);
        assertEquals(org.fresa.sole.PatternKind.COPIES, vm.designs().get(0).pattern());
    }

    @Test
    void deletingRemovesTheSelectedDesignFromTheJobAndThePlot() throws Exception {
        SoleViewModel vm = sample();
        long feeds = feedCurves(vm.scene());
        vm.select(0);
        assertEquals(Optional.empty(), vm.deleteSelected());
        assertEquals(7, vm.designs().size());
        assertFalse(vm.designs().stream().anyMatch(d -> d.name().equals("inner circle")));
        assertEquals(-1, vm.selected());
        assertTrue(feedCurves(vm.scene()) < feeds);
        assertTrue(vm.deleteSelected().orElseThrow().contains("Select"));
    }

    @Test
    void parametersAreListedWithUnitsAndEditedValuesRecomputeTheTread() throws Exception {
        SoleViewModel vm = sample();
        vm.select(0);
        assertEquals(
                List.of(
                        new SoleViewModel.Parameter("XC", "mm", "-32"),
                        new SoleViewModel.Parameter("YC", "mm", "161"),
                        new SoleViewModel.Parameter("RA", "mm", "5"),
                        new SoleViewModel.Parameter("XA4", "mm", "-37"),
                        new SoleViewModel.Parameter("YA4", "mm", "161"),
                        new SoleViewModel.Parameter("XB4", "mm", "-27"),
                        new SoleViewModel.Parameter("YB4", "mm", "161")),
                vm.parameters());
        double w = selectedBox(vm).width();
        assertEquals(Optional.empty(), vm.setParameter("XA4", "-40"));
        assertEquals(Optional.empty(), vm.setParameter("XB4", "-24"));
        assertEquals(Optional.empty(), vm.setParameter("RA", "8"));
        assertEquals("8", vm.parameters().get(2).value());
        assertTrue(vm.designs().get(0).figures().get(0).params().contains("RA=8"));
        // the ring's tool-centre diameter grows by 2 * 3 mm (times the base size's 2 % shrinkage)
        assertEquals((w / 1.02 + 6) * 1.02, selectedBox(vm).width(), 1e-3);
        assertTreadInsideOutline(vm.scene());
    }

    private static Box2 selectedBox(SoleViewModel vm) {
        var l = vm.scene().layers().stream()
                .filter(x -> x.style() == PlotScene.Style.WARNING)
                .findFirst()
                .orElseThrow();
        Box2 b = l.curves().get(0).bounds();
        for (Curve2 c : l.curves()) {
            b = b.union(c.bounds());
        }
        return b;
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            RA, abc, 'RA: expected a number in mm, found ''abc'''
            RA, -2, RA must be > 0
            RA, 1e9, at most 1000000
            QQ, 1, has no parameter QQ
            """)
    void badParameterValuesSayWhyAndLeaveTheJobUnchanged(String name, String value, String why) throws Exception {
        SoleViewModel vm = sample();
        vm.select(0);
        Job before = vm.job().orElseThrow();
        String got = vm.setParameter(name, value).orElseThrow();
        assertTrue(got.contains(why), got);
        assertEquals(before, vm.job().orElseThrow());
    }

    @Test
    void aValueThatGivesNoPathIsRefused() throws Exception {
        SoleViewModel vm = sample();
        vm.select(0);
        // the start point must lie outside the ring (-32, 161) R5 for a tangent
        String got = vm.setParameter("XA4", "-33").orElseThrow();
        assertTrue(got.startsWith("SUB4") && got.contains("inside the circle"), got);
    }

    @Test
    void theEditedJobSavedAndRunGivesTheFilesOfTheTab(@TempDir Path dir) throws Exception {
        SoleViewModel vm = sample();
        vm.selectMacro("SUB4");
        assertEquals(Optional.empty(), vm.place(Vec2.of(10, 120)));
        assertEquals(Optional.empty(), vm.setParameter("RA", "6"));
        vm.select(0);
        assertEquals(Optional.empty(), vm.moveSelectedBy(1, 1));
        TaskOutcome tab = vm.generate(dir.resolve("tab"), ProgressMonitor.NONE);
        Path saved = dir.resolve("edited.xml");
        Job job = vm.job().orElseThrow();
        JobXml.write(job, saved);
        Job read = JobXml.read(saved);
        assertEquals(
                job.sole().orElseThrow().designs(), read.sole().orElseThrow().designs());
        TaskOutcome run = JobRunner.run(read, new OutputFolder(dir.resolve("run")), ProgressMonitor.NONE);
        assertEquals(0, tab.exitStatus());
        assertEquals(tab.exitStatus(), run.exitStatus());
        List<String> names;
        try (var l = Files.list(dir.resolve("tab"))) {
            names = l.map(p -> p.getFileName().toString()).sorted().toList();
        }
        assertTrue(names.contains("tread-40-right.ngc") && names.contains("cavity-42-left.ngc"), names.toString());
        for (String n : names) {
            if (n.endsWith(".ngc") || n.endsWith(".csv")) {
                assertEquals(
                        Files.readString(dir.resolve("tab").resolve(n)),
                        Files.readString(dir.resolve("run").resolve(n)),
                        n);
            }
        }
        // the edits are in the programs: the tread differs from the sample's
        JobRunner.run(
                JobXml.read(Path.of("samples/jobs/sole-men40.xml")),
                new OutputFolder(dir.resolve("plain")),
                ProgressMonitor.NONE);
        assertFalse(Files.readString(dir.resolve("plain/tread-40-right.ngc"))
                .equals(Files.readString(dir.resolve("tab/tread-40-right.ngc"))));
    }
}
