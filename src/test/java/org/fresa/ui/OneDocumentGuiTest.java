package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import javax.swing.JTextField;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.app.cli.FresaCommand;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.junit.jupiter.api.Test;

/**
 * One job behind every tab: what the planner sees is what Save writes and what {@code fresa run}
 * executes; New and Open replace the whole document; undo restores it exactly.
 */
class OneDocumentGuiTest extends WindowGuiTest {

    // the robot presses modifier keys given by the old masks
    @SuppressWarnings("deprecation")
    private static final int CTRL = java.awt.event.InputEvent.CTRL_MASK;

    @SuppressWarnings("deprecation")
    private static final int SHIFT = java.awt.event.InputEvent.SHIFT_MASK;

    private static final Path EXAMPLE2 =
            Path.of("samples/jobs/example2-irb140.xml").toAbsolutePath();
    private static final Path CAVITY01 =
            Path.of("samples/jobs/pocket-cavity01.xml").toAbsolutePath();

    @Test
    void aGradeRefusedInAnotherTabLeavesTheSavedJobRunnableWithItsTask() throws Exception {
        open(EXAMPLE2);
        Job before = model().job();
        window.tabbedPane("tabs").selectTab("Grading");
        window.button("grading-open").click();
        JFileChooserFixture fc = window.fileChooser(Timeout.timeout(5000));
        choose(fc, Path.of("samples/grading/sole-40.contour"));
        JTextField sizes = (JTextField) textFieldShowing("36-44").target();
        GuiActionRunner.execute(() -> sizes.setText("44-36"));
        // the refused range is marked and said beside Grade, which cannot run on it
        window.button("grading-grade").requireDisabled();
        assertEquals(
                "Sizes: expected sizes A-B with A <= B, found '44-36'.",
                window.label("grading-status").target().getToolTipText());

        Path saved = saveAs("refused.xml");
        Job read = JobXml.read(saved);
        assertEquals(JobTask.ROBOT, read.task());
        assertFalse(
                read.grading().map(g -> g.sizes().equals("44-36")).orElse(false),
                read.grading().toString());
        assertEquals(before.robot(), read.robot());
        assertEquals(0, run(saved, dir.resolve("out")));
        assertTrue(Files.exists(dir.resolve("out").resolve("program.mod")));
    }

    @Test
    void openReplacesEveryTabsDocumentAndDropsTheOldResults() {
        open(EXAMPLE2);
        waitFor(
                "the STEP-NC tab shows example 2",
                () -> treeText().contains("example2")
                        || window.label(labelMatching("workingsteps"))
                                .target()
                                .getText()
                                .startsWith("example2.stp"));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.textBox("pocket-contour").setText("nothing-here.dad");

        menu("File", "Open job...").click();
        JFileChooserFixture fc = window.fileChooser(Timeout.timeout(5000));
        choose(fc, CAVITY01);
        // the contour typed went into the job, so Open first asks whether to discard it
        if (waitQuietly(
                        () -> !window.robot()
                                        .finder()
                                        .findAll(new GenericTypeMatcher<>(javax.swing.JOptionPane.class, true) {
                                            @Override
                                            protected boolean isMatching(javax.swing.JOptionPane p) {
                                                return true;
                                            }
                                        })
                                        .isEmpty()
                                || ((MainWindow) window.target()).getTitle().equals("Fresa - pocket-cavity01.xml"),
                        10_000)
                && !((MainWindow) window.target()).getTitle().equals("Fresa - pocket-cavity01.xml")) {
            answer(p -> p.noButton());
        }
        waitUntilNoTaskRuns();

        window.requireTitle("Fresa - pocket-cavity01.xml");
        assertFalse(treeText().contains("example2"), treeText());
        assertFalse(allText().contains("example2"), "a tab still names the old part");
        window.tabbedPane("tabs").selectTab("Pocket");
        assertTrue(
                window.textBox("pocket-contour").text().endsWith("cavity01.dad"),
                window.textBox("pocket-contour").text());
        assertEquals("7m-compat", window.comboBox("pocket-post").selectedItem());
        window.tabbedPane("tabs").selectTab("Output");
        assertTrue(
                window.label("output-status").text().startsWith("No programs"),
                window.label("output-status").text());
    }

