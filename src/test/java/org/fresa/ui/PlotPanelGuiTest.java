package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.event.KeyEvent;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.JTextField;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.core.matcher.JButtonMatcher;
import org.assertj.swing.edt.FailOnThreadViolationRepaintManager;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.fixture.JPopupMenuFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.jfree.chart.ChartPanel;
import org.jfree.chart.plot.XYPlot;
import org.jfree.data.Range;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The plot view under a (virtual) display, as the planner uses it: drag zoom, the plot's menu,
 * a resize, Home after a click and the export all keep a round tool round.
 */
class PlotPanelGuiTest {

    @TempDir
    Path dir;

    private FrameFixture window;
    private PlotPanel plot;

    /** A disc of radius 10 filled in the material colour, in a long thin outline: a wide scene. */
    private static final PlotScene SCENE = PlotScene.empty("disc")
            .with(new PlotScene.Layer("disc", PlotScene.Style.PART, List.of(Arc2.circle(Vec2.of(20, 10), 10, true))))
            .with(new PlotScene.Layer(
                    "strip",
                    PlotScene.Style.OUTLINE,
                    List.of(
                            Segment2.of(0, 0, 200, 0),
                            Segment2.of(200, 0, 200, 20),
                            Segment2.of(200, 20, 0, 20),
                            Segment2.of(0, 20, 0, 0))));

    private static final Box2 BOUNDS = new Box2(0, 0, 200, 20);

    @BeforeAll
    static void needsADisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under xvfb-run");
        FailOnThreadViolationRepaintManager.install();
    }

    @BeforeEach
    void open() {
        JFrame frame = GuiActionRunner.execute(() -> {
            JFrame f = new JFrame("plot");
            plot = new PlotPanel();
            // a field that has the keyboard first, as the tabs' forms do
            JTextField field = new JTextField("form");
            field.setName("field");
            f.add(field, BorderLayout.NORTH);
            f.add(plot, BorderLayout.CENTER);
            return f;
        });
        window = new FrameFixture(frame);
        window.show(new Dimension(900, 500));
        GuiActionRunner.execute(() -> plot.show(SCENE));
        awaitDrawn();
    }

    @AfterEach
    void close() {
        if (window != null) {
            window.cleanUp();
        }
    }

    private void awaitDrawn() {
        window.robot().waitForIdle();
        Pause.pause(
                new Condition("the plot is drawn") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> plot.isDrawn());
                    }
                },
                Timeout.timeout(20_000));
        window.robot().waitForIdle();
    }

    private ChartPanel chartPanel() {
        return (ChartPanel) plot.chartComponent();
    }

    /** Millimetres per pixel along x over those along y of the picture on screen. */
    private double aspect() {
        return GuiActionRunner.execute(() -> {
            XYPlot xy = chartPanel().getChart().getXYPlot();
            Rectangle2D area = chartPanel().getScreenDataArea();
            return xy.getDomainAxis().getRange().getLength()
                    / area.getWidth()
                    / (xy.getRangeAxis().getRange().getLength() / area.getHeight());
        });
    }

    private boolean showsAll() {
        return GuiActionRunner.execute(() -> {
            XYPlot xy = chartPanel().getChart().getXYPlot();
            Range x = xy.getDomainAxis().getRange();
            Range y = xy.getRangeAxis().getRange();
            return x.contains(BOUNDS.minX())
                    && x.contains(BOUNDS.maxX())
                    && y.contains(BOUNDS.minY())
                    && y.contains(BOUNDS.maxY())
                    && x.getLength() < 2 * BOUNDS.width();
        });
    }

    private Point pixel(double xMm, double yMm) {
        return GuiActionRunner.execute(() -> plot.toPixels(Vec2.of(xMm, yMm)));
    }

    private void zoomIntoTheDisc() {
        // a long flat box around the disc's middle, drawn down and to the right (up or left is
        // JFreeChart's gesture for Auto Range)
        Point from = pixel(5, 12);
        Point to = pixel(60, 8);
        window.robot().pressMouse(plot.chartComponent(), from, MouseButton.LEFT_BUTTON);
        window.robot().moveMouse(plot.chartComponent(), new Point((from.x + to.x) / 2, (from.y + to.y) / 2));
        window.robot().moveMouse(plot.chartComponent(), to);
        window.robot().releaseMouse(MouseButton.LEFT_BUTTON);
        awaitDrawn();
    }

    @Test
    void aDragZoomOverALongFlatBoxKeepsEqualScale() {
        zoomIntoTheDisc();
        double x = GuiActionRunner.execute(() ->
                chartPanel().getChart().getXYPlot().getDomainAxis().getRange().getLength());
        assertAll(() -> assertTrue(x < 100, "zoomed in: " + x + " mm across"), () -> assertEquals(1, aspect(), 0.01));
    }

    @Test
    void autoRangeOfThePlotsMenuFitsTheDrawing() {
        zoomIntoTheDisc();
        JPopupMenuFixture menu = new JPopupMenuFixture(
                window.robot(), window.robot().showPopupMenu(plot.chartComponent(), pixel(30, 10)));
        // the menu speaks the machine's language: its words from JFreeChart's own bundle
        java.util.ResourceBundle words = java.util.ResourceBundle.getBundle("org.jfree.chart.LocalizationBundle");
        menu.menuItemWithPath(words.getString("Auto_Range"), words.getString("All_Axes"))
                .click();
        awaitDrawn();
        assertAll(() -> assertTrue(showsAll(), "the whole drawing in view"), () -> assertEquals(1, aspect(), 0.01));
    }

    @Test
    void aResizeKeepsEqualScale() {
        window.resizeTo(new Dimension(600, 800));
        awaitDrawn();
        assertEquals(1, aspect(), 0.01);
        window.resizeTo(new Dimension(1200, 400));
        awaitDrawn();
        assertAll(() -> assertTrue(showsAll(), "the whole drawing in view"), () -> assertEquals(1, aspect(), 0.01));
    }

    @Test
    void homeFitsRightAfterAClickInThePlot() {
        zoomIntoTheDisc();
        window.textBox("field").focus();
        window.robot().click(plot.chartComponent(), pixel(30, 10));
        window.robot().pressAndReleaseKeys(KeyEvent.VK_HOME);
        awaitDrawn();
        assertTrue(showsAll(), "Home fitted the drawing");
    }

    @Test
    void theFitButtonFitsTheDrawing() {
        zoomIntoTheDisc();
        window.button(JButtonMatcher.withName("fitPlot")).click();
        awaitDrawn();
        assertAll(() -> assertTrue(showsAll(), "the whole drawing in view"), () -> assertEquals(1, aspect(), 0.01));
    }

    @Test
    void anExportedPngDrawsTheDiscRound() throws Exception {
        Path png = dir.resolve("plot.png");
        GuiActionRunner.execute(() -> {
            plot.export(png);
            return null;
        });
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(1, org.fresa.testing.Pictures.roundness(img, 0x90A4AE), 0.03);
    }
}
