package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.fresa.chart.PlotScene;
import org.fresa.job.CuttingService;
import org.fresa.job.ProgressMonitor;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;

class CuttingViewModelTest {

    @Test
    void withoutADrawingTheSettingsAskForOne() {
        CuttingViewModel vm = new CuttingViewModel();
        assertThrows(CamInputException.class, vm::settings);
        assertEquals(0, vm.scene().layers().size());
    }

    @Test
    void aKerfThatIsNotANumberIsNamed() {
        CuttingViewModel vm = new CuttingViewModel();
        vm.setDrawing(Path.of("samples/cutting/plate.dxf"));
        vm.setKerfMm("two");
        CamInputException e = assertThrows(CamInputException.class, vm::settings);
        assertTrue(e.getMessage().contains("Kerf (mm)"), e.getMessage());
    }

    @Test
    void theSamplePlateShowsPartsHolesOpenChainsRapidsAndOrderNumbers() throws Exception {
        CuttingViewModel vm = new CuttingViewModel();
        vm.setDrawing(Path.of("samples/cutting/plate.dxf"));
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        PlotScene s = vm.scene();
        assertTrue(layer(s, "parts").style() == PlotScene.Style.PART
                && !layer(s, "parts").curves().isEmpty());
        assertTrue(!layer(s, "holes").curves().isEmpty());
        assertEquals(PlotScene.Style.WARNING, layer(s, "open chains").style());
        assertEquals(1, layer(s, "open chains").curves().size());
        assertEquals(10, layer(s, "rapids").curves().size());
        assertEquals(10, s.labels().size());
        assertTrue(vm.totals().startsWith("10 contours (2 outer, 8 holes, 1 open), 10 pierces"), vm.totals());
        assertTrue(vm.program().contains("M3 S1"));
    }

    @Test
    @org.fresa.testing.CorpusCheck
    void everyWarningOfADrawingIsListedWithItsPlace() throws Exception {
        CuttingViewModel vm = new CuttingViewModel();
        vm.setDrawing(org.fresa.testing.TestInputs.DXF_CORPUS.resolve("dxf2gcode/pumpenteile.dxf"));
        CuttingService.Result r = CuttingService.compute(vm.settings(), ProgressMonitor.NONE);
        vm.setResult(r);
        WarningList w = vm.warnings();
        java.util.List<?> summary =
                (java.util.List<?>) CuttingService.summary(r).get("warnings");
        org.junit.jupiter.api.Assertions.assertAll(
                // 32 on the drawing in 2026-12 (18 contours not cut); the tab listed 3 of them
                () -> assertTrue(w.size() > 20, w.size() + " warnings"),
                () -> assertEquals(
                        summary, w.all().stream().map(WarningList.Warning::text).toList()),
                () -> assertEquals(
                        java.util.Optional.of(org.fresa.geom.Vec2.of(23, 109)),
                        w.all().stream()
                                .filter(x -> x.text().startsWith("open chain"))
                                .findFirst()
                                .orElseThrow()
                                .place()),
                () -> assertEquals(java.util.Optional.empty(), w.all().get(0).place()),
                () -> assertTrue(w.heading().startsWith(w.size() + " warnings"), w.heading()));
    }

    @Test
    void aJobSavedFromTheTabRunsWithFresaRun(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        CuttingViewModel vm = new CuttingViewModel();
        vm.setDrawing(Path.of("samples/cutting/plate.dxf").toAbsolutePath());
        vm.setProcess(org.fresa.cutting.CutProcess.LASER);
        vm.setCompensation(org.fresa.cutting.KerfCompensation.CONTROLLER);
        vm.setOuterDirection(org.fresa.cutting.CutSense.CCW);
        vm.setHoleDirection(org.fresa.cutting.CutSense.CW);
        vm.setOvercutMm("0.5");
        vm.setAvoidCutParts(false);
        org.fresa.job.Job job = vm.applyTo(org.fresa.job.Job.empty(org.fresa.job.JobTask.CUT));
        Path file = dir.resolve("cut.xml");
        org.fresa.job.JobXml.write(job, file);
        org.fresa.job.Job read = org.fresa.job.JobXml.read(file);
        assertEquals(job.cutting(), read.cutting());

        CuttingViewModel again = new CuttingViewModel();
        again.load(read);
        assertEquals(vm.settings(), again.settings());

        java.io.StringWriter err = new java.io.StringWriter();
        int status = org.fresa.app.cli.FresaCommand.execute(
                new java.io.PrintWriter(new java.io.StringWriter(), true),
                new java.io.PrintWriter(err, true),
                "run",
                file.toString(),
                "--out",
                dir.resolve("out").toString());
        assertTrue(status <= 1, err.toString());
        String program = java.nio.file.Files.readString(dir.resolve("out").resolve("program.ngc"));
        assertTrue(program.contains("G42") && program.contains("M64 P0"), program);
    }

