package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
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
import org.fresa.model.ArcGeometry;
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

/**
 * One slot per ISO 14649-10 profile and end type (src/test/resources/stepnc/slots-profiles.stp):
 * at every height the tool's cross-section along its moves stays within the slot's cross-section
 * there (or outside the block, past an open end) by 0.01 mm, checked with JTS; each floor is
 * cleared where the tool reaches; LinuxCNC's interpreter accepts the program; what the tool
 * cannot follow is refused with the reason.
 */
class SlotProfilesTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-profiles.stp");
    /** Heights between checks of the cross-section (mm). */
    static final double SLICE_MM = 0.5;

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    /** A slot along +x in the workpiece frame: its path, half width at each height, ends. */
    record Slot(double x0, double x1, double y, double depth, DoubleUnaryOperator halfWidth, End start, End end) {}

    /** An end: open, radiused, or flat with its +y and -y corner radii. */
    record End(char kind, double plusYRadius, double minusYRadius) {
        static final End OPEN = new End('o', 0, 0);
        static final End RADIUSED = new End('r', 0, 0);
    }

    /** How wide the tool is at a height above its tip (mm): its radius along its cutting part. */
    interface Shape {
        double radiusAt(double aboveTip);
    }

    static Shape flat(double r) {
        return h -> r;
    }

    static Shape ball(double r) {
        return h -> h >= r ? r : Math.sqrt(Math.max(r * r - (r - h) * (r - h), 0));
    }

    /** A T-slot mill: its disc over its cutting edge, its neck (of no width known) above. */
    static Shape tSlot(double r, double edge) {
        return h -> h <= edge ? r : 0;
    }

    static Geometry box(double x0, double y0, double x1, double y1) {
        return Swept.GF.createPolygon(new Coordinate[] {
            new Coordinate(x0, y0),
            new Coordinate(x1, y0),
            new Coordinate(x1, y1),
            new Coordinate(x0, y1),
            new Coordinate(x0, y0)
        });
    }

    static Geometry disc(double x, double y, double r) {
        return Swept.GF.createPoint(new Coordinate(x, y)).buffer(r, 256);
    }

    /** The slot's cross-section in the XY plane where it is w wide (half width w). */
    static Geometry section(Slot s, double w) {
        Geometry g = box(s.x0(), s.y() - w, s.x1(), s.y() + w);
        g = end(g, s, s.start(), s.x0(), -1, w);
        return end(g, s, s.end(), s.x1(), 1, w);
    }

    private static Geometry end(Geometry g, Slot s, End e, double x, double sign, double w) {
        if (e.kind() == 'r') {
            return g.union(disc(x, s.y(), w));
        }
        for (double side : new double[] {1, -1}) {
            double rc = Math.min(side > 0 ? e.plusYRadius() : e.minusYRadius(), w);
            if (rc > 0) {
                double cx = x - sign * rc;
                double cy = s.y() + side * (w - rc);
                Geometry corner = box(
                        Math.min(cx, x),
                        Math.min(cy, s.y() + side * w),
                        Math.max(cx, x),
                        Math.max(cy, s.y() + side * w));
                g = g.difference(corner.difference(disc(cx, cy, rc)));
            }
        }
        return g;
    }

    /**
     * The XY shadow, at height z, of the tool along every move with part of it at or below z,
     * outside the allowed region (mm2); discs of 32 segments a quadrant fall short of the circle
     * by less than 0.002 mm at these radii.
     */
    static double outside(ToolpathSection sec, Shape tool, double z, Geometry allowed) {
        double area = 0;
        for (Geometry g : slice(sec, tool, z)) {
            if (!allowed.covers(g)) {
                area += g.difference(allowed).getArea();
            }
        }
        return area;
    }

    static List<Geometry> slice(ToolpathSection sec, Shape tool, double z) {
        List<Geometry> parts = new ArrayList<>();
        Vec3 at = sec.start();
        for (Move m : sec.moves()) {
            double tip = Math.min(at.z(), m.end().z());
            double r = tool.radiusAt(z - tip);
            if (tip <= z + 1e-9 && r > 0) {
                List<Coordinate> pts = new ArrayList<>();
                pts.add(new Coordinate(at.x(), at.y()));
                if (m instanceof Move.Circular c) {
                    for (Vec3 p : ArcGeometry.of(at, c).points(Swept.CHORD)) {
                        pts.add(new Coordinate(p.x(), p.y()));
                    }
                } else {
                    pts.add(new Coordinate(m.end().x(), m.end().y()));
                }
                Geometry g = pts.size() == 2 && pts.get(0).equals2D(pts.get(1))
                        ? Swept.GF.createPoint(pts.get(0))
                        : Swept.GF.createLineString(pts.toArray(new Coordinate[0]));
                parts.add(g.buffer(r, 32));
            }
            at = m.end();
        }
        return parts;
    }

    /** The block is 120 x 150: the tool may go anywhere outside it. */
    static final Geometry OUTSIDE = box(-1000, -1000, 1000, 1000).difference(box(0, 0, 120, 150));

    /**
     * Checks a section against its slot: within the cross-section at every height by 0.01 mm, the
     * floor at the height expected, and the floor cleared there where the tool's disc may go.
     */
    static void check(ToolpathSection sec, Slot s, Shape tool, double floorZ, Geometry floorRegion, double radius) {
        double lowest = Double.POSITIVE_INFINITY;
        for (Move m : sec.moves()) {
            lowest = Math.min(lowest, m.end().z());
        }
        assertEquals(floorZ, lowest, 1e-3, sec.label() + ": the floor");
        for (double z = 0; z >= lowest - 1e-9; z -= SLICE_MM) {
            double at = Math.max(z, lowest);
            Geometry allowed =
                    section(s, s.halfWidth().applyAsDouble(at)).union(OUTSIDE).buffer(0.01, 64);
            double out = outside(sec, tool, at, allowed);
            assertTrue(out < 1e-6, sec.label() + " leaves the slot at z " + at + " by " + out + " mm2");
        }
        Geometry atFloor = Swept.sweep(sec, radius, lowest);
        double left = Swept.uncutBeyondResidue(floorRegion, atFloor, radius);
        assertTrue(left < 1e-2, sec.label() + " leaves " + left + " mm2 of its floor");
    }

    static ToolpathSection section(String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }

    @Test
    void theProfilesAndEndsAreBound() throws Exception {
        var program = StepNcReader.read(PART);
        var byId = new java.util.HashMap<String, org.fresa.stepnc.Feature>();
        program.workingsteps().forEach(w -> byId.put(w.feature().id(), w.feature()));
        var tee = (org.fresa.stepnc.Profile.Tee) byId.get("TEE").profile().orElseThrow();
        assertEquals(
                List.of(10.0, 20.0, 6.0, 90.0, 90.0),
                List.of(
                        tee.widthMm(),
                        tee.crossBarWidthMm(),
                        tee.crossBarDepthMm(),
                        tee.firstAngleDeg(),
                        tee.secondAngleDeg()));
        assertTrue(tee.radiusMm().isEmpty());
        var vee = (org.fresa.stepnc.Profile.Vee) byId.get("VEE").profile().orElseThrow();
        assertEquals(
                List.of(1.0, 90.0, 45.0),
                List.of(vee.profileRadiusMm().orElseThrow(), vee.profileAngleDeg(), vee.tiltAngleDeg()));
        var ends = byId.get("SQUARE U ENDS").slotEnds();
        assertEquals(org.fresa.stepnc.Feature.SlotEnd.EndType.FLAT, ends.get(0).type());
        assertEquals(6.0, ends.get(0).firstRadiusMm().orElseThrow());
        assertEquals(4.0, ends.get(0).secondRadiusMm().orElseThrow());
        assertEquals(
                org.fresa.stepnc.Feature.SlotEnd.EndType.RADIUSED, ends.get(1).type());
        assertEquals(
                org.fresa.stepnc.Feature.SlotEnd.EndType.OPEN,
                byId.get("TEE").slotEnds().get(1).type());
    }

    @Test
    void everySlotOfThePartIsPlanned() {
        assertEquals(6, plan.planned(), plan.problems().toString());
        assertEquals(6, plan.workingsteps());
    }

    @Test
    void aBallEndMillAsWideAsARoundedUFollowsItsMiddleToTheBottom() {
        // rounded-U 12 wide, 10 deep: walls down to z -4, then a half circle about (y 15, z -4)
        Slot s = new Slot(
                0, 120, 15, 10, z -> z >= -4 ? 6 : Math.sqrt(Math.max(36 - (z + 4) * (z + 4), 0)), End.OPEN, End.OPEN);
        ToolpathSection sec = section("WS ROUND U BALL");
        for (Move m : sec.moves()) {
            if (m.end().z() < 0) {
                assertEquals(15, m.end().y(), 1e-9, "along the middle");
            }
        }
        check(sec, s, ball(6), -10, box(0, 9, 120, 21), 6);
    }

    @Test
    void aFlatEndMillInARoundedUWithRadiusedEndsGoesAsDeepAsItsCornersAllow() {
        // rounded-U 16 wide, 12 deep, x 20..100 at y 40: the 10 mm cutter's corner meets the
        // half circle (radius 8 about z -4) at z -4 - sqrt(64 - 25)
        double floor = -4 - Math.sqrt(39);
        Slot s = new Slot(
                20,
                100,
                40,
                12,
                z -> z >= -4 ? 8 : Math.sqrt(Math.max(64 - (z + 4) * (z + 4), 0)),
                End.RADIUSED,
                End.RADIUSED);
        check(section("WS ROUND U FLAT"), s, flat(5), floor, section(s, 5), 5);
        assertTrue(
                plan.problems().stream()
                        .anyMatch(p -> p.contains("WS ROUND U FLAT") && p.contains("reaches 10.244998")),
                plan.problems().toString());
    }

    @Test
    void aFlatEndMillFollowsAVeeInStepsWithinItsWalls() {
        // vee of 90 deg blended by 1 mm, 10 deep, x 20..100 at y 70; radiused start, flat end (2 mm corners)
        double zc = -9;
        double zApex = zc - Math.sqrt(2);
        double zTangent = zc - Math.sqrt(0.5);
        DoubleUnaryOperator half = z -> z >= zTangent ? z - zApex : Math.sqrt(Math.max(1 - (z - zc) * (z - zc), 0));
        Slot s = new Slot(20, 100, 70, 10, half, End.RADIUSED, new End('f', 2, 2));
        double floor = zApex + 3; // where the vee is as wide as the 6 mm cutter
        check(section("WS VEE"), s, flat(3), floor, section(s, 3), 3);
    }

    @Test
    void aTeeSlotsStemIsMilledWithAnEndMillAndItsCrossBarWithATSlotMillFromItsOpenEnd() {
        // stem 10 wide down to z -10, cross bar 20 wide from z -10 to z -16; through the block at y 105
        Slot s = new Slot(0, 120, 105, 16, z -> z > -10 + 1e-9 ? 5 : 10, End.OPEN, End.OPEN);
        check(
                section("WS TEE STEM"),
                new Slot(0, 120, 105, 16, z -> 5, End.OPEN, End.OPEN),
                flat(5),
                -16,
                box(0, 100, 120, 110),
                5);
        ToolpathSection bar = section("WS TEE CROSS BAR");
        check(bar, s, tSlot(10, 6), -16, box(0, 95, 120, 115), 10);
        // it goes down and comes up outside the block, past the open start
        assertTrue(bar.start().x() < -10, bar.start().toString());
    }

    @Test
    void aSquareUWithAFlatStartOfRoundedCornersAndARadiusedEndStaysWithinThem() {
        // square-U 20 wide, 5 deep, x 20..100 at y 135; start flat with corner radius 6 (+y) and 4 (-y)
        Slot s = new Slot(20, 100, 135, 5, z -> 10, new End('f', 6, 4), End.RADIUSED);
        check(section("WS SQUARE U ENDS"), s, flat(5), -5, section(s, 10), 5);
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(PART, MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        Path program = dir.resolve("program.ngc");
        assertTrue(Files.exists(program), "the program check let the program through");
        Assumptions.assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(program, 20);
        assertEquals(0, r.exitStatus(), () -> "rs274 rejected the program: " + Rs274.log(r));
    }

    static ToolpathPlanner.Plan planText(String text) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "slots.stp"), Tolerance.DEFAULT);
    }

    static String problemOf(ToolpathPlanner.Plan p, String workingstep) {
        return p.problems().stream()
                .filter(x -> x.startsWith("workingstep '" + workingstep + "' (#"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(workingstep + " not refused: " + p.problems()));
    }

    @Test
    void whatTheToolCannotFollowIsRefusedWithTheReason() throws Exception {
        String part = Files.readString(PART);
        String text = part
                // woodruff and loop ends
                .replace("#29= RADIUSED_SLOT_END_TYPE();", "#29= WOODRUFF_SLOT_END_TYPE(8.000);")
                .replace("#37= FLAT_SLOT_END_TYPE(6.000,4.000);", "#37= LOOP_SLOT_END_TYPE();")
                // a tilted vee
                .replace("#30= VEE_PROFILE($,1.000,90.000,45.000);", "#30= VEE_PROFILE($,1.000,90.000,30.000);")
                .replace("(#29,#32)", "(#32,#32)")
                // a dovetail cut with a ball end mill, a tee without an open end
                .replace("#25= ROUNDED_U_PROFILE($,12.000);", "#25= DOVETAIL_PROFILE($,12.000,60.000);")
                .replace(
                        "#19= SLOT('TEE',#4,(#23,#33),#87,#88,#24,#35,(#26,#26));",
                        "#19= SLOT('TEE',#4,(#23,#33),#87,#88,#24,#35,(#32,#32));");
        ToolpathPlanner.Plan p = planText(text);
        assertTrue(
                problemOf(p, "WS ROUND U BALL")
                        .endsWith("a DOVETAIL_PROFILE is no ISO 14649-10 profile: a dovetail is a SQUARE_U_PROFILE"
                                + " whose sides meet its base at one angle under 90 deg"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS ROUND U FLAT")
                        .contains("woodruff slot ends are machined on a SQUARE_U_PROFILE slot along a LINEAR_PATH"
                                + " only"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS VEE").contains("the vee leans by -15 deg (tilt_angle 30 deg for a 90 deg vee)"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS TEE CROSS BAR")
                        .endsWith("a T_SLOT_MILL enters the cross bar from an open end; the slot" + " has none"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS SQUARE U ENDS")
                        .contains("loop slot ends are machined along a closed course of travel only"),
                p.problems().toString());
        // the stem is still milled (its flat ends keep the cutter within the slot)
        assertEquals(1, p.planned(), p.problems().toString());

        // a T-slot mill narrower than the cross bar would leave the bar's sides
        ToolpathPlanner.Plan narrow = planText(part.replace(
                "#52= MILLING_TOOL_DIMENSION(20.000,$,$,6.0,0.0,$,$);",
                "#52= MILLING_TOOL_DIMENSION(16.000,$,$,6.0,0.0,$,$);"));
        assertTrue(
                problemOf(narrow, "WS TEE CROSS BAR")
                        .contains("the T-slot mill (16 mm) is narrower than the cross bar (20 mm): along the middle it"
                                + " leaves 2 mm of the bar on each side"),
                narrow.problems().toString());

        // a cutter wider than the slot
        ToolpathPlanner.Plan wide = planText(
                part.replace("#36= SQUARE_U_PROFILE($,20.000,$,$,$,$);", "#36= SQUARE_U_PROFILE($,8.000,$,$,$,$);"));
        assertTrue(
                problemOf(wide, "WS SQUARE U ENDS").endsWith("the tool (10 mm) is wider than the slot (8 mm)"),
                wide.problems().toString());
    }

    @Test
    void aPartWhoseSlotsAreAllRefusedWritesNoProgramAndExitsWith1(@TempDir Path dir) throws Exception {
        String part = Files.readString(PART);
        // every slot gets a woodruff end, of a radius less than any slot's depth
        String text = part.replace("(#26,#26)", "(#26,#38)")
                .replace("(#29,#29)", "(#29,#38)")
                .replace("(#29,#32)", "(#29,#38)")
                .replace("(#37,#29)", "(#37,#38)")
                .replace(
                        "#37= FLAT_SLOT_END_TYPE(6.000,4.000);",
                        "#37= FLAT_SLOT_END_TYPE(6.000,4.000);\n" + "#38= WOODRUFF_SLOT_END_TYPE(1.000);");
        Path file = dir.resolve("woodruff.stp");
        Files.writeString(file, text);
        TaskOutcome o = ToolpathService.run(
                file, MillingPost.LINUXCNC, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertFalse(Files.exists(dir.resolve("out/program.ngc")));
        assertEquals(6, o.problems().size(), o.problems().toString());
        assertTrue(
                o.problems().stream()
                        .allMatch(x -> x.contains("woodruff slot ends are machined on a SQUARE_U_PROFILE")
                                || x.contains("the woodruff end's radius (1 mm) is less than the slot's depth")),
                o.problems().toString());
    }
}