    @Test
    void newEmptiesEveryTabAndAsksBeforeDiscardingChanges() {
        open(CAVITY01);
        // a loaded run once left another tab in front after opening the job: the tab is selected,
        // once no task runs, until it is the one shown
        waitUntilNoTaskRuns();
        for (int attempt = 0; attempt < 50; attempt++) {
            window.tabbedPane("tabs").selectTab("Position");
            window.robot().waitForIdle();
            String shown = GuiActionRunner.execute(() -> {
                javax.swing.JTabbedPane tabs = ((MainWindow) window.target()).tabs();
                return tabs.getTitleAt(tabs.getSelectedIndex());
            });
            if ("Position".equals(shown)) {
                break;
            }
            Pause.pause(200);
        }
        waitFor(
                "the Position tab's fields are shown",
                () -> window.robot()
                                .finder()
                                .findAll(
                                        new GenericTypeMatcher<javax.swing.text.JTextComponent>(
                                                javax.swing.text.JTextComponent.class, true) {
                                            @Override
                                            protected boolean isMatching(javax.swing.text.JTextComponent c) {
                                                return "position-rt-X".equals(c.getName());
                                            }
                                        })
                                .size()
                        == 1);
        window.textBox("position-rt-X").deleteText().enterText("123");
        window.requireTitle("Fresa - pocket-cavity01.xml *");

        askFromMenu("File", "New");
        answer(p -> p.cancelButton());
        assertEquals("123", window.textBox("position-rt-X").text());
        window.requireTitle("Fresa - pocket-cavity01.xml *");
        askFromMenu("File", "New");
        answer(p -> p.noButton());
        waitUntilNoTaskRuns();

        window.requireTitle("Fresa");
        assertEquals("0", window.textBox("position-rt-X").text());
        window.tabbedPane("tabs").selectTab("Pocket");
        assertEquals("", window.textBox("pocket-contour").text());
        assertFalse(allText().contains("cavity01"), "a tab still names the old pocket");
    }

    @Test
    void openRecentAsksBeforeDiscardingChanges() {
        open(EXAMPLE2);
        open(CAVITY01);
        window.tabbedPane("tabs").selectTab("Pocket");
        window.textBox("pocket-tool").setText("5");
        waitFor("the edit is the job's", () -> model().isDirty());
        // the recent jobs, newest first: cavity 01, then example 2
        askFromRecent(2);
        answer(p -> p.cancelButton());
        window.requireTitle("Fresa - pocket-cavity01.xml *");
        assertEquals(5, model().job().pocket().orElseThrow().toolDiameterMm());
        askFromRecent(2);
        answer(p -> p.noButton());
        waitUntilNoTaskRuns();
        window.requireTitle("Fresa - example2-irb140.xml");
    }

    @Test
    void theOutputTabShowsTheLastRunsProgramsOfThisJobOnly() {
        window.tabbedPane("tabs").selectTab("Output");
        assertTrue(
                window.label("output-status").text().startsWith("No programs"),
                window.label("output-status").text());
        open(EXAMPLE2);
        menu("Job", "Run job into folder...").click();
        JFileChooserFixture fc = window.fileChooser(Timeout.timeout(5000));
        choose(fc, dir.resolve("run"));
        window.optionPane(Timeout.timeout(180_000)).okButton().click();
        window.tabbedPane("tabs").selectTab("Output");
        window.radioButton("output-preview-rapid").click();
        waitFor(
                "the run's RAPID program is shown",
                () -> window.textBox("output-text").target().getText().contains("MoveL"));
        assertTrue(
                window.label("output-status").text().contains("irb140"),
                window.label("output-status").text());

        open(CAVITY01);
        assertTrue(
                window.label("output-status").text().startsWith("No programs"),
                window.label("output-status").text());
        assertEquals("", window.textBox("output-text").text());
    }