    /**
     * The planner moves a cut and a start point in the tab; the job saved then, run by
     * {@code fresa run}, writes byte for byte the program the tab shows.
     */
    @Test
    void anOrderEditedInTheTabIsSavedAndRunsToTheProgramTheTabShows(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        CuttingViewModel vm = new CuttingViewModel();
        vm.setDrawing(Path.of("samples/cutting/plate.dxf").toAbsolutePath());
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        java.util.List<CuttingViewModel.CutRow> auto = vm.cutList();
        assertEquals(10, auto.size());
        // a part may not move up over its own hole (the part's last hole comes just before it)
        int part = java.util.stream.IntStream.range(1, auto.size())
                .filter(i -> !auto.get(i).contour().contains("hole")
                        && auto.get(i - 1).contour().startsWith(auto.get(i).contour() + " hole"))
                .findFirst()
                .orElseThrow();
        java.util.Optional<String> refused = vm.moveCut(part, -1);
        assertTrue(
                refused.isPresent()
                        && refused.get()
                                .startsWith(auto.get(part - 1).contour() + " lies inside "
                                        + auto.get(part).contour()),
                refused.toString());
        assertTrue(vm.cutOrder().isEmpty(), "a refused move leaves the order alone");
        // a hole moved up over another hole of the same part is allowed
        int hole = java.util.stream.IntStream.range(1, auto.size())
                .filter(i -> auto.get(i).contour().contains("hole")
                        && auto.get(i - 1).contour().contains("hole"))
                .findFirst()
                .orElseThrow();
        assertEquals(java.util.Optional.empty(), vm.moveCut(hole, -1));
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        assertEquals(auto.get(hole).contour(), vm.cutList().get(hole - 1).contour());
        assertEquals(auto.get(hole - 1).contour(), vm.cutList().get(hole).contour());
        // the first cut started 5 mm from where it starts now: the start moves onto its path
        org.fresa.geom.Vec2 was = vm.cutList().get(0).startMm();
        assertEquals(java.util.Optional.empty(), vm.setStart(0, was.plus(org.fresa.geom.Vec2.of(5, 0))));
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        CuttingViewModel.CutRow first = vm.cutList().get(0);
        assertTrue(first.startAsked() && first.startMm().distance(was) > 1e-3, first.toString());
        String shown = vm.program();

        org.fresa.job.Job job = vm.applyTo(org.fresa.job.Job.empty(org.fresa.job.JobTask.CUT));
        Path file = dir.resolve("cut.xml");
        org.fresa.job.JobXml.write(job, file);
        assertTrue(java.nio.file.Files.readString(file).contains("<cutOrder>"));
        CuttingViewModel again = new CuttingViewModel();
        again.load(org.fresa.job.JobXml.read(file));
        assertEquals(vm.settings(), again.settings());
        java.io.StringWriter err = new java.io.StringWriter();
        int status = org.fresa.app.cli.FresaCommand.execute(
                new java.io.PrintWriter(new java.io.StringWriter(), true),
                new java.io.PrintWriter(err, true),
                "run",
                file.toString(),
                "--out",
                dir.resolve("out").toString());
        assertTrue(status <= 1, err.toString());
        assertEquals(shown, java.nio.file.Files.readString(dir.resolve("out").resolve("program.ngc")));
        // Reset: the automatic order and starts again
        vm.resetOrder();
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        assertEquals(auto, vm.cutList());
    }

    @Test
    void aStartIsTypedAsTwoNumbers() {
        assertEquals(
                java.util.Optional.of(org.fresa.geom.Vec2.of(12.5, -3)), CuttingViewModel.parseStart(" 12.5, -3 "));
        assertEquals(java.util.Optional.of(org.fresa.geom.Vec2.of(1, 2)), CuttingViewModel.parseStart("1 2"));
        assertEquals(java.util.Optional.empty(), CuttingViewModel.parseStart("1"));
        assertEquals(java.util.Optional.empty(), CuttingViewModel.parseStart("a, b"));
        assertEquals(java.util.Optional.empty(), CuttingViewModel.parseStart("NaN, 1"));
    }

    private static PlotScene.Layer layer(PlotScene s, String name) {
        return s.layers().stream()
                .filter(l -> l.name().equals(name))
                .findFirst()
                .orElseThrow();
    }

