package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.CycleTime;
import org.fresa.model.Move;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;

class StepNcViewModelTest {

    static StepNcViewModel loaded(String name) throws Exception {
        StepNcViewModel vm = new StepNcViewModel();
        vm.load(StepNcReader.read(Path.of("samples/stepnc", name)));
        return vm;
    }

    @Test
    void theTreeShowsWorkplansThenSkippedWorkingstepsAndNotes() throws Exception {
        StepNcViewModel.Node root = loaded("example2.stp").tree().orElseThrow();
        assertTrue(root.label().contains("3caras"));
        List<String> top =
                root.children().stream().map(StepNcViewModel.Node::label).toList();
        assertEquals("Workplan 'Main workplan'", top.get(0));
        assertEquals("Skipped workingsteps (14)", top.get(1));
        StepNcViewModel.Node main = root.children().get(0);
        assertEquals(3, main.children().size());
        assertEquals(9, main.children().get(0).children().size());
        assertTrue(main.children().get(0).children().get(0).workingstep().isPresent());
        assertTrue(main.children().get(0).children().get(0).label().startsWith("1. "));
    }

    @Test
    void unknownEntitiesAreVisibleInTheTree() throws Exception {
        StepNcViewModel.Node root =
                loaded("iso14649-11-example1-explicit-toolpaths.stp").tree().orElseThrow();
        assertTrue(
                root.children().stream().anyMatch(n -> n.label().startsWith("Entities not interpreted")),
                root.children().toString());
    }

    @Test
    void theDetailsGiveUnits() throws Exception {
        StepNcViewModel vm = loaded("iso14649-11-example1.stp");
        String text = String.join("\n", vm.details());
        assertTrue(text.contains("PLANAR_FACE"), text);
        assertTrue(text.contains("depth 5 mm"), text);
        assertTrue(text.contains("feed 0.04 m/s = 2400 mm/min"), text);
        assertTrue(text.contains("= 720 rpm, clockwise"), text);
        assertTrue(text.contains("diameter 18 mm"), text);
    }