    @Test
    void undoAndRedoRestoreTheJobExactly() {
        open(EXAMPLE2);
        Job opened = model().job();
        window.tabbedPane("tabs").selectTab("Position");
        // on a loaded machine the tab's fields may be shown a moment after the tab is selected
        waitFor(
                "the Position tab's fields are shown",
                () -> window.robot()
                                .finder()
                                .findAll(
                                        new GenericTypeMatcher<javax.swing.text.JTextComponent>(
                                                javax.swing.text.JTextComponent.class, true) {
                                            @Override
                                            protected boolean isMatching(javax.swing.text.JTextComponent c) {
                                                return "position-rt-X".equals(c.getName());
                                            }
                                        })
                                .size()
                        == 1);
        window.textBox("position-rt-X").setText("300");
        Job edited = model().job();
        assertNotEquals(opened, edited);
        window.requireTitle("Fresa - example2-irb140.xml *");
        menu("Edit", "Undo").click();
        assertEquals(opened, model().job());
        window.requireTitle("Fresa - example2-irb140.xml");
        assertEquals("450", window.textBox("position-rt-X").text());
        menu("Edit", "Redo").click();
        assertEquals(edited, model().job());
        assertEquals("300", window.textBox("position-rt-X").text());
        // the keys: Ctrl+Z undoes, Ctrl+Y and Ctrl+Shift+Z redo
        window.textBox("position-tp-Z").focus();
        window.pressAndReleaseKey(org.assertj.swing.core.KeyPressInfo.keyCode(java.awt.event.KeyEvent.VK_Z)
                .modifiers(CTRL));
        assertEquals(opened, model().job());
        window.pressAndReleaseKey(org.assertj.swing.core.KeyPressInfo.keyCode(java.awt.event.KeyEvent.VK_Y)
                .modifiers(CTRL));
        assertEquals(edited, model().job());
        window.pressAndReleaseKey(org.assertj.swing.core.KeyPressInfo.keyCode(java.awt.event.KeyEvent.VK_Z)
                .modifiers(CTRL));
        window.pressAndReleaseKey(org.assertj.swing.core.KeyPressInfo.keyCode(java.awt.event.KeyEvent.VK_Z)
                .modifiers(CTRL, SHIFT));
        assertEquals(edited, model().job());
    }

    @Test
    void aJobSavedWithSeveralModulesRunsTheTickedOnesOnly() throws Exception {
        open(EXAMPLE2);
        window.tabbedPane("tabs").selectTab("Grading");
        window.button("grading-open").click();
        JFileChooserFixture fc = window.fileChooser(Timeout.timeout(5000));
        choose(fc, Path.of("samples/grading/sole-40.contour"));
        waitUntilNoTaskRuns();
        window.button("grading-grade").click();
        waitFor(
                "the accepted grading is the job's",
                () -> model().job().grading().isPresent());
        assertEquals(java.util.List.of(JobTask.ROBOT), model().job().runs());

        window.menuItem("run-stepnc").click();
        window.menuItem("run-grade").click();
        window.menuItem("run-robot").click();
        assertEquals(
                java.util.List.of(JobTask.STEPNC, JobTask.GRADE), model().job().runs());
        Path saved = saveAs("several.xml");
        assertEquals(
                java.util.List.of(JobTask.STEPNC, JobTask.GRADE),
                JobXml.read(saved).runs());

        Path out = dir.resolve("out");
        run(saved, out);
        try (java.util.stream.Stream<Path> s = Files.list(out)) {
            assertEquals(
                    java.util.List.of("grade", "stepnc"),
                    s.filter(Files::isDirectory)
                            .map(p -> p.getFileName().toString())
                            .sorted()
                            .toList());
        }
        assertTrue(Files.exists(out.resolve("stepnc/summary.json"))
                || Files.list(out.resolve("stepnc")).count() > 0);
        assertFalse(Files.exists(out.resolve("robot")));
    }

    /** Every sample job, opened, every tab visited and saved again, runs as the sample does. */
    @Test
    void everySampleJobSavedAfterVisitingEveryTabWritesTheSameFiles() throws Exception {
        java.util.List<Path> samples;
        try (java.util.stream.Stream<Path> s = Files.list(Path.of("samples/jobs"))) {
            samples = s.filter(f -> f.toString().endsWith(".xml")).sorted().toList();
        }
        for (Path sample : samples) {
            open(sample.toAbsolutePath());
            for (String tab : MainWindowGuiTest.TABS) {
                window.tabbedPane("tabs").selectTab(tab);
                waitUntilNoTaskRuns();
            }
            String name = sample.getFileName().toString();
            Path saved = dir.resolve("saved-" + name);
            MainViewModel m = model();
            GuiActionRunner.execute(() -> {
                m.saveAs(saved);
                return null;
            });
            assertEquals(JobXml.read(sample).withName("x"), JobXml.read(saved).withName("x"), name);
            Path a = dir.resolve("a-" + name);
            Path b = dir.resolve("b-" + name);
            run(sample, a);
            run(saved, b);
            assertEquals(contents(a), contents(b), name);
        }
    }

    /** File name -> text of every file but pictures. */
    private static java.util.Map<String, String> contents(Path folder) throws java.io.IOException {
        java.util.Map<String, String> out = new java.util.TreeMap<>();
        try (java.util.stream.Stream<Path> s = Files.walk(folder)) {
            for (Path f : s.filter(Files::isRegularFile).toList()) {
                String n = folder.relativize(f).toString();
                if (!n.endsWith(".png") && !n.startsWith(".fresa")) {
                    // the time a step took differs from run to run
                    out.put(
                            n,
                            Files.readString(f, java.nio.charset.StandardCharsets.ISO_8859_1)
                                    .replaceAll("\"[a-z_]*_ms\": [0-9.Ee+-]+", "\"ms\""));
                }
            }
        }
        return out;
    }

