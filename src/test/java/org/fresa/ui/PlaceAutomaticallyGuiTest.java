package org.fresa.ui;

import java.nio.file.Path;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.JobSettings;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;

/** The Position tab's "Place automatically" under a (virtual) display; a headless run skips it. */
class PlaceAutomaticallyGuiTest extends WindowGuiTest {

    @Test
    void thePlacementFoundFillsTheFieldsAndTheTriceptReachesEveryPoint() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitUntilNoTaskRuns();
        window.tabbedPane("tabs").selectTab("Robot");
        window.comboBox("robot-choice").selectItem("tricept806");

        window.tabbedPane("tabs").selectTab("Position");
        // at the origin the part is in the Tricept's base: the search moves the table far below it
        window.button("position-place-auto").click();
        Pause.pause(
                new Condition("the job's placement is the one found") {
                    @Override
                    public boolean test() {
                        Placement p = GuiActionRunner.execute(
                                () -> model.job().robot().orElseThrow().robotTable());
                        return p.zMm() < -1000;
                    }
                },
                Timeout.timeout(180_000));
        waitUntilNoTaskRuns();
        Placement p =
                GuiActionRunner.execute(() -> model.job().robot().orElseThrow().robotTable());
        window.textBox("position-rt-Z").requireText(RobotViewModel.num(p.zMm()));
        window.textBox("position-rt-RZ").requireText(RobotViewModel.num(p.rzDeg()));
        window.tabbedPane("position-results").selectTab("Summary");
        // the summary first says which placement was found; the live reachability of the new
        // placement then takes its place, and must find every target reached
        Pause.pause(
                new Condition("the summary says the placement found reaches every target") {
                    @Override
                    public boolean test() {
                        String said = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return said.startsWith("placement found: --robot-table ") || said.contains("Out of reach: 0");
                    }
                },
                Timeout.timeout(60_000));

        window.button("position-compute").click();
        Pause.pause(
                new Condition("every point is reached from the placement found") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.contains("Unreachable: 0");
                    }
                },
                Timeout.timeout(120_000));
        shoot("position-place-auto.png");
    }

    /**
     * A job that searches its table placement (place="auto") is computed where fresa run solves it,
     * at the placement the search finds, not at the fields' (the origin, where the part is in the
     * robot's base), and the Summary says what the run says.
     */
    @Test
    void aJobThatSearchesItsPlacementIsComputedWhereTheRunSolvesIt(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        org.fresa.job.Job job = model.job()
                .withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))
                .withRobot(new JobSettings.RobotSettings(
                        "irb140",
                        Placement.ORIGIN,
                        Placement.ORIGIN,
                        java.util.List.of("csv"),
                        java.util.Optional.empty(),
                        java.util.OptionalDouble.empty(),
                        org.fresa.cell.TablePlacing.AUTO));
        org.fresa.job.TaskOutcome run = org.fresa.job.RobotService.run(
                job, new org.fresa.io.OutputFolder(dir), org.fresa.job.ProgressMonitor.NONE);
        String what = String.valueOf(((java.util.Map<?, ?>) run.summary().get("placement_search")).get("what"));
        // the placement, without the search's own timing
        String found = what.substring(0, what.indexOf(" reaches all"));
        GuiActionRunner.execute(() -> model.setJob(job));
        waitUntilNoTaskRuns();
        window.tabbedPane("tabs").selectTab("Position");
        window.button("position-compute").click();
        window.tabbedPane("position-results").selectTab("Summary");
        Pause.pause(
                new Condition("the trajectory is computed") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.contains("Unreachable: ");
                    }
                },
                Timeout.timeout(120_000));
        waitUntilNoTaskRuns();
        String reach = GuiActionRunner.execute(
                () -> window.label("position-reach").target().getText());
        org.junit.jupiter.api.Assertions.assertTrue(
                reach.startsWith(found + " reaches all"), reach + "\nfresa run: " + what);
        window.textBox("position-summary").requireText(java.util.regex.Pattern.compile("(?s).*Unreachable: 0\n.*"));
        java.util.List<String> rows =
                java.util.Arrays.asList(window.list("position-warnings").contents());
        org.junit.jupiter.api.Assertions.assertEquals(run.problems().size(), rows.size(), rows.toString());
        for (String p : run.problems()) {
            org.junit.jupiter.api.Assertions.assertTrue(
                    rows.stream().anyMatch(r -> r.endsWith(p)), "the Summary does not say: " + p + "\n" + rows);
        }
        shoot("position-place-auto-job.png");
    }

    /**
     * With a 3 m tool no placement reaches a target: fresa run refuses the job, and Compute shows
     * no trajectory and says what the run says.
     */
    @Test
    void aJobWhosePlacementSearchFailsIsRefusedAsTheRunRefusesIt(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        org.fresa.job.Job job = model.job()
                .withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))
                .withRobot(new JobSettings.RobotSettings(
                        "irb140",
                        Placement.ORIGIN,
                        Placement.ORIGIN,
                        java.util.List.of("csv"),
                        java.util.Optional.empty(),
                        java.util.OptionalDouble.of(3000),
                        org.fresa.cell.TablePlacing.AUTO));
        org.fresa.job.TaskOutcome run = org.fresa.job.RobotService.run(
                job, new org.fresa.io.OutputFolder(dir), org.fresa.job.ProgressMonitor.NONE);
        org.junit.jupiter.api.Assertions.assertEquals(
                1, run.exitStatus(), run.problems().toString());
        GuiActionRunner.execute(() -> model.setJob(job));
        waitUntilNoTaskRuns();
        window.tabbedPane("tabs").selectTab("Position");
        window.button("position-compute").click();
        window.tabbedPane("position-results").selectTab("Summary");
        Pause.pause(
                new Condition("the refusal is shown") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.startsWith("No trajectory");
                    }
                },
                Timeout.timeout(120_000));
        waitUntilNoTaskRuns();
        // the same words but the search's own timing
        java.util.function.UnaryOperator<String> untimed =
                t -> t.replaceAll(" tried in [0-9.]+ s, [0-9.]+ s of CPU", " tried");
        java.util.List<String> rows = java.util.Arrays.stream(
                        window.list("position-warnings").contents())
                .map(untimed)
                .toList();
        org.junit.jupiter.api.Assertions.assertEquals(run.problems().size(), rows.size(), rows.toString());
        for (String p : run.problems()) {
            org.junit.jupiter.api.Assertions.assertTrue(
                    rows.stream().anyMatch(r -> r.endsWith(untimed.apply(p))),
                    "the Summary does not say: " + p + "\n" + rows);
        }
        String reach = GuiActionRunner.execute(
                () -> window.label("position-reach").target().getText());
        org.junit.jupiter.api.Assertions.assertEquals(
                untimed.apply(run.problems().get(run.problems().size() - 1)), untimed.apply(reach));
        shoot("position-place-auto-refused.png");
    }

    /** For looking at after the build: target/screenshots/position-place-auto.png. */
    private void shoot(String name) {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            java.nio.file.Files.createDirectories(Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(
                    img, "png", Path.of("target", "screenshots", name).toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private void waitUntilNoTaskRuns() {
        Pause.pause(
                new Condition("no task is running") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.robot()
                                .finder()
                                .findAll(
                                        new org.assertj.swing.core.GenericTypeMatcher<>(
                                                javax.swing.JProgressBar.class, false) {
                                            @Override
                                            protected boolean isMatching(javax.swing.JProgressBar b) {
                                                return b.isShowing();
                                            }
                                        })
                                .isEmpty());
                    }
                },
                Timeout.timeout(60_000));
    }
}
