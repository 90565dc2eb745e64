package org.fresa.toolpath;

import static org.fresa.toolpath.SlotProfilesTest.End;
import static org.fresa.toolpath.SlotProfilesTest.Shape;
import static org.fresa.toolpath.SlotProfilesTest.Slot;
import static org.fresa.toolpath.SlotProfilesTest.box;
import static org.fresa.toolpath.SlotProfilesTest.check;
import static org.fresa.toolpath.SlotProfilesTest.flat;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.DoubleUnaryOperator;
import org.fresa.geom.Tolerance;
import org.fresa.io.OutputFolder;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.job.ToolpathService;
import org.fresa.model.ToolpathSection;
import org.fresa.post.MillingPost;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Square-U slots whose bottoms are blended into their sides (ISO 14649-10 square_u_profile's
 * first_radius and second_radius; first_angle and second_angle each side's angle to the bottom),
 * src/test/resources/stepnc/slots-square-u-fillets.stp: the cutter stays within the slot's
 * cross-section, fillets included, at every 0.5 mm of height (JTS, 0.01 mm), clears the floor it
 * reaches, and what it cannot mill as drawn is refused. Before, the fillets were cut away as if the
 * corners were sharp and a side at any angle was milled upright.
 */
class SquareUFilletsTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-square-u-fillets.stp");

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    static ToolpathSection section(String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }

    /** Half the width of a square U at height z: its sides, then the fillets about zc. */
    static DoubleUnaryOperator filleted(double halfWidth, double fillet, double depth) {
        double zc = -depth + fillet;
        return z -> z >= zc
                ? halfWidth
                : halfWidth - fillet + Math.sqrt(Math.max(fillet * fillet - (z - zc) * (z - zc), 0));
    }

    /** A bull-nose end mill of radius r with a corner of radius e. */
    static Shape bull(double r, double e) {
        return h -> h >= e ? r : r - e + Math.sqrt(Math.max(e * e - (e - h) * (e - h), 0));
    }

    static String problem(String workingstep) {
        return plan.problems().stream()
                .filter(p -> p.startsWith("workingstep '" + workingstep + "'"))
                .reduce((a, b) -> a + " | " + b)
                .orElseThrow(() -> new AssertionError(workingstep + ": nothing said: " + plan.problems()));
    }

    @Test
    void theFilletsAndAnglesAreBoundInDegrees() throws Exception {
        var program = StepNcReader.read(PART);
        var u = program.workingsteps().stream()
                .filter(w -> w.feature().id().equals("FILLETS FLAT"))
                .map(w -> (org.fresa.stepnc.Profile.U) w.feature().profile().orElseThrow())
                .findFirst()
                .orElseThrow();
        assertEquals(4.0, u.firstRadiusMm().orElseThrow());
        assertEquals(90.0, u.firstAngleDeg().orElseThrow());
        assertEquals(4.0, u.secondRadiusMm().orElseThrow());
        assertEquals(90.0, u.secondAngleDeg().orElseThrow());
    }

    @Test
    void fourOfTheSixSlotsArePlannedAndTheOthersRefusedWithTheReason() {
        assertEquals(4, plan.planned(), plan.problems().toString());
        assertTrue(
                problem("WS FILLETS SMALLER THAN CORNER")
                        .contains("the cutter's corner radius 4 mm is larger than the square U's 2 mm bottom fillets"),
                plan.problems().toString());
        assertTrue(
                problem("WS SIDE AT 80").contains("has a side at 80 deg to its bottom (first_angle)"),
                plan.problems().toString());
        assertTrue(
                problem("WS ANGLES WRITTEN 0").contains("first_angle is written 0 deg"),
                plan.problems().toString());
    }

    @Test
    void aFlatEndMillLeavesTheFilletsStandingAndClearsTheFlatFloor() {
        // 20 wide, 4 mm fillets, 10 deep, through the block at y 20: the 10 mm cutter's flat end
        // fits the 12 mm of flat floor, so it reaches the bottom, its centre at most 1 mm off the middle
        Slot s = new Slot(0, 120, 20, 10, filleted(10, 4, 10), End.OPEN, End.OPEN);
        ToolpathSection sec = section("WS FILLETS FLAT");
        check(sec, s, flat(5), -10, box(0, 14, 120, 26), 5);
        assertTrue(problem("WS FILLETS FLAT").contains("leaving steps on them"));
        // the check sees a cutter that cuts into a fillet: the same moves, a cutter 0.05 mm wider
        assertThrows(AssertionError.class, () -> check(sec, s, flat(5.05), -10, box(0, 14, 120, 26), 5));
    }

    @Test
    void aBullNoseOfTheFilletsRadiusMillsThemAsDrawnInOnePassPerLayer() {
        // the same U 8 deep, x 20..100 at y 50, radiused ends: the 4 mm corner is the fillet
        Slot s = new Slot(20, 100, 50, 8, filleted(10, 4, 8), End.RADIUSED, End.RADIUSED);
        ToolpathSection sec = section("WS FILLETS BULL");
        // the floor, to within 0.3 mm: passes 5 mm apart leave the corner's ridges between them, up
        // to 4 - sqrt(16 - 1.5^2) = 0.29 mm high, where the end's 1 mm flat does not pass; within
        // 0.3 mm of its tip the bull-nose is 1 + sqrt(16 - 3.7^2) = 2.52 mm in radius
        double within = 1 + Math.sqrt(16 - 3.7 * 3.7);
        Slot floor = new Slot(20, 100, 50, 8, z -> 6, End.RADIUSED, End.RADIUSED);
        check(sec, s, bull(5, 4), -8, SlotProfilesTest.section(floor, 6), within);
        assertTrue(
                plan.problems().stream().noneMatch(p -> p.startsWith("workingstep 'WS FILLETS BULL'")),
                plan.problems().toString());
    }

    @Test
    void aFlatEndWiderThanTheFloorBetweenTheFilletsStopsWhereItsCornersMeetThem() {
        // 14 wide with 4 mm fillets: 6 mm of flat floor for a 10 mm flat end; its corner meets
        // the fillets (about z -4, radius 4) 3 mm beyond their centres: z = -4 - sqrt(16 - 4)
        double floor = -4 - Math.sqrt(12);
        Slot s = new Slot(20, 100, 80, 8, filleted(7, 4, 8), End.RADIUSED, End.RADIUSED);
        check(section("WS FILLETS NARROW FLOOR"), s, flat(5), floor, SlotProfilesTest.section(s, 5), 5);
        assertTrue(problem("WS FILLETS NARROW FLOOR").contains("reaches 7.464102 mm of the square U's 8 mm"));
    }

    @Test
    void anAngleWrittenZeroIsReadAsASquareSide() {
        Slot s = new Slot(20, 100, 141, 6, z -> 8, End.RADIUSED, End.RADIUSED);
        check(section("WS ANGLES WRITTEN 0"), s, flat(5), -6, SlotProfilesTest.section(s, 8), 5);
    }

    @Test
    void aRightAngleWrittenInRadiansIsRefusedSayingSo() throws Exception {
        String text = Files.readString(PART)
                .replace(
                        "#45= SQUARE_U_PROFILE($,16.000,$,80.000,$,90.000);",
                        "#45= SQUARE_U_PROFILE($,16.000,$,1.570796,$,1.570796);");
        ToolpathPlanner.Plan p = ToolpathPlanner.plan(
                StepNcReader.read(new java.io.StringReader(text), "radians.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS SIDE AT 80'")
                                && x.contains("a side at 1.570796 deg to its bottom")
                                && x.endsWith("the file writes pi / 2, a right angle in radians where ISO 14649"
                                        + " writes 90")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(PART, MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), "two workingsteps are refused: " + o.problems());
        Path program = dir.resolve("program.ngc");
        assertTrue(Files.exists(program), "the program check let the planned workingsteps through");
        Assumptions.assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(program, 20);
        assertEquals(0, r.exitStatus(), () -> "rs274 rejected the program: " + Rs274.log(r));
    }
}
