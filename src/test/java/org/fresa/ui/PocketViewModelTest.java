package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.junit.jupiter.api.Test;

class PocketViewModelTest {

    @Test
    void computesTreeSceneAndProgramForCavity03() {
        PocketViewModel m = new PocketViewModel();
        m.setSettings(new PocketSettings(
                Path.of("samples/pocket/cavity03.dad"),
                6,
                0.73,
                0.22,
                30,
                27,
                5,
                2750,
                280,
                90,
                org.fresa.post.PocketPost.SINUMERIK_7M_COMPAT,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT));
        m.compute();
        PocketViewModel.Result r = m.result().orElseThrow();
        assertTrue(r.report().contains("divides at t = 6.135716"), r.report());
        assertEquals("done", PocketViewModel.doneLine(r));
        assertTrue(r.report().contains("DIAMETRO MAXIMO (largest tool)    12.271 mm"), r.report());
        assertTrue(r.nc().startsWith("N05 %\n"));
        assertEquals(5, r.scene().labels().size());
        assertTrue(r.scene().layers().stream()
                .anyMatch(l -> l.style() == PlotScene.Style.FEED && !l.curves().isEmpty()));
    }

    @Test
    void aMissingFileIsAMessageNotAnException() {
        PocketViewModel m = new PocketViewModel();
        m.setSettings(new PocketSettings(
                Path.of("samples/pocket/none.dad"),
                6,
                0.6,
                0.1,
                0,
                -3,
                3,
                3000,
                300,
                100,
                org.fresa.post.PocketPost.SINUMERIK_7M,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT));
        m.compute();
        assertTrue(m.result().isEmpty());
        assertTrue(m.error().isPresent());
    }