    @Test
    void thePocketTabMarksABadFieldInThePlannersWordsAndAFailedComputeSaysFailed() {
        open(CAVITY01);
        window.tabbedPane("tabs").selectTab("Pocket");
        java.util.List<String> posts =
                java.util.Arrays.asList(window.comboBox("pocket-post").contents());
        assertTrue(
                posts.containsAll(java.util.List.of("7m-compat", "7m", "linuxcnc", "iso", "fanuc", "840d")),
                posts.toString());
        window.textBox("pocket-tool").setText("6,5");
        window.button("pocket-compute").requireDisabled();
        String why = window.label("pocket-status").target().getToolTipText();
        shoot("pocket-bad-field.png");
        assertEquals("Tool diameter (mm): '6,5' is not a number (decimals take a point: 6.5).", why);
        assertEquals(
                new java.awt.Color(255, 220, 220),
                window.textBox("pocket-tool").background().target());
        window.textBox("pocket-tool").setText("6");
        window.button("pocket-compute").requireEnabled();

        window.textBox("pocket-contour").setText(dir.resolve("none.dad").toString());
        window.button("pocket-compute").click();
        waitUntilNoTaskRuns();
        window.label("status").requireText("Pocket: failed");
        String failed = window.label("pocket-status").target().getToolTipText();
        assertTrue(failed.startsWith("There is no file") || failed.contains("none.dad"), failed);
        assertFalse(failed.contains("--") || failed.contains("Exception"), failed);
        // the refused contour is not the job's
        assertTrue(model().job().pocket().orElseThrow().contour().endsWith("cavity01.dad"));
    }

    @Test
    void undoOfAPocketComputeAndOfARunTickRestoresTheJobExactly() {
        open(CAVITY01);
        Job opened = model().job();
        window.tabbedPane("tabs").selectTab("Pocket");
        window.textBox("pocket-tool").setText("5");
        window.button("pocket-compute").click();
        waitUntilNoTaskRuns();
        window.label("pocket-status").requireText("done");
        assertEquals(5, model().job().pocket().orElseThrow().toolDiameterMm());
        assertEquals(opened.runs(), model().job().runs());
        window.menuItem("run-robot").requireDisabled();
        menu("Edit", "Undo").click();
        assertEquals(opened, model().job());
        assertEquals("6", window.textBox("pocket-tool").text());
        window.requireTitle("Fresa - pocket-cavity01.xml");
    }

