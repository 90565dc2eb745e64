package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.io.OutputFolder;
import org.fresa.model.CycleTime;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.ExpectedMotions;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.fresa.toolpath.Profile;
import org.fresa.toolpath.Swept;
import org.fresa.toolpath.ToolpathCsv;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Geometry;

class ToolpathServiceTest {

    static final Path EXAMPLE1 = Path.of("samples/stepnc/iso14649-11-example1.stp");
    static final Path EXAMPLE2 = Path.of("samples/stepnc/example2.stp");

    static Toolpath plan(Path file) throws Exception {
        ToolpathPlanner.Plan p = ToolpathPlanner.plan(StepNcReader.read(file), Tolerance.DEFAULT);
        assertEquals(p.workingsteps(), p.planned(), p.problems().toString());
        return p.toolpath();
    }

    @ParameterizedTest
    @ValueSource(strings = {"samples/stepnc/iso14649-11-example1.stp", "samples/stepnc/example2.stp"})
    @InterpreterCheck
    void theProgramIsAcceptedByLinuxCncAndItsMotionsAreTheCsvsMoves(String input, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        TaskOutcome o = ToolpathService.run(
                Path.of(input), org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        // example 2's front and left faces (tool axes (0, -1, 0) and (-1, 0, 0)) need the part
        // turned: the 3-axis program holds its top's 9 workingsteps and names the other 17
        boolean sides = input.endsWith("example2.stp");
        assertEquals(sides ? 1 : 0, o.exitStatus(), o.problems().toString());
        if (sides) {
            assertEquals(
                    List.of(
                            "tool axis (0, -1, 0): a 3-axis program machines along +Z only; 11 workingsteps need"
                                    + " another setup",
                            "tool axis (-1, 0, 0): a 3-axis program machines along +Z only; 6 workingsteps need"
                                    + " another setup"),
                    o.problems().stream().filter(p -> p.startsWith("tool axis")).toList());
        }
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 18);
        assertEquals(0, r.exitStatus(), r.stderr());
        // the interpreter's motions are the planned moves along +Z (each section's start, then its moves)
        plan(Path.of(input));
        ToolpathPlanner.Plan alongZ = ToolpathService.alongMachineZ(
                ToolpathPlanner.plan(StepNcReader.read(Path.of(input)), Tolerance.DEFAULT));
        assertEquals(sides ? 9 : alongZ.workingsteps(), alongZ.planned());
        List<Rs274.Canon> expected = ExpectedMotions.of(alongZ.toolpath(), false, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
        assertCsvHoldsTheMotions(dir, r);
    }

    /**
     * Example 1 with a multistep drilling (dwell_time_step 0.5 s, dwell_time_bottom 1.5 s) and a
     * ream that dwells 0.75 s before its spindle stop: LinuxCNC dwells where the toolpath does,
     * toolpath.csv has a dwell row for each DWELL, and the cycle time counts them.
     */
    @Test
    @InterpreterCheck
    void aProgramWithDwellsIsAcceptedByLinuxCncAndItsDwellsAreTheCsvsDwells(@TempDir Path dir) throws Exception {
        String text = Files.readString(EXAMPLE1)
                .replace(
                        "#20= DRILLING($,$,'DRILL HOLE1',10.000,$,#44,#45,#41,$,$,$,$,$,#46);",
                        "#20= MULTISTEP_DRILLING($,$,'DRILL HOLE1',10.000,$,#44,#45,#41,$,$,$,1.5,$,#46,2.0,12.0,6.0,0.5);")
                .replace(
                        "#21= REAMING($,$,'REAM HOLE1',10.000,$,#47,#48,#41,$,$,$,$,$,#49,.T.,$,$);",
                        "#21= REAMING($,$,'REAM HOLE1',10.000,$,#47,#48,#41,$,$,$,0.75,$,#49,.T.,$,$);");
        Path input = dir.resolve("dwells.stp");
        Files.writeString(input, text);
        Path out = dir.resolve("out");
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        Toolpath path = plan(input);
        List<Double> dwells = new ArrayList<>();
        for (ToolpathSection s : path.sections()) {
            s.moves().stream()
                    .filter(m -> m instanceof Move.Dwell)
                    .forEach(m -> dwells.add(((Move.Dwell) m).seconds()));
        }
        // steps to 12, 18, 24, 30, 36 mm deep, then the through bottom at 30 + the point (36.0086); then the ream
        assertEquals(List.of(0.5, 0.5, 0.5, 0.5, 0.5, 1.5, 0.75), dwells);
        assertEquals(4.75, (double) o.summary().get("dwell_time_s"), 1e-12);
        CycleTime total = CycleTime.ZERO;
        for (ToolpathSection s : path.sections()) {
            total = total.plus(CycleTime.of(s, ToolpathService.RAPID_MM_PER_MIN));
        }
        assertEquals(
                total.feedSeconds() + total.rapidSeconds() + 4.75,
                (double) o.summary().get("cycle_time_s"),
                1e-9);
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(out.resolve("program.ngc"), 18);
        assertEquals(0, r.exitStatus(), r.stderr());
        List<Rs274.Canon> expected = ExpectedMotions.of(path, false, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
        assertEquals(
                7, r.motions().stream().filter(c -> c.kind().equals("dwell")).count());
        assertCsvHoldsTheMotions(out, r);
    }

    /** toolpath.csv holds the interpreter's motions: straight rows and dwells one to one, each arc as points on it. */
    static void assertCsvHoldsTheMotions(Path dir, Rs274.Result r) throws Exception {
        List<ToolpathCsv.Row> rows =
                ToolpathCsv.read(new StringReader(Files.readString(dir.resolve("toolpath.csv"))), "csv");
        int i = 0;
        for (Rs274.Canon c : r.motions()) {
            if (!c.kind().equals("arc")) {
                ToolpathCsv.Row row = rows.get(i++);
                assertEquals(c.kind(), row.move(), "row " + row.index());
                assertTrue(row.point().distance(c.end()) <= 0.0011, "row " + row.index() + " vs " + c);
                if (c.kind().equals("dwell")) {
                    // a dwell row's feed column is its time in seconds
                    assertEquals(c.seconds(), row.feedMmPerMin(), 5e-4, "row " + row.index());
                }
                continue;
            }
            Vec3 n = c.normal();
            ToolpathCsv.Row row;
            do {
                row = rows.get(i++);
                assertTrue(row.move().startsWith("arc"), "row " + row.index());
                Vec3 radial = row.point().minus(c.center());
                Vec3 inPlane = radial.minus(n.times(radial.dot(n)));
                Vec3 endRadial = c.end().minus(c.center());
                double rEnd = endRadial.minus(n.times(endRadial.dot(n))).norm();
                assertEquals(rEnd, inPlane.norm(), 0.002, "row " + row.index() + " off the arc " + c);
            } while (row.point().distance(c.end()) > 0.0011);
        }
        assertEquals(rows.size(), i);
    }

    static ToolpathSection section(Toolpath p, String label) {
        return p.sections().stream()
                .filter(s -> s.label().equals(label))
                .findFirst()
                .orElseThrow();
    }

    /**
     * Example 1's planar face, x 0..100, y 0..120, finished at z 0.
     *
     * <p>Against NIST's interpreter (samples/stepnc/iso14649-11-example1.nist-canonical.txt,
     * lines 13-41): the same 6 bidirectional passes along +Y from y -13.5 to 133.5 (the tool edge
     * clears the boundary by 0.25 D), the same two layers at z 2.5 and 0, and the same stepping to
     * the left (-X) as BIDIRECTIONAL(.., .LEFT.) asks. NIST steps by exactly 17.1 = 18 (1 - 0.05)
     * from x 91.9, so its first pass overhangs x = 100 by 0.9 mm and its last (6.4) overhangs x = 0
     * by 2.6 mm; we spread the same 6 passes evenly between the tool-edge-flush positions 91 and 9,
     * 16.4 apart (below the 17.1 limit), so both sides are cut with the edge on the boundary. NIST
     * links layers by a traverse at z 15 back to the first pass; so do we (retract plane 10 above
     * the face's top at z 5).
     */
    @Test
    void exampleOnesFaceIsClearedAtZeroWithPassesLikeNists() throws Exception {
        Toolpath p = plan(EXAMPLE1);
        ToolpathSection face = section(p, "WS FINISH PLANAR FACE1");
        Geometry box =
                Swept.polygon(new Profile.RoundedRectangle(new Vec2(50, 60), 100, 120, 0).contour(Tolerance.DEFAULT));
        Geometry cut = Swept.sweep(face, 9, 1e-9);
        assertTrue(
                box.difference(cut).getArea() < 1e-6,
                "uncut " + box.difference(cut).getArea());
        List<Double> xs = new ArrayList<>();
        Vec3 at = face.start();
        for (Move m : face.moves()) {
            if (m instanceof Move.Linear
                    && at.z() == 0
                    && m.end().z() == 0
                    && at.x() == m.end().x()) {
                xs.add(m.end().x());
                assertEquals(-13.5, Math.min(at.y(), m.end().y()), 1e-9);
                assertEquals(133.5, Math.max(at.y(), m.end().y()), 1e-9);
            }
            at = m.end();
        }
        assertEquals(
                List.of(91.0, 74.6, 58.2, 41.8, 25.4, 9.0),
                xs.stream().map(x -> Math.round(x * 1e6) / 1e6).toList());
    }

    @Test
    void exampleOnesPocketFloorIsClearedAndItsWallsAreNeverCutBeyond() throws Exception {
        Toolpath p = plan(EXAMPLE1);
        Geometry pocket =
                Swept.polygon(new Profile.RoundedRectangle(new Vec2(70, 70), 50, 80, 10).contour(Tolerance.DEFAULT));
        for (String ws : List.of("WS ROUGH POCKET1", "WS FINISH POCKET1")) {
            ToolpathSection s = section(p, ws);
            Geometry below = Swept.sweep(s, 9, -1e-9);
            assertTrue(Swept.gouge(pocket, below) < 1e-3, ws + " cuts beyond the wall: " + Swept.gouge(pocket, below));
            assertTrue(s.moves().stream().allMatch(m -> m.end().z() >= -30 - 1e-9), ws + " below the floor");
        }
        Geometry floor = Swept.sweep(section(p, "WS FINISH POCKET1"), 9, -30 + 1e-9);
        // corner radius 10 > tool radius 9: nothing is unavoidable, all the floor must go; the 0.005 mm
        // margin absorbs JTS's polygonal discs (64 segments a quadrant fall 0.0007 mm short of R 9)
        Geometry inner = pocket.buffer(-0.005, Swept.QUADRANT_SEGMENTS);
        assertTrue(
                inner.difference(floor).getArea() < 1e-6,
                "uncut floor " + inner.difference(floor).getArea());
    }

    /**
     * Example 1's through hole at (20, 60), drilled with DRILLING_TYPE_STRATEGY(0.75, 0.50,
     * 2.0, 0.50, 0.75, 8.0) by the D20 TWIST_DRILL (tool_top_angle 31 deg from the plane, a 118 deg
     * point: tip 10 tan 31 = 6.0086 mm) at 1800 mm/min, retract plane 10.
     *
     * <p>Against NIST's interpreter (samples/stepnc/iso14649-11-example1.nist-canonical.txt,
     * lines 50-62): feed 900 from z 10 to -9.1378, 1800 to -15.1378, 1350 to -37.1378, out at 1800.
     * Same feeds (0.5 F, F, 0.75 F), same start zone rule (until the full diameter is 2 mm deep,
     * the tip one point length deeper), same first zone starting at the retract plane. Differences:
     * <ul>
     * <li>Point length: NIST's is 7.1378 mm, ours 6.0086 = r tan 31 deg; NIST's figure is close to
     * (r - edge_radius) tan 31 + edge_radius / cos 31 = 7.1402 (edge_radius 2) but not equal, and its
     * source is not in ../shared, so the 1.13 mm is left unexplained. NIST goes until the full
     * diameter reaches z -30, ours 1 mm further (the default breakthrough, so that no burr of the
     * exit is left uncut), to -37.0086.
     * <li>End zone: NIST starts the reduced end feed 8 mm + tip below the top (z -15.1378), i.e. it
     * measures depth_of_end from the top like depth_of_start and reduces 22 mm of travel; ISO's
     * depth_of_end is the last part of the drilling, so we reduce the last 8 mm (from -29.0086).
     * <li>Out: NIST retracts at 1800 mm/min; feed_on_retract is unset, so our drill leaves at rapid.
     * <li>Spindle: NIST sets 720 / 960 / 480 rpm (reduced_cut_at_start/end 0.75, 0.5) where the
     * zones begin, and so do we (spindle starts at the new speed, at our zone boundaries).
     * <li>Ream: NIST stops the spindle at the bottom (spindle_stop_at_bottom) and leaves at feed;
     * so do we, and start the spindle again at the retract height. NIST reams to z -30, we ream
     * the breakthrough further, to -31.
     * </ul>
     */
    @Test
    void exampleOnesThroughHoleIsDrilledWithTheStrategysFeedsLikeNists() throws Exception {
        Toolpath p = plan(EXAMPLE1);
        ToolpathSection drill = section(p, "WS DRILL HOLE1");
        double tip = 10 * Math.tan(Math.toRadians(31));
        double breakthrough = 1;
        List<double[]> feeds = new ArrayList<>();
        for (Move m : drill.moves()) {
            if (m.end().z() < 0) {
                assertEquals(20, m.end().x(), 1e-9);
                assertEquals(60, m.end().y(), 1e-9);
            }
            if (m instanceof Move.Linear l) {
                feeds.add(new double[] {l.end().z(), l.feedMmPerMin()});
            }
        }
        assertEquals(3, feeds.size());
        assertAll(
                () -> assertEquals(-(2 + tip), feeds.get(0)[0], 1e-9),
                () -> assertEquals(900, feeds.get(0)[1], 1e-9),
                () -> assertEquals(-(30 + tip + breakthrough) + 8, feeds.get(1)[0], 1e-9),
                () -> assertEquals(1800, feeds.get(1)[1], 1e-9),
                () -> assertEquals(-(30 + tip + breakthrough), feeds.get(2)[0], 1e-9),
                () -> assertEquals(1350, feeds.get(2)[1], 1e-9),
                () -> assertEquals(-37.0086, feeds.get(2)[0], 1e-4),
                // NIST's bottom, 1.13 mm deeper for its longer point, less our breakthrough (see above)
                () -> assertEquals(-37.1378 + 1.1292 - breakthrough, feeds.get(2)[0], 1e-4));
        assertEquals(20, drill.toolDiameterMm());
        // the reamer (no point, no strategy) stops the breakthrough below the exit at -30 and leaves
        // at its feed, as NIST's does
        ToolpathSection ream = section(p, "WS REAM HOLE1");
        assertEquals(
                -31, ream.moves().stream().mapToDouble(m -> m.end().z()).min().orElseThrow(), 1e-9);
        assertEquals(
                List.of(-31.0, 10.0),
                ream.moves().stream()
                        .filter(m -> m instanceof Move.Linear)
                        .map(m -> m.end().z())
                        .toList());
        List<String> problems = ToolpathPlanner.plan(StepNcReader.read(EXAMPLE1), Tolerance.DEFAULT)
                .problems();
        assertTrue(problems.stream().noneMatch(q -> q.startsWith("workingstep 'WS DRILL HOLE1'")), problems.toString());
        // reduced_cut_at_start/end 0.75, 0.5 of 960 rpm: NIST's 720, 960 (after the start zone), 480 (end zone)
        List<double[]> speeds = new ArrayList<>();
        for (Move m : drill.moves()) {
            if (m instanceof Move.SpindleStart on) {
                speeds.add(new double[] {on.end().z(), on.rpm()});
            }
        }
        assertEquals(960, drill.spindleRpm(), 1e-9);
        assertEquals(3, speeds.size());
        assertAll(
                () -> assertEquals(10, speeds.get(0)[0], 1e-9),
                () -> assertEquals(720, speeds.get(0)[1], 1e-9),
                () -> assertEquals(-(2 + tip), speeds.get(1)[0], 1e-9),
                () -> assertEquals(960, speeds.get(1)[1], 1e-9),
                () -> assertEquals(-(30 + tip + breakthrough) + 8, speeds.get(2)[0], 1e-9),
                () -> assertEquals(480, speeds.get(2)[1], 1e-9));
        // the reamer's spindle_stop_at_bottom: M5 at -31, out at feed, M3 again at the retract height
        assertTrue(problems.stream().noneMatch(q -> q.startsWith("workingstep 'WS REAM HOLE1'")), problems.toString());
        List<Move> rm = ream.moves();
        int stop = rm.indexOf(rm.stream()
                .filter(m -> m instanceof Move.SpindleStop)
                .findFirst()
                .orElseThrow());
        assertEquals(-31, rm.get(stop).end().z(), 1e-9);
        assertTrue(
                rm.get(stop + 1) instanceof Move.Linear && rm.get(stop + 2) instanceof Move.SpindleStart,
                rm.toString());
        assertEquals(10, rm.get(stop + 2).end().z(), 1e-9);
        assertEquals(ream.spindleRpm(), ((Move.SpindleStart) rm.get(stop + 2)).rpm());
    }

    /** Example 2's unitless feeds are chip loads, converted with the spindle speed and said so. */
    @Test
    void summaryJsonSaysHowEachUnitlessFeedWasRead(@TempDir Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(
                EXAMPLE2, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        // exit 1: its side faces' workingsteps need another setup (a 3-axis program machines along +Z)
        assertEquals(1, o.exitStatus(), o.problems().toString());
        String json = Files.readString(dir.resolve("summary.json"));
        assertTrue(json.contains("\"rapid_mm_per_min\": 10000"), json);
        assertTrue(json.contains("\"feed_read_as\": \"mm/tooth\""), json);
        assertTrue(json.contains("\"feed_read_as\": \"mm/rev\""), json);
        assertTrue(json.contains("read as mm/tooth: 0.0505 x 4 teeth x 2884.6833 rpm = 582.706 mm/min"), json);
        assertTrue(
                o.problems().stream().anyMatch(p -> p.contains("0.0505 (no unit in the file) read as mm/tooth")),
                o.problems().toString());
        assertFalse(json.contains("1000 mm/min used"), json);
    }

    @Test
    void anIntegratedFormFileWithNothingToMachineIsRefusedWithItsRealReasonAndNoProgram(@TempDir Path dir)
            throws Exception {
        // the workingstep is in the main workplan's sequence but has no operation: that is the reason given,
        // never "not referenced by any workplan"
        Path aim = Path.of("src/test/resources/stepnc/aim-header-only.stp");
        TaskOutcome o = ToolpathService.run(
                aim, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertTrue(
                o.problems().get(0).contains("#20 'WS FINISH PLANAR FACE' the workingstep has no operation"),
                o.problems().toString());
        assertFalse(o.problems().get(0).contains("not referenced"), o.problems().toString());
        assertEquals(List.of(dir.resolve("summary.json")), o.files());
        assertFalse(Files.exists(dir.resolve("program.ngc")));
        assertTrue(Files.readString(dir.resolve("summary.json")).contains("has no operation"));
    }
}
