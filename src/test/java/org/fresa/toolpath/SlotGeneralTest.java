package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.operation.buffer.BufferOp;
import org.locationtech.jts.operation.buffer.BufferParameters;

/**
 * Slots along general paths, loops, woodruff ends and a partial circular profile
 * (src/test/resources/stepnc/slots-general.stp). At every 0.5 mm of height the tool's
 * cross-section along its moves stays within the slot's by 0.01 mm (JTS), the floor is cleared
 * where the tool reaches, and LinuxCNC and the program check accept the program.
 */
class SlotGeneralTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-general.stp");

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    /** The points of a path: (x, y) pairs, with arcs given as chords of a degree. */
    static Coordinate[] points(double... xy) {
        Coordinate[] out = new Coordinate[xy.length / 2];
        for (int i = 0; i < out.length; i++) {
            out[i] = new Coordinate(xy[2 * i], xy[2 * i + 1]);
        }
        return out;
    }

    /** The first slot's path: (20, 20)-(60, 20), a counter-clockwise quarter about (60, 40), (80, 40)-(80, 80). */
    static Coordinate[] radiusedPath() {
        List<Coordinate> pts = new ArrayList<>();
        pts.add(new Coordinate(20, 20));
        for (int i = 0; i <= 90; i++) {
            double a = Math.toRadians(-90 + i);
            pts.add(new Coordinate(60 + 20 * Math.cos(a), 40 + 20 * Math.sin(a)));
        }
        pts.add(new Coordinate(80, 80));
        return pts.toArray(new Coordinate[0]);
    }

    static Geometry band(Coordinate[] path, double w, int cap) {
        BufferParameters p = new BufferParameters(64, cap, BufferParameters.JOIN_ROUND, 5);
        return BufferOp.bufferOp(Swept.GF.createLineString(path), w, p);
    }

    static Geometry ring(double cx, double cy, double rIn, double rOut) {
        return SlotProfilesTest.disc(cx, cy, rOut).difference(SlotProfilesTest.disc(cx, cy, rIn));
    }

    static final Coordinate[] CORNER = points(120, 20, 170, 20, 170, 70, 140, 90);
    static final Coordinate[] SQUARE = points(130, 120, 190, 120, 190, 180, 130, 180, 130, 120);

    /** How far a woodruff end of radius 15 reaches beyond the path's end at a height above the 6 mm floor. */
    static double woodruffBeyond(double z) {
        double dz = 15 - (z + 6);
        return Math.sqrt(Math.max(225 - dz * dz, 0));
    }

    static double partialHalfWidth(double z) {
        return Math.sqrt(Math.max(100 - (z - 3) * (z - 3), 0));
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

    /** The tool's shadow outside the slot's cross-section (mm2), the worst height. */
    static double outside(ToolpathSection sec, double r, DoubleFunction<Geometry> slotAt) {
        return FeatureVolumeCheck.outside(sec, SlotProfilesTest.flat(r), slotAt);
    }

    /**
     * The floor left uncut (mm2), less a 0.003 mm strip along its walls: the tool's arcs are
     * swept as chords falling short of them by up to 0.002 mm (Swept.CHORD).
     */
    static double uncut(ToolpathSection sec, double r, Geometry walls, boolean residue) {
        return FeatureVolumeCheck.uncut(sec, r, walls.buffer(-0.003, 64), residue);
    }

    @Test
    void everySlotIsPlanned() {
        assertEquals(9, plan.planned(), plan.problems().toString());
        assertEquals(
                List.of(
                        "workingstep 'WS WOODRUFF': the woodruff end is cut in 6 layers square to the path, each as"
                                + " long as the end's arc at its bottom: steps up to 5.385165 mm are left along the"
                                + " arc, and the 4 mm corners of the cutter in each layer's ends",
                        "workingstep 'WS PARTIAL CIRCLE': the 8 mm cutter reaches 6.165151 mm of the partial circle's"
                                + " 7 mm; a ball end mill no wider than the circle (20 mm) reaches the bottom",
                        "workingstep 'WS ARC TEE STEM': the TAPERED_ENDMILL mills the tee's stem; its cross bar needs a"
                                + " T_SLOT_MILL"),
                plan.problems());
    }

    @Test
    void theSlotAlongLinesAndAnArcStaysInsideAndClearsItsFloor() {
        ToolpathSection s = section("WS GEN RADIUSED");
        assertEquals(-5, lowest(s), 1e-9);
        Geometry slot = band(radiusedPath(), 6, BufferParameters.CAP_ROUND);
        assertTrue(outside(s, 5, z -> slot) < 1e-6, "leaves the slot");
        double left = uncut(s, 5, slot, true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
        // its walls stay arcs about the path's arc's centre: the outer one at 20 + 6 - 5 = 21 mm
        assertTrue(
                s.moves().stream()
                        .anyMatch(x -> x instanceof Move.Circular c
                                && c.center()
                                                .distance(new Vec3(
                                                        60, 40, c.center().z()))
                                        < 1e-6
                                && Math.abs(Math.hypot(c.end().x() - 60, c.end().y() - 40) - 21) < 1e-6),
                "no arc about (60, 40) at 21 mm");
    }

    @Test
    void theSlotAlongAPolylineTurnsRoundItsCornersAndStaysInside() {
        ToolpathSection s = section("WS GEN CORNER");
        assertEquals(-4, lowest(s), 1e-9);
        Geometry slot = band(CORNER, 7, BufferParameters.CAP_FLAT);
        assertTrue(outside(s, 5, z -> slot) < 1e-6, "leaves the slot");
        double left = uncut(s, 5, slot, true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
    }

    @Test
    void theLoopAboutACircleClearsItsRingAndLeavesTheIsland() {
        ToolpathSection s = section("WS LOOP CIRCLE");
        assertEquals(-5, lowest(s), 1e-9);
        Geometry slot = ring(50, 150, 18, 32);
        assertTrue(outside(s, 5, z -> slot) < 1e-6, "leaves the ring");
        double left = uncut(s, 5, slot, true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
    }

    @Test
    void theLoopAsWideAsTheCutterFollowsItsClosedPath() {
        ToolpathSection s = section("WS LOOP SQUARE");
        assertEquals(-3, lowest(s), 1e-9);
        Geometry slot = band(SQUARE, 4, BufferParameters.CAP_FLAT);
        assertTrue(outside(s, 4, z -> slot) < 1e-6, "leaves the loop");
        double left = uncut(s, 4, band(SQUARE, 4 - 0.01, BufferParameters.CAP_FLAT), false);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of the band its centre line sweeps");
    }

    @Test
    void theWoodruffEndsAreCutInLayersWithinTheirArcs() {
        ToolpathSection s = section("WS WOODRUFF");
        assertEquals(-6, lowest(s), 1e-9);
        DoubleFunction<Geometry> at =
                z -> SlotProfilesTest.box(20 - woodruffBeyond(z), 226, 60 + woodruffBeyond(z), 234);
        assertTrue(outside(s, 4, at) < 1e-6, "leaves the woodruff ends");
        double left = uncut(s, 4, SlotProfilesTest.box(20, 226, 60, 234), true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
        // the top layer reaches beyond the path's ends, the floor's does not
        double topReach = s.moves().stream()
                .filter(m -> m.end().z() > -1.5)
                .mapToDouble(m -> m.end().x())
                .max()
                .orElseThrow();
        assertTrue(topReach > 60, "the top layer stops at " + topReach);
    }

    @Test
    void thePartialCircleIsFollowedDownToWhereTheCutterReaches() {
        ToolpathSection s = section("WS PARTIAL CIRCLE");
        assertEquals(-6.165151, lowest(s), 1e-6);
        DoubleFunction<Geometry> at =
                z -> SlotProfilesTest.box(100, 230 - partialHalfWidth(z), 160, 230 + partialHalfWidth(z));
        assertTrue(outside(s, 4, at) < 1e-6, "leaves the partial circle");
        double left = uncut(s, 4, SlotProfilesTest.box(100, 226.01, 160, 233.99), true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
    }

    /**
     * The material a flat end's rounded corner leaves in a slot along an arc about (cx, cy): the
     * corner between the wall of radius rWall and the end's radial line at endA, less the fillet
     * of radius rc touching both; the fillet lies towards larger angles when toward is +1.
     */
    static Geometry arcCorner(
            double cx, double cy, double rWall, double rc, double endA, double toward, boolean outer) {
        double centre = outer ? rWall - rc : rWall + rc;
        double d = Math.asin(rc / centre);
        Coordinate p =
                new Coordinate(cx + centre * Math.cos(endA + toward * d), cy + centre * Math.sin(endA + toward * d));
        double l = Math.sqrt(centre * centre - rc * rc);
        List<Coordinate> pts = new ArrayList<>();
        pts.add(p);
        pts.add(new Coordinate(cx + l * Math.cos(endA), cy + l * Math.sin(endA)));
        for (int k = 0; k <= 32; k++) {
            double a = endA + toward * d * k / 32;
            pts.add(new Coordinate(cx + rWall * Math.cos(a), cy + rWall * Math.sin(a)));
        }
        pts.add(p);
        Geometry wedge = Swept.GF.createPolygon(pts.toArray(new Coordinate[0]));
        return wedge.difference(SlotProfilesTest.disc(p.x, p.y, rc));
    }

    @Test
    void flatEndsAlongAnArcKeepTheirCornerRadii() {
        ToolpathSection s = section("WS ARC FLAT CORNERS");
        assertEquals(-4, lowest(s), 1e-9);
        double a0 = -Math.toRadians(100);
        SlotArcsTest.ArcSlot arc = new SlotArcsTest.ArcSlot(250, 60, 30, a0, 0, SlotArcsTest.square(16), 'f', 'f');
        // the path runs clockwise: its left (corner_radius1, 7 mm) is the outer wall at both ends
        Geometry slot = SlotArcsTest.section(arc, 8, 720)
                .difference(arcCorner(250, 60, 38, 7, 0, -1, true))
                .difference(arcCorner(250, 60, 22, 6, 0, -1, false))
                .difference(arcCorner(250, 60, 38, 7, a0, 1, true))
                .difference(arcCorner(250, 60, 22, 6, a0, 1, false));
        assertTrue(outside(s, 5, z -> slot) < 1e-6, "leaves the slot's rounded corners");
        double left = uncut(s, 5, slot, true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of its floor");
    }

    @Test
    void aTeeAlongAnArcHasItsCrossBarMilledWithATSlotMillFromItsOpenStart() {
        SlotArcsTest.ArcSlot stem =
                new SlotArcsTest.ArcSlot(260, 320, 40, -Math.PI / 2, 0, SlotArcsTest.square(10), 'f', 'f');
        // the open start is on the block's edge y 320: beyond it the cutter cuts air
        Geometry air = SlotProfilesTest.box(0, 320, 400, 400);
        ToolpathSection s = section("WS ARC TEE STEM");
        assertEquals(-16, lowest(s), 1e-9);
        assertTrue(outside(s, 5, z -> SlotArcsTest.section(stem, 5, 180).union(air)) < 1e-6, "the stem leaves");
        ToolpathSection bar = section("WS ARC TEE CROSS BAR");
        assertEquals(-16, lowest(bar), 1e-9);
        double out = 0;
        for (double z = -16; z <= -8; z += SlotProfilesTest.SLICE_MM) {
            Geometry allowed = SlotArcsTest.section(stem, z > -10 + 1e-9 ? 5 : 10, 180)
                    .union(air)
                    .buffer(0.01, 64);
            out = Math.max(out, SlotProfilesTest.outside(bar, SlotProfilesTest.tSlot(10, 6), z, allowed));
        }
        assertTrue(out < 1e-6, "the cross bar's cutter leaves by " + out + " mm2");
        double left = uncut(bar, 10, SlotArcsTest.section(stem, 10, 720), true);
        assertTrue(left < 1e-2, "leaves " + left + " mm2 of the cross bar's floor");
        assertTrue(bar.start().y() > 320, "enters at " + bar.start());
    }

    /** The loop's path moved 0.05 mm along x: it leaves the ring on one side, its floor uncut on the other. */
    @Test
    void aPath005MmOffFailsBothChecks() {
        ToolpathSection s = SlotArcsTest.shifted(section("WS LOOP CIRCLE"), new Vec3(0.05, 0, 0));
        Geometry slot = ring(50, 150, 18, 32);
        assertFalse(outside(s, 5, z -> slot) < 1e-6, "a path 0.05 mm off stays inside");
        assertFalse(uncut(s, 5, slot, true) < 1e-2, "a path 0.05 mm off clears the floor");
    }

    @Test
    @InterpreterCheck
    void linuxCncAndTheProgramCheckAcceptThePart(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }
}
