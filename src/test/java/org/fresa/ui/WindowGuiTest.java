package org.fresa.ui;

import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import org.assertj.swing.edt.FailOnThreadViolationRepaintManager;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * The main window under a real (virtual) display, opened fresh for each test with its recent-jobs
 * list in the test's folder: CI runs these under Xvfb, a headless run skips them.
 */
abstract class WindowGuiTest {

    @TempDir
    Path dir;

    FrameFixture window;

    @BeforeAll
    static void needsADisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under xvfb-run");
        FailOnThreadViolationRepaintManager.install();
    }

    /** The window's size for the test, or null for its own preferred size. */
    Dimension windowSize() {
        return null;
    }

    @BeforeEach
    void openWindow() {
        MainWindow w = GuiActionRunner.execute(() -> FresaApp.create(new RecentJobs(dir.resolve("recent.txt"))));
        window = new FrameFixture(w);
        // wait for idle by one invokeAndWait on the system queue: AssertJ's own wait posts to every
        // queue its window monitor has seen and waits up to 10 s for each, so one queue no thread
        // pumps costs 10 s per robot action (seen after File > Open recent: 51 s for one test)
        window.robot().settings().simpleWaitForIdle(true);
        if (windowSize() == null) {
            window.show();
        } else {
            window.show(windowSize());
        }
        settlePlacement();
    }

    /**
     * Makes sure the window is where Java thinks on the display. No window manager places it, and
     * a loaded run once left every click on a tab landing on the tab to its right: the robot aims
     * at screen points Java computes from the window's location, the display delivers the click
     * by where the window really is. The pointer is moved into the window; the mouse event tells
     * where the display has the window (its screen point less its window point). Where the two
     * differ, the window is moved again until they agree.
     */
    private void settlePlacement() {
        javax.swing.JFrame frame = (javax.swing.JFrame) window.target();
        java.util.concurrent.atomic.AtomicReference<java.awt.Point> seen =
                new java.util.concurrent.atomic.AtomicReference<>();
        java.awt.event.AWTEventListener listener = e -> {
            if (e instanceof java.awt.event.MouseEvent m
                    && m.getComponent() != null
                    && m.getComponent().isShowing()) {
                java.awt.Point at = m.getComponent().getLocationOnScreen();
                // where the display has the component, less where Java has it
                seen.set(new java.awt.Point(m.getXOnScreen() - m.getX() - at.x, m.getYOnScreen() - m.getY() - at.y));
            }
        };
        java.awt.Toolkit.getDefaultToolkit().addAWTEventListener(listener, java.awt.AWTEvent.MOUSE_MOTION_EVENT_MASK);
        try {
            for (int attempt = 0; attempt < 5; attempt++) {
                java.awt.Point centre = GuiActionRunner.execute(() -> {
                    java.awt.Point p = new java.awt.Point(
                            frame.getContentPane().getWidth() / 2,
                            frame.getContentPane().getHeight() / 2);
                    javax.swing.SwingUtilities.convertPointToScreen(p, frame.getContentPane());
                    return p;
                });
                seen.set(null);
                window.robot().moveMouse(new java.awt.Point(centre.x + 3 + attempt, centre.y + 3));
                window.robot().moveMouse(centre);
                window.robot().waitForIdle();
                java.awt.Point off = seen.get();
                if (off == null || (off.x == 0 && off.y == 0)) {
                    return;
                }
                System.err.println("the window is " + off.x + "," + off.y
                        + " px from where Java has it on the display: placed again");
                GuiActionRunner.execute(() -> {
                    java.awt.Point p = frame.getLocation();
                    frame.setLocation(p.x + 1, p.y + 1);
                    frame.setLocation(p);
                });
                window.robot().waitForIdle();
                org.assertj.swing.timing.Pause.pause(200);
            }
        } finally {
            java.awt.Toolkit.getDefaultToolkit().removeAWTEventListener(listener);
        }
    }

    @AfterEach
    void closeWindow() {
        if (window != null) {
            window.cleanUp();
        }
    }

    /**
     * Chooses a file in a shown chooser and approves it, on the event thread. The robot's select
     * and approve sometimes did not take in a loaded run (the dialog stayed, or closed with no
     * selection): JFileChooser is Swing's, not ours, so these tests give it the user's answer
     * directly and test what the window does with it.
     */
    static void choose(JFileChooserFixture chooser, Path file) {
        Path absolute = file.toAbsolutePath();
        GuiActionRunner.execute(() -> {
            if (absolute.getParent() != null) {
                chooser.target().setCurrentDirectory(absolute.getParent().toFile());
            }
            chooser.target().setSelectedFile(absolute.toFile());
            chooser.target().approveSelection();
        });
    }
}
