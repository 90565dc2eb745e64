package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobTask;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Test;

/** The Cutting tab under a (virtual) display: a job's drawing cut, shown and written to target/screenshots. */
class CuttingTabGuiTest extends WindowGuiTest {

    @Override
    java.awt.Dimension windowSize() {
        return new java.awt.Dimension(1400, 860);
    }

    private void cut(Path drawing, String shot) {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(Job.empty(JobTask.CUT)
                .withCutting(new CuttingSettings(
                        drawing.toAbsolutePath(),
                        2,
                        org.fresa.cutting.CutProcess.PLASMA,
                        3,
                        1,
                        org.fresa.cutting.LeadShape.ARC,
                        0.001,
                        org.fresa.dxf.DrawingUnits.AUTO,
                        false,
                        org.fresa.post.CuttingPost.LINUXCNC))));
        window.tabbedPane("tabs").selectTab("Cutting");
        window.textBox("cutting-kerf").requireText("2");
        window.button("cutting-cut").click();
        Pause.pause(
                new Condition("the drawing is cut") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.textBox("cutting-totals")
                                        .target()
                                        .getText())
                                .contains("pierces");
                    }
                },
                Timeout.timeout(60_000));
        String totals = GuiActionRunner.execute(
                () -> window.textBox("cutting-totals").target().getText());
        assertTrue(totals.contains("cut ") && totals.contains(" s;"), totals);
        assertTrue(GuiActionRunner.execute(
                        () -> window.textBox("cutting-program").target().getText())
                .contains("M3 S1"));
        // what was cut is the job: saving it now saves these settings
        assertEquals(
                drawing.toAbsolutePath(),
                GuiActionRunner.execute(
                        () -> model.job().cutting().orElseThrow().drawing()));
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            Files.createDirectories(Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(
                    img, "png", Path.of("target", "screenshots", shot).toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void theSamplePlateIsCutAndShown() {
        cut(Path.of("samples/cutting/plate.dxf"), "cutting-plate.png");
        window.textBox("cutting-totals").requireText(java.util.regex.Pattern.compile("(?s)10 contours.*"));
    }

    /**
     * A part 20 m from the zero: Job > Run refuses its program (a coordinate word out of range),
     * and the tab says so beside Cut and in its list, in the run's words.
     */
    @Test
    void aProgramTheRunRefusesIsSaidRefused(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path far = Files.writeString(
                dir.resolve("far.dxf"),
                "0\nSECTION\n2\nENTITIES\n"
                        + "0\nLINE\n8\n0\n10\n20000\n20\n0\n30\n0\n11\n20100\n21\n0\n31\n0\n"
                        + "0\nLINE\n8\n0\n10\n20100\n20\n0\n30\n0\n11\n20100\n21\n100\n31\n0\n"
                        + "0\nLINE\n8\n0\n10\n20100\n20\n100\n30\n0\n11\n20000\n21\n100\n31\n0\n"
                        + "0\nLINE\n8\n0\n10\n20000\n20\n100\n30\n0\n11\n20000\n21\n0\n31\n0\n"
                        + "0\nENDSEC\n0\nEOF\n");
        cut(far, "cutting-refused.png");
        String said = GuiActionRunner.execute(
                () -> window.label("cutting-status").target().getToolTipText() + " "
                        + window.label("cutting-status").target().getText());
        assertTrue(said.contains("program.ngc not written: it fails the program check"), said);
        assertTrue(
                java.util.Arrays.stream(window.list("cutting-warnings").contents())
                        .anyMatch(r -> r.contains("word X19996 out of range")),
                java.util.Arrays.toString(window.list("cutting-warnings").contents()));
    }

    @Test
    @CorpusCheck
    void aCorpusDrawingIsCutAndShown() {
        Path p = TestInputs.DXF_CORPUS.resolve("dxf2gcode/pumpenteile.dxf");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(p), "corpus absent");
        cut(p, "cutting-pumpenteile.png");
    }

    @Test
    @CorpusCheck
    void everyWarningIsListedAndAClickShowsItsPlaceInThePlot() {
        Path p = TestInputs.DXF_CORPUS.resolve("dxf2gcode/pumpenteile.dxf");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(p), "corpus absent");
        cut(p, "cutting-pumpenteile.png");
        org.assertj.swing.fixture.JListFixture list = window.list("cutting-warnings");
        String[] rows = list.contents();
        String totals = GuiActionRunner.execute(
                () -> window.textBox("cutting-totals").target().getText());
        java.util.regex.Matcher counted =
                java.util.regex.Pattern.compile("(\\d+) warnings").matcher(totals);
        assertTrue(counted.find(), totals);
        // every warning the totals count is in the list (the tab used to show 3 of 32)
        assertEquals(Integer.parseInt(counted.group(1)), rows.length);
        assertTrue(rows.length > 20, rows.length + " warnings");
        int placed = java.util.stream.IntStream.range(0, rows.length)
                .filter(i -> WarningList.placeIn(rows[i]).isPresent() && !rows[i].contains("open chain"))
                .findFirst()
                .orElseThrow();
        org.fresa.geom.Vec2 place = WarningList.placeIn(rows[placed]).orElseThrow();
        list.clickItem(placed);
        PlotPanel plot = window.robot()
                .finder()
                .find(new org.assertj.swing.core.GenericTypeMatcher<PlotPanel>(PlotPanel.class, true) {
                    @Override
                    protected boolean isMatching(PlotPanel c) {
                        return true;
                    }
                });
        Pause.pause(
                new Condition("the plot is drawn") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> plot.isDrawn());
                    }
                },
                Timeout.timeout(20_000));
        org.fresa.geom.Box2 view = GuiActionRunner.execute(() -> plot.view());
        org.junit.jupiter.api.Assertions.assertAll(
                () -> assertTrue(view.contains(place), "the place " + place + " in view: " + view),
                () -> assertTrue(view.width() < 80, "zoomed to the place: " + view),
                () -> assertTrue(
                        GuiActionRunner.execute(() -> plot.scene().layers().stream()
                                .anyMatch(l -> l.name().equals("selected warning"))),
                        "the place is marked"),
                () -> assertEquals(1, GuiActionRunner.execute(() -> plot.shownAspect()), 0.01));
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            javax.imageio.ImageIO.write(
                    img,
                    "png",
                    Path.of("target", "screenshots", "cutting-warning-place.png")
                            .toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** A contour not cut is drawn in its own layer and names itself and its reason under the mouse. */
    @Test
    void aContourNotCutIsDrawnAndTellsWhyOnHover(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path dxf = dir.resolve("plate-with-pinhole.dxf");
        StringBuilder d = new StringBuilder("0\nSECTION\n2\nENTITIES\n");
        double[][] c = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
        for (int k = 0; k < 4; k++) {
            d.append("0\nLINE\n8\n0\n10\n")
                    .append(c[k][0])
                    .append("\n20\n")
                    .append(c[k][1])
                    .append("\n11\n")
                    .append(c[(k + 1) % 4][0])
                    .append("\n21\n")
                    .append(c[(k + 1) % 4][1])
                    .append("\n");
        }
        // a pin hole of 1 mm: a 2 mm kerf cannot cut it
        d.append("0\nCIRCLE\n8\n0\n10\n50\n20\n50\n40\n0.5\n0\nENDSEC\n0\nEOF\n");
        Files.writeString(dxf, d.toString());
        cut(dxf, "cutting-not-cut.png");
        PlotPanel plot = window.robot()
                .finder()
                .find(new org.assertj.swing.core.GenericTypeMatcher<PlotPanel>(PlotPanel.class, true) {
                    @Override
                    protected boolean isMatching(PlotPanel p) {
                        return true;
                    }
                });
        Pause.pause(
                new Condition("the plot is drawn") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> plot.isDrawn());
                    }
                },
                Timeout.timeout(20_000));
        assertTrue(
                GuiActionRunner.execute(() -> plot.scene().layers().stream()
                        .anyMatch(l -> l.name().equals("not cut") && !l.curves().isEmpty())),
                "a layer of the contours not cut");
        javax.swing.JComponent chart = GuiActionRunner.execute(() -> plot.chartComponent());
        java.awt.Point onHole = GuiActionRunner.execute(() -> plot.toPixels(org.fresa.geom.Vec2.of(50.5, 50)));
        java.awt.Point onPart = GuiActionRunner.execute(() -> plot.toPixels(org.fresa.geom.Vec2.of(25, 25)));
        window.robot().moveMouse(chart, onPart);
        window.robot().waitForIdle();
        assertEquals(null, GuiActionRunner.execute(() -> chart.getToolTipText()), "nothing to tell over a cut part");
        window.robot().moveMouse(chart, onHole);
        Pause.pause(
                new Condition("the pin hole tells why it is not cut") {
                    @Override
                    public boolean test() {
                        String t = GuiActionRunner.execute(() -> chart.getToolTipText());
                        return t != null && t.contains("not cut");
                    }
                },
                Timeout.timeout(10_000));
        String tip = GuiActionRunner.execute(() -> chart.getToolTipText());
        assertTrue(
                tip.startsWith("part 1 hole 1 (1.000 x 1.000 mm at 49.500, 49.500)")
                        && tip.contains("too small for a 2.000 mm kerf"),
                tip);
    }
}