    private void shoot(String name) {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            Files.createDirectories(Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(
                    img, "png", Path.of("target", "screenshots", name).toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private MainViewModel model() {
        return GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
    }

    private void open(Path job) {
        GuiActionRunner.execute(() -> ((MainWindow) window.target()).openJob(job));
        waitUntilNoTaskRuns();
    }

    /**
     * A menu item, its menu opened again once when Xvfb lost the first click (the pop-up never
     * showed: an event lost by the virtual display, not by the window).
     */
    private org.assertj.swing.fixture.JMenuItemFixture menu(String... path) {
        try {
            return window.menuItemWithPath(path);
        } catch (org.assertj.swing.exception.ActionFailedException lost) {
            window.robot().waitForIdle();
            return window.menuItemWithPath(path);
        }
    }

    /**
     * Presses a button of the open question or message, again when Xvfb lost the click and the
     * pane still shows (the dialog then stays open with its default button focused).
     */
    private void answer(
            java.util.function.Function<
                            org.assertj.swing.fixture.JOptionPaneFixture, org.assertj.swing.fixture.JButtonFixture>
                    button) {
        org.assertj.swing.fixture.JOptionPaneFixture pane = window.optionPane(Timeout.timeout(20_000));
        for (int i = 0; i < 5 && GuiActionRunner.execute(() -> pane.target().isShowing()); i++) {
            org.assertj.swing.fixture.JButtonFixture b = button.apply(pane);
            if (i > 0) {
                // a lost click: the keyboard presses the button instead
                b.focus();
                b.pressAndReleaseKeys(java.awt.event.KeyEvent.VK_SPACE);
            } else {
                b.click();
            }
            waitQuietly(() -> !pane.target().isShowing(), 3_000);
        }
        assertFalse(GuiActionRunner.execute(() -> pane.target().isShowing()), "the question is still open");
    }

    /** Chooses a recent job (the list is filled as File opens), again when the click was lost. */
    private void askFromRecent(int n) {
        for (int i = 0; i < 3; i++) {
            window.menuItemWithPath("File").click();
            window.menuItemWithPath("File", "Recent jobs").click();
            window.menuItem("recent-" + n).click();
            if (waitQuietly(
                    () -> !window.robot()
                            .finder()
                            .findAll(new GenericTypeMatcher<>(javax.swing.JOptionPane.class, true) {
                                @Override
                                protected boolean isMatching(javax.swing.JOptionPane p) {
                                    return true;
                                }
                            })
                            .isEmpty(),
                    5_000)) {
                return;
            }
        }
    }

    /** Chooses a menu item that asks a question, again when the click was lost and no question shows. */
    private void askFromMenu(String... path) {
        for (int i = 0; i < 3; i++) {
            menu(path).click();
            if (waitQuietly(
                    () -> !window.robot()
                            .finder()
                            .findAll(new GenericTypeMatcher<>(javax.swing.JOptionPane.class, true) {
                                @Override
                                protected boolean isMatching(javax.swing.JOptionPane p) {
                                    return true;
                                }
                            })
                            .isEmpty(),
                    5_000)) {
                return;
            }
        }
    }

    private boolean waitQuietly(BooleanSupplier test, long ms) {
        long end = System.currentTimeMillis() + ms;
        while (System.currentTimeMillis() < end) {
            if (GuiActionRunner.execute(test::getAsBoolean)) {
                return true;
            }
            Pause.pause(50);
        }
        return false;
    }

    private Path saveAs(String name) {
        menu("File", "Save as...").click();
        JFileChooserFixture save = window.fileChooser(Timeout.timeout(5000));
        Path file = dir.resolve(name);
        // the file named on the event thread: the robot's typing and approve in the save chooser
        // sometimes did not take on a loaded machine (the job never written); the open chooser
        // of this class is still driven by the robot
        GuiActionRunner.execute(() -> {
            save.target().setCurrentDirectory(dir.toFile());
            save.target().setSelectedFile(file.toFile());
            save.target().approveSelection();
        });
        waitFor(name + " is written", () -> Files.exists(file));
        return file;
    }

    static int run(Path job, Path out) {
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter(), true),
                new PrintWriter(err, true),
                "run",
                job.toString(),
                "--out",
                out.toString());
        assertEquals(0, status, err.toString());
        return status;
    }

    private org.assertj.swing.fixture.JTextComponentFixture textFieldShowing(String text) {
        return window.textBox(new GenericTypeMatcher<>(JTextField.class, true) {
            @Override
            protected boolean isMatching(JTextField f) {
                return text.equals(f.getText());
            }
        });
    }

    private GenericTypeMatcher<javax.swing.JLabel> labelMatching(String part) {
        return new GenericTypeMatcher<>(javax.swing.JLabel.class, false) {
            @Override
            protected boolean isMatching(javax.swing.JLabel l) {
                return l.getText() != null && l.getText().contains(part);
            }
        };
    }

    private String treeText() {
        return GuiActionRunner.execute(() -> {
            javax.swing.JTree t =
                    window.robot().finder().findByName(window.target(), "stepnc-tree", javax.swing.JTree.class, false);
            return String.valueOf(t.getModel().getRoot());
        });
    }

    /** Every label, text field and text area of the window (shown or not), one after the other. */
    private String allText() {
        return GuiActionRunner.execute(() -> {
            StringBuilder sb = new StringBuilder();
            collect((java.awt.Container) window.target(), sb);
            return sb.toString();
        });
    }

    private static void collect(java.awt.Container c, StringBuilder sb) {
        for (java.awt.Component k : c.getComponents()) {
            if (k instanceof javax.swing.JLabel l && l.getText() != null) {
                sb.append(l.getText()).append('\n');
            } else if (k instanceof javax.swing.text.JTextComponent t) {
                sb.append(t.getText()).append('\n');
            } else if (k instanceof javax.swing.JTree t) {
                sb.append(t.getModel().getRoot()).append('\n');
            }
            if (k instanceof java.awt.Container cc) {
                collect(cc, sb);
            }
        }
    }

    private void waitFor(String what, BooleanSupplier test) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(test::getAsBoolean);
                    }
                },
                Timeout.timeout(120_000));
    }

    private void waitUntilNoTaskRuns() {
        waitFor(
                "no task is running",
                () -> window.robot()
                        .finder()
                        .findAll(new GenericTypeMatcher<>(javax.swing.JProgressBar.class, false) {
                            @Override
                            protected boolean isMatching(javax.swing.JProgressBar b) {
                                return b.isShowing();
                            }
                        })
                        .isEmpty());
    }
}
