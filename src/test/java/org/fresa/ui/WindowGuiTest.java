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
