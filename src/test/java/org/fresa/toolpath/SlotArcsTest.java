package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.io.OutputFolder;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.job.ToolpathService;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.post.MillingPost;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.operation.buffer.BufferParameters;

/**
 * Slots along circular paths (src/test/resources/stepnc/slots-circular.stp): square-U and
 * rounded-U profiles, open, radiused and flat ends, both senses. At every height the tool's
 * cross-section along its moves stays within the slot's by 0.01 mm (JTS), the floor is cleared
 * where the tool reaches, the walls are cut as arcs about the path's centre, and LinuxCNC and
 * the program check accept the program. A path moved 0.05 mm off fails both checks.
 */
class SlotArcsTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-circular.stp");

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    /**
     * A slot along an arc in the workpiece frame, counter-clockwise from a0 to a1 (the ends as
     * they lie there: 'o' open, 'r' radiused, 'f' flat).
     */
    record ArcSlot(
            double cx,
            double cy,
            double radius,
            double a0,
            double a1,
            DoubleUnaryOperator halfWidth,
            char e0,
            char e1) {}

    /**
     * The slot's cross-section where it is w wide, its arc in n chords (the chords' sag, 0.0003 mm
     * at 180 chords, is well within the 0.01 mm allowed; the floor's area wants 720).
     */
    static Geometry section(ArcSlot s, double w, int n) {
        // chords of a degree or less, and a first and last one of no length, whose flat caps are then
        // square to the path at its ends
        double eps = 1e-7;
        Coordinate[] pts = new Coordinate[n + 3];
        for (int i = 0; i <= n + 2; i++) {
            double t = i == 0 ? 0 : i == n + 2 ? 1 : i == 1 ? eps : i == n + 1 ? 1 - eps : (double) (i - 1) / n;
            double a = s.a0() + (s.a1() - s.a0()) * t;
            pts[i] = new Coordinate(s.cx() + s.radius() * Math.cos(a), s.cy() + s.radius() * Math.sin(a));
        }
        BufferParameters flat = new BufferParameters(64, BufferParameters.CAP_FLAT);
        Geometry g = org.locationtech.jts.operation.buffer.BufferOp.bufferOp(Swept.GF.createLineString(pts), w, flat);
        if (s.e0() == 'r') {
            g = g.union(SlotProfilesTest.disc(pts[0].x, pts[0].y, w));
        }
        if (s.e1() == 'r') {
            g = g.union(SlotProfilesTest.disc(pts[n + 2].x, pts[n + 2].y, w));
        }
        return g;
    }

    static DoubleUnaryOperator square(double w) {
        return z -> w / 2;
    }

    /** Walls down to a half circle of the width: w wide, d deep. */
    static DoubleUnaryOperator roundedU(double w, double d) {
        double zc = -d + w / 2;
        return z -> z >= zc ? w / 2 : Math.sqrt(Math.max(w * w / 4 - (z - zc) * (z - zc), 0));
    }

    static final ArcSlot OPEN = new ArcSlot(50, 50, 30, 0, Math.PI / 2, square(14), 'o', 'o');
    static final ArcSlot RADIUSED_CW =
            new ArcSlot(150, 50, 25, Math.PI / 2 - Math.toRadians(120), Math.PI / 2, square(10), 'r', 'r');
    static final ArcSlot ROUNDED_FLAT = new ArcSlot(60, 150, 35, 0, Math.toRadians(150), roundedU(16, 8), 'f', 'r');

    /** The part of the tool's shadow at each height outside the slot (mm2), the floor uncut (mm2). */
    record Misfit(double outsideMm2, double uncutMm2) {}

    static Misfit misfit(ToolpathSection sec, ArcSlot s, double r, double floorHalfWidth) {
        return misfit(sec, s, r, section(s, floorHalfWidth, 720), true);
    }

    /**
     * @param floor the floor the tool must clear
     * @param residue whether the corners the cutter cannot reach are left out of it (a floor as wide
     *     as the cutter is given as the band its centre line sweeps, with no corners)
     */
    static Misfit misfit(ToolpathSection sec, ArcSlot s, double r, Geometry floor, boolean residue) {
        double out = FeatureVolumeCheck.outside(
                sec, SlotProfilesTest.flat(r), z -> section(s, s.halfWidth().applyAsDouble(z), 180));
        double uncut = FeatureVolumeCheck.uncut(sec, r, floor, residue);
        return new Misfit(out, uncut);
    }

    static ToolpathSection section(String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }

    static double lowest(ToolpathSection s) {
        return FeatureVolumeCheck.lowest(s);
    }

    @Test
    void everySlotIsPlanned() {
        assertEquals(3, plan.planned(), plan.problems().toString());
        assertEquals(
                List.of("workingstep 'WS ARC ROUNDED FLAT': the 10 mm cutter reaches 6.244998 mm of the rounded-U's 8"
                        + " mm; a ball end mill as wide as the slot reaches the bottom"),
                plan.problems());
    }

    @Test
    void theSquareUWithOpenEndsStaysInsideAndClearsItsFloor() {
        ToolpathSection s = section("WS ARC OPEN");
        assertEquals(-5, lowest(s), 1e-9);
        Misfit m = misfit(s, OPEN, 5, 7);
        assertTrue(m.outsideMm2() < 1e-6, "leaves the slot by " + m.outsideMm2() + " mm2");
        assertTrue(m.uncutMm2() < 1e-2, "leaves " + m.uncutMm2() + " mm2 of its floor");
        // the walls are arcs about the path's centre: the outer at 30 + 7 - 5 = 32 mm
        assertTrue(
                s.moves().stream()
                        .anyMatch(x -> x instanceof Move.Circular c
                                && c.center()
                                                .distance(new Vec3(
                                                        50, 50, c.center().z()))
                                        < 1e-6
                                && Math.abs(Math.hypot(c.end().x() - 50, c.end().y() - 50) - 32) < 1e-6),
                "no arc about the path's centre at 32 mm");
    }

    @Test
    void theClockwiseSlotAsWideAsTheCutterFollowsItsMiddleToBothRadiusedEnds() {
        ToolpathSection s = section("WS ARC RADIUSED CW");
        assertEquals(-4, lowest(s), 1e-9);
        // the floor: the band the cutter's centre line sweeps, to both ends' centres
        Misfit m = misfit(s, RADIUSED_CW, 5, section(RADIUSED_CW, 5 - 0.01, 720), false);
        assertTrue(m.outsideMm2() < 1e-6, "leaves the slot by " + m.outsideMm2() + " mm2");
        assertTrue(m.uncutMm2() < 1e-2, "leaves " + m.uncutMm2() + " mm2 of its floor");
    }

    @Test
    void theRoundedUFollowsItsProfileDownToWhereTheFlatCutterReaches() {
        ToolpathSection s = section("WS ARC ROUNDED FLAT");
        assertEquals(-6.244998, lowest(s), 1e-6);
        // at its deepest the cutter is as wide as the profile there: the floor is the band its centre
        // line sweeps, from where the cutter touches the flat end (5 mm from it) to the radiused end's centre
        double touch = Math.asin(5.0 / 35);
        ArcSlot band = new ArcSlot(60, 150, 35, touch, Math.toRadians(150), square(10), 'r', 'r');
        Misfit m = misfit(s, ROUNDED_FLAT, 5, section(band, 5 - 0.01, 720), false);
        assertTrue(m.outsideMm2() < 1e-6, "leaves the slot by " + m.outsideMm2() + " mm2");
        assertTrue(m.uncutMm2() < 1e-2, "leaves " + m.uncutMm2() + " mm2 of its floor");
    }

    /** The open slot's path moved 0.05 mm along x: it leaves the slot on one side, its floor uncut on the other. */
    @Test
    void aPath005MmOffFailsBothChecks() {
        ToolpathSection s = shifted(section("WS ARC OPEN"), new Vec3(0.05, 0, 0));
        Misfit m = misfit(s, OPEN, 5, 7);
        assertFalse(m.outsideMm2() < 1e-6, "a path 0.05 mm off stays inside: " + m.outsideMm2());
        assertFalse(m.uncutMm2() < 1e-2, "a path 0.05 mm off clears the floor: " + m.uncutMm2());
    }

    static ToolpathSection shifted(ToolpathSection s, Vec3 by) {
        List<Move> moves = new ArrayList<>();
        for (Move m : s.moves()) {
            if (m instanceof Move.Rapid r) {
                moves.add(new Move.Rapid(r.end().plus(by)));
            } else if (m instanceof Move.Linear l) {
                moves.add(new Move.Linear(l.end().plus(by), l.feedMmPerMin()));
            } else if (m instanceof Move.Circular c) {
                moves.add(new Move.Circular(
                        c.end().plus(by), c.center().plus(by), c.normal(), c.ccw(), c.turns(), c.feedMmPerMin()));
            } else {
                moves.add(m);
            }
        }
        return new ToolpathSection(
                s.label(),
                s.toolAxis(),
                s.toolDiameterMm(),
                s.toolNumber(),
                s.spindleRpm(),
                s.start().plus(by),
                moves);
    }

    @Test
    @InterpreterCheck
    void linuxCncAndTheProgramCheckAcceptTheArcsAsG2AndG3(@TempDir Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(PART, MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertFalse(o.summary().containsKey("program_refused"));
        String nc = Files.readString(dir.resolve("program.ngc"));
        assertTrue(nc.lines().filter(l -> l.matches("^(G17 )?G[23] .*")).count() > 20, nc);
        Assumptions.assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 10);
        assertEquals(0, r.exitStatus(), r.stderr());
    }
}
