package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.junit.jupiter.api.Test;

/** The main window under a real (virtual) display: CI runs it under Xvfb, a headless run skips it. */
class MainWindowGuiTest extends WindowGuiTest {

    static final String[] TABS = {"STEP-NC", "Position", "Robot", "Pocket", "Cutting", "Grading", "Sole", "Output"};

    @Test
    void windowIsTitledFresaWithTheEightTabs() {
        window.requireTitle("Fresa");
        window.tabbedPane("tabs").requireTabTitles(TABS);
    }

    @Test
    void everyTabCanBeSelectedWithTheKeyboard() {
        for (int i = 0; i < TABS.length; i++) {
            window.tabbedPane("tabs").selectTab(i);
            window.tabbedPane("tabs").requireSelectedTab(org.assertj.swing.data.Index.atIndex(i));
            assertTrue(window.tabbedPane("tabs").target().getComponentAt(i).isShowing(), TABS[i]);
        }
        int mnemonic =
                GuiActionRunner.execute(() -> window.tabbedPane("tabs").target().getMnemonicAt(3));
        assertEquals(java.awt.event.KeyEvent.VK_4, mnemonic);
    }

    @Test
    void aJobCanBeSavedAndOpenedAgain() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Job job = Job.empty(JobTask.POCKET)
                .withPocket(new PocketSettings(
                        Path.of("samples/pocket/cavity01.dad").toAbsolutePath(),
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
                        PocketStrategy.DEFAULT));
        GuiActionRunner.execute(() -> model.setJob(job));

        window.menuItemWithPath("File", "Save as...").click();
        JFileChooserFixture save = window.fileChooser(Timeout.timeout(5000));
        Path file = dir.resolve("cavity.xml");
        // the file named on the event thread: the robot's typing and approve in the save chooser
        // sometimes did not take on a loaded machine; the open chooser below is driven by the robot
        GuiActionRunner.execute(() -> {
            save.target().setCurrentDirectory(dir.toFile());
            save.target().setSelectedFile(file.toFile());
            save.target().approveSelection();
        });
        org.assertj.swing.timing.Pause.pause(
                new org.assertj.swing.timing.Condition("cavity.xml is written") {
                    @Override
                    public boolean test() {
                        return Files.exists(file);
                    }
                },
                Timeout.timeout(30_000));
        assertTrue(Files.exists(file));
        assertEquals(job.withName("cavity"), JobXml.read(file));
        window.requireTitle("Fresa - cavity.xml");

        GuiActionRunner.execute(model::newJob);
        window.menuItemWithPath("File", "Open job...").click();
        JFileChooserFixture open = window.fileChooser(Timeout.timeout(5000));
        choose(open, file);

        Job reopened = GuiActionRunner.execute(model::job);
        assertEquals(job.withName("cavity"), reopened);
        assertEquals(Optional.of(file.toAbsolutePath()), GuiActionRunner.execute(model::file));
        assertEquals(java.util.List.of(file.toAbsolutePath()), model.recentJobs());

        // the job saved by the GUI runs unchanged on the command line
        java.io.StringWriter err = new java.io.StringWriter();
        int status = org.fresa.app.cli.FresaCommand.execute(
                new java.io.PrintWriter(new java.io.StringWriter(), true),
                new java.io.PrintWriter(err, true),
                "run",
                file.toString(),
                "--out",
                dir.resolve("out").toString());
        assertEquals(0, status, err.toString());
        assertTrue(Files.size(dir.resolve("out").resolve("pocket.ngc")) > 1000);
    }
}