    @Test
    void aHoleOnTheFrontFaceIsDrawnAsACircleInTheFrontView() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        StepNcProgram p = vm.program().orElseThrow();
        MachiningWorkingstep hole = p.workingsteps().get(11);
        vm.select(Optional.of(hole));
        PlotScene s = vm.plot();
        assertEquals("Front view (XZ)", s.title());
        PlotScene.Layer feature = s.layers().get(1);
        Arc2 circle = (Arc2) feature.curves().get(0);
        assertEquals(60.0, circle.center().x(), 1e-9);
        assertEquals(150.0, circle.center().y(), 1e-9);
        Box2 all = s.bounds().orElseThrow();
        assertEquals(200.0, all.width(), 1e-9);
    }

    @Test
    void theFrontViewNamesItsAxesXAndZ() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        vm.select(Optional.of(vm.program().orElseThrow().workingsteps().get(11)));
        PlotScene s = vm.plot();
        assertAll(
                () -> assertEquals("x (mm)", s.axes().horizontal()),
                () -> assertEquals("z (mm)", s.axes().vertical()),
                () -> assertEquals(
                        "z (mm)",
                        org.fresa.chart.ToolpathChart.frame(s)
                                .getXYPlot()
                                .getRangeAxis()
                                .getLabel()));
    }

    @Test
    void everyPlanningProblemIsListedAndNamesItsWorkingstep() throws Exception {
        StepNcViewModel vm = loaded("iso14649-11-example1.stp");
        StepNcProgram p = vm.program().orElseThrow();
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        vm.planned(plan);
        MachiningWorkingstep ws = p.workingsteps().get(1);
        assertAll(
                () -> assertEquals(
                        plan.problems(),
                        vm.problems().all().stream()
                                .map(WarningList.Warning::text)
                                .toList()),
                () -> assertEquals(
                        Optional.of(ws), vm.workingstepNamedIn("workingstep 'x' (#" + ws.instanceId() + "): no tool")),
                () -> assertEquals(
                        Optional.of(ws),
                        vm.workingstepNamedIn("workingstep '" + ws.id() + "': read but not in the moves: depth")),
                () -> assertEquals(Optional.empty(), vm.workingstepNamedIn("3 workingsteps: feed from the tool")));
    }

    @Test
    void theTopPocketIsDrawnAsItsRoundedRectangle() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        vm.select(Optional.of(vm.program().orElseThrow().workingsteps().get(8)));
        PlotScene s = vm.plot();
        assertEquals("Top view (XY)", s.title());
        // 140 x 140 at (100, 100) with its orthogonal radius 10 at the corners, drawn as arcs
        List<Curve2> outline = s.layers().get(1).curves();
        assertEquals(
                4,
                outline.stream()
                        .filter(c -> c instanceof Arc2 a && Math.abs(a.radius() - 10) < 1e-9)
                        .count());
        Box2 b = outline.stream().map(Curve2::bounds).reduce(Box2::union).orElseThrow();
        assertAll(
                () -> assertEquals(30.0, b.minX(), 1e-9),
                () -> assertEquals(170.0, b.maxX(), 1e-9),
                () -> assertEquals(30.0, b.minY(), 1e-9),
                () -> assertEquals(170.0, b.maxY(), 1e-9));
        double length = outline.stream().mapToDouble(Curve2::length).sum();
        assertEquals(4 * 120 + 2 * Math.PI * 10, length, 1e-9);
    }

    static final double EPS = 1e-9;

    /** Example 1 read and planned, with the named workingstep selected. */
    static StepNcViewModel planned(String name, String workingstep) throws Exception {
        StepNcViewModel vm = loaded(name);
        StepNcProgram p = vm.program().orElseThrow();
        vm.planned(ToolpathPlanner.plan(p, Tolerance.DEFAULT));
        vm.select(p.workingsteps().stream()
                .filter(w -> w.id().equals(workingstep))
                .findFirst());
        return vm;
    }

    static final String EX1 = "iso14649-11-example1.stp";
    static final String FACE = "WS FINISH PLANAR FACE1";
    static final String DRILL = "WS DRILL HOLE1";

    /**
     * Example 1's face by hand (security plane z 30, retract plane 10 above the face top z 5, D18,
     * feed 0.04 m/s = 2400 mm/min, plunge at half): per layer 6 passes of 147 mm (y -13.5..133.5)
     * and 5 steps of 16.4 mm at 2400; plunges 15 -> 2.5 and 15 -> 0 (27.5 mm) at 1200; rapids
     * 30 -> 15, 2.5 -> 15, 9 -> 91 across, 0 -> 15 and 15 -> 30 (139.5 mm) at 10000 mm/min.
     */
    @Test
    void theFacesCycleTimeIsTheHandComputation() throws Exception {
        CycleTime t = planned(EX1, FACE).workingstepTime().orElseThrow();
        double feedS = 2 * (6 * 147 + 5 * 16.4) / 2400.0 * 60 + 27.5 / 1200.0 * 60;
        double rapidS = 139.5 / 10000.0 * 60;
        assertAll(
                () -> assertEquals(2 * (6 * 147 + 5 * 16.4) + 27.5, t.feedLengthMm(), 1e-9),
                () -> assertEquals(139.5, t.rapidLengthMm(), 1e-9),
                () -> assertEquals(feedS, t.feedSeconds(), 1e-9),
                () -> assertEquals(rapidS, t.rapidSeconds(), 1e-9),
                () -> assertEquals(50.412, t.seconds(), 1e-9));
    }

    /** Example 1's drill point: 10 tan 31 deg (TWIST_DRILL D20, tool_top_angle 31, a 118 deg point). */
    static final double TIP = 10 * Math.tan(Math.toRadians(31));

    /**
     * The drill (feed 0.03 m/s = 1800 mm/min, DRILLING_TYPE_STRATEGY(0.75, 0.50, 2, 0.50, 0.75, 8))
     * rapids 30 -> 10, drills the through hole until its full diameter is 1 mm (the breakthrough)
     * past z -30: at 900 from 10 to -(2 + tip), at 1800 for 21 mm, at 1350 over the last 8 mm down
     * to -(31 + tip), then rapids back to 10 and 30 (81 mm + tip of rapids in all); the reamer (no
     * strategy, no point) reams to -31 and leaves at feed (82 mm fed, 40 mm of rapids). The program is the sum of its workingsteps.
     */
    @Test
    void theHolesAndTheProgramCycleTimesAreTheHandComputation() throws Exception {
        StepNcViewModel vm = planned(EX1, DRILL);
        double drill = (12 + TIP) / 900.0 * 60 + 21 / 1800.0 * 60 + 8 / 1350.0 * 60 + (81 + TIP) / 10000.0 * 60;
        assertEquals(drill, vm.workingstepTime().orElseThrow().seconds(), 1e-9);
        vm.select(vm.program().orElseThrow().workingsteps().stream()
                .filter(w -> w.id().equals("WS REAM HOLE1"))
                .findFirst());
        double ream = 82 / 1800.0 * 60 + 40 / 10000.0 * 60;
        assertEquals(ream, vm.workingstepTime().orElseThrow().seconds(), 1e-9);
        double sum = 0;
        for (MachiningWorkingstep ws : vm.program().orElseThrow().workingsteps()) {
            vm.select(Optional.of(ws));
            sum += vm.workingstepTime().orElseThrow().seconds();
        }
        double total = vm.programTime().orElseThrow().seconds();
        assertEquals(sum, total, 1e-9);
        assertTrue(total > 50.412 + drill + ream, "pockets take time too: " + total);
        List<String> lines = vm.cycleTime();
        assertEquals(
                "Cycle time of this workingstep: "
                        + StepNcViewModel.seconds(
                                vm.workingstepTime().orElseThrow().seconds()) + " (feed",
                lines.get(0).substring(0, lines.get(0).indexOf("(feed") + 5));
        assertTrue(
                lines.get(1)
                        .startsWith(
                                "Cycle time of the program (5 of 5 workingsteps): " + StepNcViewModel.seconds(total)),
                lines.get(1));
        assertTrue(lines.get(2).contains("rapids at 10000 mm/min"), lines.get(2));
    }

    @Test
    void timesReadAsSecondsThenMinutes() {
        assertEquals("50.4 s", StepNcViewModel.seconds(50.412));
        assertEquals("3 min 05.2 s", StepNcViewModel.seconds(185.2));
    }

    @Test
    void theFaceHasTwoLayersAndEachShowsItsOwnPassesAndTheWayIn() throws Exception {
        StepNcViewModel vm = planned(EX1, FACE);
        // the face's top is z 5: layers at z 2.5 and 0
        assertEquals(List.of(new StepNcViewModel.Layer(1, 2.5), new StepNcViewModel.Layer(2, 5.0)), vm.layers());
        assertEquals(
                List.of("All 2 layers", "Layer 1 of 2: 2.5 mm deep", "Layer 2 of 2: 5 mm deep"), vm.layerChoices());
        assertEquals(29, vm.shown().orElseThrow().moves().size());
        vm.selectLayer(1);
        StepNcViewModel.Shown one = vm.shown().orElseThrow();
        vm.selectLayer(2);
        StepNcViewModel.Shown two = vm.shown().orElseThrow();
        assertEquals(29, one.moves().size() + two.moves().size());
        assertEquals(new Vec3(91, -13.5, 30), one.start());
        // layer 2 starts where layer 1's last pass ended, and rises, crosses and plunges into z 0
        assertEquals(new Vec3(9, -13.5, 2.5), two.start());
        assertEquals(new Vec3(9, -13.5, 15), two.moves().get(0).end());
        for (StepNcViewModel.Shown sh : List.of(one, two)) {
            double z = sh == one ? 2.5 : 0;
            Vec3 at = sh.start();
            int passes = 0;
            for (Move m : sh.moves()) {
                if (m instanceof Move.Linear && at.z() == m.end().z()) {
                    assertEquals(z, m.end().z(), EPS);
                    passes++;
                }
                at = m.end();
            }
            assertEquals(11, passes);
        }
        assertThrows(IllegalArgumentException.class, () -> vm.selectLayer(3));
    }

    @Test
    void aDrillingWorkingstepHasNoLayersButAllItsMoves() throws Exception {
        StepNcViewModel vm = planned(EX1, DRILL);
        assertEquals(List.of(), vm.layers());
        assertEquals(List.of("All moves"), vm.layerChoices());
        // rapid in, three feed zones of the drilling strategy each after its spindle speed (720, 960, 480 rpm),
        // rapid out to the retract and security planes
        assertEquals(9, vm.shown().orElseThrow().moves().size());
    }

    /**
     * The drill's moves take 0.12 s (rapid 20 mm), (12 + tip) / 15 s (feed 900), 0.7 s (feed
     * 21 mm at 1800), 0.3556 s (8 mm at 1350) and the rapids out: at half of the total the tool is in
     * the full-feed zone, fed at 30 mm/s down from z -(2 + tip).
     */
    @Test
    void theReplaySliderPutsTheToolWhereTheMachiningTimeSays() throws Exception {
        StepNcViewModel vm = planned(EX1, DRILL);
        assertEquals(StepNcViewModel.REPLAY_STEPS, vm.replay());
        assertEquals(new Vec3(20, 60, 30), vm.replayPoint().orElseThrow().position());
        vm.setReplay(StepNcViewModel.REPLAY_STEPS / 2);
        StepNcViewModel.ReplayPoint half = vm.replayPoint().orElseThrow();
        double total = (12 + TIP) / 900.0 * 60 + 21 / 1800.0 * 60 + 8 / 1350.0 * 60 + (81 + TIP) / 10000.0 * 60;
        double intoFullFeed = total / 2 - 0.12 - (12 + TIP) / 15;
        assertAll(
                () -> assertEquals(4, half.moveIndex()),
                () -> assertEquals(total / 2, half.timeS(), 1e-9),
                () -> assertEquals(total, half.totalS(), 1e-9),
                () -> assertEquals(20, half.position().x(), EPS),
                () -> assertEquals(60, half.position().y(), EPS),
                () -> assertEquals(
                        -(2 + TIP) - intoFullFeed * 30, half.position().z(), 1e-9),
                () -> assertEquals(-10.0641, half.position().z(), 1e-4));
        assertTrue(
                vm.replayText()
                        .startsWith("1.4 s of 2.8 s: move 5 of 9 (feed 1800 mm/min), tool at (20, 60, -10.0641) mm"),
                vm.replayText());
        vm.setReplay(0);
        assertEquals(new Vec3(20, 60, 30), vm.replayPoint().orElseThrow().position());
        assertEquals(-1, vm.replayPoint().orElseThrow().moveIndex());
        vm.setReplay(-5);
        assertEquals(0, vm.replay());
        vm.setReplay(10_000);
        assertEquals(StepNcViewModel.REPLAY_STEPS, vm.replay());
    }

    /** A dwell takes its time where the tool is; spindle events take none. */
    @Test
    void theReplayWaitsAtADwellAndNamesIt() {
        Vec3 bottom = new Vec3(0, 0, -10);
        List<Move> moves = List.of(
                new Move.Linear(bottom, 600),
                new Move.Dwell(bottom, 2),
                new Move.SpindleStop(bottom),
                new Move.Rapid(new Vec3(0, 0, 0)));
        StepNcViewModel.Shown sh = new StepNcViewModel.Shown(Vec3.ZERO, moves);
        // 1 s of feed, 2 s of dwell, 0.06 s of rapid
        StepNcViewModel.ReplayPoint r = StepNcViewModel.replayAt(sh, 2.0 / 3.06);
        assertAll(
                () -> assertEquals(1, r.moveIndex()),
                () -> assertEquals(bottom, r.position()),
                () -> assertEquals(3.06, r.totalS(), 1e-12));
        assertEquals("dwell 2 s", StepNcViewModel.kindText(moves.get(1)));
        assertEquals("spindle stop", StepNcViewModel.kindText(moves.get(2)));
        assertEquals(
                "spindle 800 rpm counter-clockwise",
                StepNcViewModel.kindText(new Move.SpindleStart(bottom, 800, false)));
    }

    @Test
    void replayingAnArcFollowsTheArc() throws Exception {
        StepNcViewModel vm = planned(EX1, "WS FINISH POCKET1");
        StepNcViewModel.Shown sh = vm.shown().orElseThrow();
        Vec3 at = sh.start();
        boolean helix = false;
        boolean planar = false;
        for (Move m : sh.moves()) {
            if (m instanceof Move.Circular c) {
                // the pass enters on a helix (it rises along the arc's normal) and then cuts planar
                // arcs: both keep their radius in the arc's plane and rise evenly with the sweep
                Vec3 mid = StepNcViewModel.pointOn(at, m, 0.5);
                assertEquals(radiusInPlane(at, c), radiusInPlane(mid, c), 1e-9);
                double rise = c.end().minus(at).dot(c.normal());
                assertEquals(rise / 2, mid.minus(at).dot(c.normal()), 1e-9);
                helix |= Math.abs(rise) > 1e-9;
                planar |= Math.abs(rise) <= 1e-9;
            }
            at = m.end();
        }
        assertTrue(helix && planar, "helix " + helix + ", planar arc " + planar);
    }

    private static double radiusInPlane(Vec3 p, Move.Circular c) {
        Vec3 d = p.minus(c.center());
        return d.minus(c.normal().times(d.dot(c.normal()))).norm();
    }

    @Test
    void theToolpathIsPlottedOverTheFeatureWithArcsRapidsAndTheTool() throws Exception {
        StepNcViewModel vm = planned(EX1, "WS FINISH POCKET1");
        vm.setReplay(StepNcViewModel.REPLAY_STEPS / 3);
        PlotScene s = vm.plot();
        List<String> names = s.layers().stream().map(PlotScene.Layer::name).toList();
        // example 1's workpiece has no BLOCK shape: the pocket outline, then the path
        assertEquals(List.of("CLOSED_POCKET 'POCKET1'", "rapid", "feed", "travelled", "tool"), names);
        assertEquals(PlotScene.Style.OUTLINE, s.layers().get(0).style());
        assertEquals(PlotScene.Style.RAPID, s.layers().get(1).style());
        assertEquals(PlotScene.Style.FEED, s.layers().get(2).style());
        List<Curve2> feeds = s.layers().get(2).curves();
        // the corner arcs (pocket corner radius 10 - tool radius 9 = 1) are drawn as arcs
        assertTrue(
                feeds.stream().anyMatch(c -> c instanceof Arc2 a && Math.abs(a.radius() - 1) < 1e-9), "no corner arc");
        assertTrue(s.layers().get(1).curves().stream().allMatch(c -> c instanceof Segment2));
        // the travelled part is shorter than all feeds, and the tool is a D18 circle at the replay point
        double all = feeds.stream().mapToDouble(Curve2::length).sum();
        double done =
                s.layers().get(3).curves().stream().mapToDouble(Curve2::length).sum();
        assertTrue(done > 0 && done < all, done + " of " + all);
        Arc2 tool = (Arc2) s.layers().get(4).curves().get(0);
        Vec3 at = vm.replayPoint().orElseThrow().position();
        assertAll(
                () -> assertEquals(9, tool.radius(), 1e-9),
                () -> assertEquals(at.x(), tool.center().x(), 1e-9),
                () -> assertEquals(at.y(), tool.center().y(), 1e-9));
        assertTrue(s.title().endsWith(": WS FINISH POCKET1"), s.title());
    }

    @Test
    void aHoleOnTheFrontFaceIsMilledAlongArcsDrawnAsArcsInTheFrontView() throws Exception {
        StepNcViewModel vm = loaded("example2.stp");
        StepNcProgram p = vm.program().orElseThrow();
        vm.planned(ToolpathPlanner.plan(p, Tolerance.DEFAULT));
        // workingstep 12: milling the Ø30 hole at (60, 0, 150), axis -Y, with the Ø20 mill
        vm.select(Optional.of(p.workingsteps().get(11)));
        PlotScene s = vm.plot();
        assertEquals("Front view (XZ)", s.title().substring(0, "Front view (XZ)".length()));
        List<Arc2> arcs = s.layers().get(3).curves().stream()
                .filter(c -> c instanceof Arc2)
                .map(c -> (Arc2) c)
                .toList();
        assertTrue(!arcs.isEmpty(), "no arcs in the front view");
        for (Arc2 a : arcs) {
            assertEquals(60, a.center().x(), 1e-6);
            assertEquals(150, a.center().y(), 1e-6);
            assertTrue(a.radius() <= 15 - 10 + 1e-9, "beyond the hole wall: " + a.radius());
        }
    }

    @Test
    void selectingAnotherWorkingstepShowsAllItsLayersFromTheEnd() throws Exception {
        StepNcViewModel vm = planned(EX1, FACE);
        vm.selectLayer(2);
        vm.setReplay(3);
        vm.select(vm.program().orElseThrow().workingsteps().stream()
                .filter(w -> w.id().equals("WS ROUGH POCKET1"))
                .findFirst());
        assertEquals(0, vm.layer());
        assertEquals(StepNcViewModel.REPLAY_STEPS, vm.replay());
        assertTrue(vm.layers().size() > 1);
        assertTrue(String.join("\n", vm.details()).contains("Cycle time of this workingstep"));
    }

    @Test
    void theTabsPathChoiceGoesIntoTheJobKeepingItsOtherStepNcSettings() {
        Path file = Path.of("samples/stepnc/example2.stp");
        org.fresa.job.Job job = org.fresa.job.Job.empty(org.fresa.job.JobTask.ofId("robot"))
                .withStepnc(new org.fresa.job.JobSettings.StepNcSettings(
                        file, org.fresa.post.MillingPost.SIEMENS_840D, true, 2));
        var s = StepNcViewModel.settingsFor(job, file, org.fresa.toolpath.PathConvention.THESIS);
        assertEquals(
                new org.fresa.job.JobSettings.StepNcSettings(
                        file,
                        org.fresa.post.MillingPost.SIEMENS_840D,
                        true,
                        2,
                        org.fresa.pocket.EntryRule.DEFAULT,
                        org.fresa.toolpath.PathConvention.THESIS),
                s);
        assertEquals(org.fresa.toolpath.PathConvention.THESIS, s.choices().paths());
        // another file: the job's post, the default choices, the paths shown
        Path other = Path.of("samples/stepnc/iso14649-11-example1.stp");
        var o = StepNcViewModel.settingsFor(job, other, org.fresa.toolpath.PathConvention.FRESA);
        assertEquals(new org.fresa.job.JobSettings.StepNcSettings(other, org.fresa.post.MillingPost.SIEMENS_840D), o);
        assertEquals(
                List.of("Fresa's paths", "the 2016 robot thesis's points"),
                StepNcViewModel.PATHS.stream().map(StepNcViewModel::pathsLabel).toList());
    }

    /**
     * The tab's problem list says what {@code fresa run} of a toolpath job says of the same file:
     * the planner's problems and the workingsteps the 3-axis program leaves for another setup.
     */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(
            strings = {
                "samples/stepnc/example2.stp",
                "samples/stepnc/iso14649-11-example1-explicit-toolpaths.stp",
                "../shared/corpus/stepnc/grima/testBoxy.p21"
            })
    void theProblemsAreWhatTheToolpathRunSays(String name, @org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        Path file = Path.of(name);
        org.junit.jupiter.api.Assumptions.assumeTrue(java.nio.file.Files.isRegularFile(file), "no " + file);
        org.fresa.job.JobSettings.StepNcSettings s =
                new org.fresa.job.JobSettings.StepNcSettings(file, org.fresa.post.MillingPost.LINUXCNC);
        org.fresa.job.Job job =
                org.fresa.job.Job.empty(org.fresa.job.JobTask.TOOLPATH).withStepnc(s);
        org.fresa.job.TaskOutcome run = org.fresa.job.ToolpathService.run(
                job, new org.fresa.io.OutputFolder(dir), org.fresa.job.ProgressMonitor.NONE);
        assertEquals(1, run.exitStatus(), "the run refuses workingsteps of " + file);
        org.fresa.job.ToolpathService.Planned planned =
                org.fresa.job.ToolpathService.compute(file, s.choices(), org.fresa.job.ProgressMonitor.NONE);
        StepNcViewModel vm = new StepNcViewModel();
        vm.load(planned.program());
        vm.planned(planned.plan(), StepNcViewModel.problemsOf(job, file, planned, s));
        List<String> shown =
                vm.problems().all().stream().map(WarningList.Warning::text).toList();
        for (String p : run.problems()) {
            assertTrue(shown.contains(p), "the tab does not say: " + p + "\n" + shown);
        }
    }
}