    @Test
    void theContourFileIsDrawnAsReadBeforeComputeAndAWrongOneSaysWhy(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        PocketViewModel m = new PocketViewModel();
        m.load(org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET)
                .withPocket(roomsIslands(0.6, PocketStrategy.DEFAULT)));
        PlotScene s = m.fileScene();
        assertEquals("rooms-islands.contour as read, 2 islands: press Compute", s.title());
        int elements =
                org.fresa.job.PocketService.readContours(Path.of("samples/pocket/rooms-islands.contour")).stream()
                        .mapToInt(org.fresa.geom.Contour::size)
                        .sum();
        assertEquals(1, s.layers().size());
        assertEquals(elements, s.layers().get(0).curves().size());
        java.nio.file.Path bad = dir.resolve("bad.contour");
        java.nio.file.Files.writeString(bad, "this is no contour\n");
        m.setContourText(bad.toString());
        PlotScene refused = m.fileScene();
        assertTrue(refused.layers().isEmpty());
        assertTrue(refused.title().startsWith("bad.contour, line 1: Expected contour"), refused.title());
        m.setContourText(dir.resolve("none.contour").toString());
        assertEquals(PocketViewModel.NO_CONTOUR, m.fileScene().title());
    }

    /** The rooms with islands, a 6 mm tool at this cut, 4 mm deep in two layers, linuxcnc, climb. */
    static PocketSettings roomsIslands(double cut, PocketStrategy strategy) {
        return new PocketSettings(
                Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath(),
                6,
                cut,
                0.1,
                0,
                -4,
                2,
                3000,
                300,
                100,
                org.fresa.post.PocketPost.LINUXCNC,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                strategy);
    }

    @Test
    void adaptiveClearingShowsWhereItSlowsItsFeedInThePlotAndTheReport() {
        PocketViewModel m = new PocketViewModel();
        m.setSettings(roomsIslands(0.4, new PocketStrategy(PocketStrategy.Kind.ADAPTIVE, 0)));
        m.compute();
        PocketViewModel.Result r = m.result().orElseThrow(() -> new AssertionError(m.error()));
        assertTrue(r.report().startsWith("warning: adaptive: "), r.report());
        PlotScene.Layer slowed = r.scene().layers().stream()
                .filter(l -> l.name().equals("slowed feed"))
                .findFirst()
                .orElseThrow();
        assertEquals(PlotScene.Style.WARNING, slowed.style());
        assertTrue(!slowed.curves().isEmpty());
        // each slowed curve is a move of the program at a feed below the programmed 300 and 100 mm/min
        assertTrue(r.nc().lines().anyMatch(l -> l.matches(".*F(?!300\\b|100\\b)\\d+.*")), "a slowed F word");
    }

    @Test
    void aContourWithIslandsShowsItsOffsetsAndTheLinuxCncProgram() {
        PocketViewModel m = new PocketViewModel();
        m.setSettings(new PocketSettings(
                Path.of("samples/pocket/rooms-islands.contour"),
                6,
                0.7,
                0.1,
                0,
                -6,
                3,
                3000,
                300,
                100,
                org.fresa.post.PocketPost.LINUXCNC,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT));
        m.compute();
        PocketViewModel.Result r = m.result().orElseThrow(() -> new AssertionError(m.error()));
        assertTrue(r.report().startsWith("2 island(s)"), r.report());
        assertTrue(r.report().contains("3 sub-area(s)"), r.report());
        assertTrue(r.nc().contains("\nG2 ") || r.nc().contains("\nG3 "), "arcs as arcs");
        assertTrue(r.scene().layers().stream()
                .anyMatch(l -> l.style() == PlotScene.Style.FEED && !l.curves().isEmpty()));
    }

    @Test
    void theDirectionSettingReversesTheProgramsArcs() {
        PocketViewModel m = new PocketViewModel();
        PocketSettings climb = new PocketSettings(
                Path.of("samples/pocket/examplepart.dad"),
                4,
                0.62,
                0.18,
                8,
                6,
                2,
                3000,
                300,
                100,
                org.fresa.post.PocketPost.LINUXCNC,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);
        m.setSettings(climb);
        m.compute();
        String a = m.result().orElseThrow(() -> new AssertionError(m.error())).nc();
        m.setSettings(climb.withDirection(org.fresa.pocket.MillingDirection.CONVENTIONAL));
        m.compute();
        String b = m.result().orElseThrow(() -> new AssertionError(m.error())).nc();
        assertEquals(words(a, "G3"), words(b, "G2"));
        assertTrue(words(a, "G3") > words(a, "G2"), "convex arcs counter-clockwise in climb");
    }

    private static long words(String nc, String word) {
        return java.util.regex.Pattern.compile("\\b" + word + "\\b")
                .matcher(nc)
                .results()
                .count();
    }

    @Test
    void theEntryFieldsAreBoundToTheJobsPocketAndTheAngleIsChecked() {
        PocketViewModel m = new PocketViewModel();
        m.load(org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET)
                .withPocket(new PocketSettings(
                                Path.of("samples/pocket/cavity01.dad"),
                                6,
                                0.62,
                                0.13,
                                30,
                                27,
                                3,
                                3200,
                                290,
                                100,
                                org.fresa.post.PocketPost.LINUXCNC,
                                MillingDirection.CLIMB,
                                EntryRule.Kind.AUTO,
                                EntryRule.DEFAULT_ANGLE_DEG,
                                false,
                                Optional.empty(),
                                PocketStrategy.DEFAULT)
                        .withEntry(org.fresa.pocket.EntryRule.Kind.RAMP, 2.5, true)));
        assertEquals("ramp", m.entry());
        assertEquals("2.5", m.entryAngle());
        assertTrue(m.centreCutting());
        m.setEntryAngle("95");
        assertEquals(
                "Entry angle (deg): expected a number from 0.5 to 90 deg, found 95.",
                m.problems().get(PocketViewModel.ENTRY_ANGLE));
        assertTrue(m.typedSettings().isEmpty());
        m.setEntryAngle("1.5");
        m.setEntry("helix");
        m.setCentreCutting(false);
        PocketSettings s = m.typedSettings().orElseThrow();
        assertEquals(org.fresa.pocket.EntryRule.Kind.HELIX, s.entry());
        assertEquals(1.5, s.entryAngleDeg());
        assertTrue(!s.centreCutting());
    }

    @Test
    void aPlungeOfACutterNotCuttingAtItsCentreIsPlannedAndRefusedByTheCheckAndCannotBeSaved() {
        PocketViewModel m = new PocketViewModel();
        assertTrue(m.saveProblem().orElseThrow().contains("press Compute"));
        PocketSettings plunge = new PocketSettings(
                        Path.of("samples/pocket/cavity01.dad"),
                        6,
                        0.62,
                        0.13,
                        30,
                        27,
                        3,
                        3200,
                        290,
                        100,
                        org.fresa.post.PocketPost.LINUXCNC,
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT)
                .withEntry(org.fresa.pocket.EntryRule.Kind.PLUNGE, 3, false);
        m.setSettings(plunge);
        m.compute();
        org.fresa.check.Failure f = m.result().orElseThrow().refusal().orElseThrow();
        assertEquals("entry angle", f.rule().name());
        assertTrue(m.saveProblem().orElseThrow().startsWith("The program is not saved: it fails the program check at"));
        m.setSettings(plunge.withEntry(org.fresa.pocket.EntryRule.Kind.PLUNGE, 3, true));
        m.compute();
        assertTrue(m.result().orElseThrow().refusal().isEmpty());
        assertTrue(m.saveProblem().isEmpty());
    }

    @Test
    void theStrategyFieldsAreBoundToTheJobAndTheProgramIsFresaRunsOfTheSavedJob(
            @org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        PocketViewModel m = new PocketViewModel();
        assertEquals("offset", m.strategy());
        m.load(org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET)
                .withPocket(new PocketSettings(
                        Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath(),
                        6,
                        0.6,
                        0.1,
                        0,
                        -4,
                        2,
                        3000,
                        300,
                        100,
                        org.fresa.post.PocketPost.LINUXCNC,
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT)));
        m.setStrategy("zigzag");
        m.setAngle("200");
        assertEquals(
                "Zigzag angle (deg): expected a number from -180 to 180 deg, found 200.",
                m.problems().get(PocketViewModel.ANGLE));
        m.setStockToLeave("0,3");
        assertTrue(m.problems().get(PocketViewModel.STOCK_TO_LEAVE).contains("decimals take a point: 0.3"));
        m.setAngle("30");
        m.setStockToLeave("0.3");
        m.setOrder("outside-in");
        PocketSettings s = m.typedSettings().orElseThrow();
        assertEquals(
                new org.fresa.pocket.PocketStrategy(
                        org.fresa.pocket.PocketStrategy.Kind.ZIGZAG,
                        30,
                        0.3,
                        org.fresa.pocket.PocketStrategy.Order.OUTSIDE_IN),
                s.strategy());
        m.setSettings(s);
        m.compute();
        String tab = m.result().orElseThrow(() -> new AssertionError(m.error())).nc();
        // the same settings saved as a job and run as fresa run runs it
        Path file = dir.resolve("job.xml");
        org.fresa.job.JobXml.write(
                org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET).withPocket(s), file);
        Path out = dir.resolve("out");
        java.nio.file.Files.createDirectories(out);
        org.fresa.job.TaskOutcome o = org.fresa.job.JobRunner.run(
                org.fresa.job.JobXml.read(file),
                new org.fresa.io.OutputFolder(out),
                org.fresa.job.ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(java.nio.file.Files.readString(out.resolve("pocket.ngc")), tab);
        PocketViewModel again = new PocketViewModel();
        again.load(org.fresa.job.JobXml.read(file));
        assertEquals("zigzag", again.strategy());
        assertEquals("30", again.angle());
        assertEquals("0.3", again.stockToLeave());
        assertEquals("outside-in", again.order());
    }

    @Test
    void theRestToolIsCheckedAsTypedAndTheProgramIsFresaRunsOfTheSavedJob(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        PocketViewModel m = new PocketViewModel();
        assertEquals("", m.restTool());
        m.load(org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET)
                .withPocket(new PocketSettings(
                        Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath(),
                        6,
                        0.6,
                        0.1,
                        0,
                        -4,
                        2,
                        3000,
                        300,
                        100,
                        org.fresa.post.PocketPost.LINUXCNC,
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT)));
        assertTrue(m.problems().isEmpty(), m.problems().toString());
        m.setRestTool("6");
        assertEquals(
                "Rest tool (mm): expected a number of at least 0.01 mm and below 5.99 mm, found 6.",
                m.problems().get(PocketViewModel.REST_TOOL));
        m.setRestTool("2,5");
        assertTrue(m.problems().get(PocketViewModel.REST_TOOL).contains("decimals take a point: 2.5"));
        m.setRestTool("2.5");
        assertTrue(m.problems().isEmpty(), m.problems().toString());
        PocketSettings s = m.typedSettings().orElseThrow();
        assertEquals(2.5, s.strategy().restToolDiameterMm());
        m.setSettings(s);
        m.compute();
        String tab = m.result().orElseThrow(() -> new AssertionError(m.error())).nc();
        assertTrue(tab.contains("T2 M6"), tab);
        assertTrue(m.result().orElseThrow().report().contains("rest tool T2 D2.5"));
        // the rest tool's pieces are drawn apart from the first tool's passes
        assertTrue(
                m.result().orElseThrow().scene().layers().stream()
                        .anyMatch(l -> l.name().equals("feed T2")
                                && l.style() == org.fresa.chart.PlotScene.Style.FINISH
                                && !l.curves().isEmpty()),
                m.result().orElseThrow().scene().layers().toString());
        Path file = dir.resolve("job.xml");
        org.fresa.job.JobXml.write(
                org.fresa.job.Job.empty(org.fresa.job.JobTask.POCKET).withPocket(s), file);
        Path out = dir.resolve("out");
        java.nio.file.Files.createDirectories(out);
        org.fresa.job.TaskOutcome o = org.fresa.job.JobRunner.run(
                org.fresa.job.JobXml.read(file),
                new org.fresa.io.OutputFolder(out),
                org.fresa.job.ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(java.nio.file.Files.readString(out.resolve("pocket.ngc")), tab);
        PocketViewModel again = new PocketViewModel();
        again.load(org.fresa.job.JobXml.read(file));
        assertEquals("2.5", again.restTool());
    }
    /**
     * The tab's report says what fresa pocket and Job > Run say of the same settings: a stepover
     * raised to half the tool, a tool that does not pass every bottleneck, the wall the thesis's
     * printed program cuts.
     */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({
        "cavity01.dad, 10, 0.3, LINUXCNC, OFFSET",
        "cavity01.dad, 10, 0.3, LINUXCNC, ZIGZAG",
        "cavity02.dad, 10, 0.6, SINUMERIK_7M_COMPAT, OFFSET",
        "cavity03.dad, 14, 0.6, SINUMERIK_7M, OFFSET"
    })
    void theReportSaysTheWarningsTheProgramIsWrittenWith(
            String contour,
            double toolMm,
            double cut,
            org.fresa.post.PocketPost post,
            PocketStrategy.Kind kind,
            @org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        PocketStrategy strategy = kind == PocketStrategy.Kind.OFFSET
                ? PocketStrategy.DEFAULT
                : new PocketStrategy(kind, 0, 0, PocketStrategy.Order.INSIDE_OUT, 0);
        PocketSettings s = new PocketSettings(
                Path.of("samples/pocket/" + contour),
                toolMm,
                cut,
                0.1,
                30,
                27,
                5,
                2750,
                280,
                90,
                post,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                strategy);
        org.fresa.job.TaskOutcome run =
                org.fresa.job.PocketService.run(s, dir.resolve("p.nc"), org.fresa.job.ProgressMonitor.NONE);
        assertEquals(0, run.exitStatus(), run.problems().toString());
        assertTrue(
                run.problems().stream().anyMatch(w -> w.startsWith("warning: ")),
                "these settings are written with a warning: " + run.problems());
        PocketViewModel m = new PocketViewModel();
        m.setSettings(s);
        m.compute();
        String report = m.result().orElseThrow().report();
        for (String w : run.problems()) {
            assertTrue(report.contains(w), "the tab does not say: " + w + "\n" + report);
        }
        // and its status line says it, the report not being in front
        String done = PocketViewModel.doneLine(m.result().orElseThrow());
        assertTrue(done.startsWith("done, with") && done.contains("warning: "), done);
    }
}