    @Test
    void aBadFieldIsNamedInThePlannersWordsAndTheSettingsWaitForAGoodOne() {
        CuttingViewModel vm = new CuttingViewModel();
        assertEquals(
                java.util.List.of(CuttingViewModel.DRAWING),
                java.util.List.copyOf(vm.problems().keySet()));
        vm.setDrawing(Path.of("samples/cutting/plate.dxf"));
        assertTrue(vm.problems().isEmpty(), vm.problems().toString());
        vm.setKerfMm("1,5");
        vm.setLeadInMm("-3");
        vm.setOvercutMm("");
        java.util.Map<String, String> p = vm.problems();
        assertEquals("Kerf (mm): '1,5' is not a number (decimals take a point: 1.5).", p.get(CuttingViewModel.KERF));
        assertTrue(
                p.get(CuttingViewModel.LEAD_IN).startsWith("Lead-in (mm): expected a number from 0 to "),
                p.get(CuttingViewModel.LEAD_IN));
        assertEquals("Overcut (mm): a number is needed.", p.get(CuttingViewModel.OVERCUT));
        for (String m : p.values()) {
            assertTrue(!m.contains("--") && !m.contains("Exception") && !m.contains("kerfMm"), m);
        }
        assertTrue(vm.typedSettings().isEmpty());
        vm.setKerfMm("1.5");
        vm.setLeadInMm("3");
        vm.setOvercutMm("0");
        assertEquals(1.5, vm.typedSettings().orElseThrow().kerfMm());
    }

    @Test
    void whatTheTabHasNoFieldForStaysAsTheJobHasIt() throws Exception {
        org.fresa.job.Job job = org.fresa.job.JobXml.read(Path.of("samples/jobs/cut-plate.xml"));
        org.fresa.job.JobSettings.CuttingSettings c = job.cutting().orElseThrow();
        org.fresa.job.JobSettings.CuttingSettings odd = new org.fresa.job.JobSettings.CuttingSettings(
                c.drawing(),
                c.kerfMm(),
                c.process(),
                c.leadInMm(),
                c.leadOutMm(),
                c.lead(),
                0.05,
                org.fresa.dxf.DrawingUnits.of("mm").orElseThrow(),
                c.paperMode(),
                c.post(),
                c.compensation(),
                c.outerDirection(),
                c.holeDirection(),
                c.overcutMm(),
                c.avoidCutParts());
        CuttingViewModel vm = new CuttingViewModel();
        vm.load(job.withCutting(odd));
        assertEquals(odd, vm.typedSettings().orElseThrow());
    }

    /** A drawing of four lines, a square {@code sideMm} wide at (x, 0), or its first two sides only. */
    private static String squareDxf(double x, double sideMm, boolean closed) {
        double[][] p = {{x, 0}, {x + sideMm, 0}, {x + sideMm, sideMm}, {x, sideMm}};
        StringBuilder b = new StringBuilder("0\nSECTION\n2\nENTITIES\n");
        for (int i = 0; i < (closed ? 4 : 2); i++) {
            double[] a = p[i];
            double[] z = p[(i + 1) % 4];
            b.append("0\nLINE\n8\n0\n10\n" + a[0] + "\n20\n" + a[1] + "\n30\n0\n11\n" + z[0] + "\n21\n" + z[1]
                    + "\n31\n0\n");
        }
        return b.append("0\nENDSEC\n0\nEOF\n").toString();
    }

    /**
     * The tab's warnings say what Job > Run says of the same job: the drawing's and the plan's
     * warnings, "nothing to cut" for a drawing without a closed contour, and the program check's
     * refusal of a part 20 m from the zero (a coordinate word out of range).
     */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"plate", "open", "far"})
    void theWarningsAreWhatTheRunSays(String drawing, @org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path dxf = drawing.equals("plate")
                ? Path.of("samples/cutting/plate.dxf").toAbsolutePath()
                : java.nio.file.Files.writeString(
                        dir.resolve(drawing + ".dxf"),
                        squareDxf(drawing.equals("far") ? 20_000 : 0, 100, drawing.equals("far")));
        // the sample job with this drawing
        Path file = java.nio.file.Files.writeString(
                dir.resolve("cut.xml"),
                java.nio.file.Files.readString(Path.of("samples/jobs/cut-plate.xml"))
                        .replace("../cutting/plate.dxf", dxf.toString()));
        org.fresa.job.Job job = org.fresa.job.JobXml.read(file);
        org.fresa.job.TaskOutcome run = org.fresa.job.CuttingService.run(
                job.cutting().orElseThrow(), new org.fresa.io.OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertTrue(!run.problems().isEmpty(), "the run says something of " + drawing);
        CuttingViewModel vm = new CuttingViewModel();
        vm.load(job);
        vm.setResult(CuttingService.compute(vm.settings(), ProgressMonitor.NONE));
        java.util.List<String> shown =
                vm.warnings().all().stream().map(WarningList.Warning::text).toList();
        for (String p : run.problems()) {
            assertTrue(shown.contains(p), "the tab does not say: " + p + "\n" + shown);
        }
        // the open drawing's nothing to cut and the far part's refused program are said beside Cut
        assertEquals(
                !drawing.equals("plate"), vm.refusal().isPresent(), vm.refusal().toString());
    }
}
