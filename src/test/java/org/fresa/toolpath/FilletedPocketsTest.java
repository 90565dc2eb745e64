package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.DoubleFunction;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * Closed pockets whose floor meets their walls in a fillet (planar_radius), milled by cutters
 * whose corner is smaller than the fillet (src/test/resources/stepnc/filleted-pockets.stp): at
 * every 0.5 mm of height, and every 0.1 mm through the fillet, the tool's cross-section along its
 * moves stays within the pocket's, less what the fillet takes at that height, by 0.01 mm (JTS);
 * the floor is cleared out to the fillet's foot; a cutter 0.05 mm wider is seen cutting into the
 * fillet; the program check and LinuxCNC's interpreter accept the program.
 */
class FilletedPocketsTest {

    static final Path PART = Path.of("src/test/resources/stepnc/filleted-pockets.stp");

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

    /** A rounded rectangle w x l centred at (cx, cy) with corners of radius rc. */
    static Geometry rounded(double cx, double cy, double w, double l, double rc) {
        return SlotProfilesTest.box(cx - w / 2, cy - l / 2, cx + w / 2, cy + l / 2)
                .buffer(-rc, 64)
                .buffer(rc, 64);
    }

    static final Geometry FLAT = rounded(30, 30, 40, 30, 6);
    static final Geometry BOSS = rounded(85, 35, 40, 40, 6).difference(SlotProfilesTest.disc(85, 35, 5));
    static final Geometry CORNER = rounded(60, 110, 50, 30, 8);

    /** How far the fillet of radius r reaches in from the walls at height u above the floor. */
    static double filletAt(double r, double u) {
        return u >= r ? 0 : r - Math.sqrt(Math.max(r * r - (r - u) * (r - u), 0));
    }

    /** The pocket's cross-section at height z (top 0): its region less the fillet there. */
    static DoubleFunction<Geometry> pocketAt(Geometry region, double depth, double r) {
        return z -> {
            double in = filletAt(r, z + depth);
            return in > 0 ? region.buffer(-in, 64) : region;
        };
    }

    /** A cutter of radius rt with a corner of radius e. */
    static SlotProfilesTest.Shape corner(double rt, double e) {
        return h -> h >= e ? rt : rt - e + Math.sqrt(Math.max(e * e - (e - h) * (e - h), 0));
    }

    /** Every 0.1 mm from the floor up through the fillet. */
    static void checkFillet(
            ToolpathSection sec, SlotProfilesTest.Shape tool, DoubleFunction<Geometry> at, double depth, double r) {
        for (double u = 0; u <= r + 1e-9; u += 0.1) {
            double z = -depth + u;
            double out = FeatureVolumeCheck.outsideAt(sec, tool, z, at.apply(z));
            assertTrue(out < 1e-6, sec.label() + " cuts into the fillet at z " + z + " by " + out + " mm2");
        }
    }

    @Test
    void everyPocketIsPlanned() {
        assertEquals(3, plan.planned(), plan.problems().toString());
        assertEquals(List.of(), plan.problems());
    }

    @Test
    void aFlatEndMillLeavesTheFilletAndClearsTheFloorToItsFoot() {
        ToolpathSection sec = section("WS FILLET FLAT");
        DoubleFunction<Geometry> at = pocketAt(FLAT, 8, 3);
        FeatureVolumeCheck.assertFloor(sec, -8, 1e-6);
        FeatureVolumeCheck.assertInside(sec, SlotProfilesTest.flat(3), at);
        checkFillet(sec, SlotProfilesTest.flat(3), at, 8, 3);
        FeatureVolumeCheck.assertFloorCleared(sec, 3, FLAT.buffer(-3 - 0.005, 64));
    }

    @Test
    void theFilletRunsRoundTheBossesFootToo() {
        ToolpathSection sec = section("WS FILLET BOSS");
        DoubleFunction<Geometry> at = pocketAt(BOSS, 6, 2);
        FeatureVolumeCheck.assertFloor(sec, -6, 1e-6);
        FeatureVolumeCheck.assertInside(sec, SlotProfilesTest.flat(3), at);
        checkFillet(sec, SlotProfilesTest.flat(3), at, 6, 2);
        FeatureVolumeCheck.assertFloorCleared(sec, 3, BOSS.buffer(-2 - 0.005, 64));
    }

    @Test
    void aCutterWithASmallerCornerLeavesTheRestOfTheFillet() {
        ToolpathSection sec = section("WS FILLET CORNER");
        DoubleFunction<Geometry> at = pocketAt(CORNER, 10, 3);
        FeatureVolumeCheck.assertFloor(sec, -10, 1e-6);
        FeatureVolumeCheck.assertInside(sec, corner(4, 1), at);
        checkFillet(sec, corner(4, 1), at, 10, 3);
        // the cutter's flat bottom, 3 mm about its axis, reaches the fillet's foot
        FeatureVolumeCheck.assertFloorCleared(sec, 3, CORNER.buffer(-3 - 0.005, 64));
    }

    @Test
    void aRoughingLeavesItsAllowancesOffTheFilletToo() throws Exception {
        // 0.5 mm on the walls, 0.2 mm on the floor: the fillet's passes move off the walls and up
        String text = Files.readString(PART)
                .replace(
                        "'MILL FILLET FLAT',5.000,$,#52,#50,$,$,$,$,$,3.000,3.000,$,$);",
                        "'MILL FILLET FLAT',5.000,$,#52,#50,$,$,$,$,$,3.000,3.000,0.500,0.200);");
        ToolpathSection sec = planText(text).toolpath().sections().get(0);
        DoubleFunction<Geometry> at = pocketAt(FLAT, 8, 3);
        FeatureVolumeCheck.assertFloor(sec, -7.8, 1e-6);
        FeatureVolumeCheck.assertInside(sec, SlotProfilesTest.flat(3.5), at);
        checkFillet(sec, SlotProfilesTest.flat(3.5), at, 8, 3);
        FeatureVolumeCheck.assertFloorCleared(sec, 3, FLAT.buffer(-3.5 - 0.005, 64));
    }

    @Test
    void theVolumeCheckSeesACutterWiderThanPlannedCutIntoTheFillet() {
        ToolpathSection sec = section("WS FILLET FLAT");
        double z = -8 + 1.5;
        assertTrue(FeatureVolumeCheck.outsideAt(
                        sec,
                        SlotProfilesTest.flat(3.05),
                        z,
                        pocketAt(FLAT, 8, 3).apply(z))
                > 1e-6);
        assertTrue(FeatureVolumeCheck.outsideAt(
                        sec, SlotProfilesTest.flat(3), z, pocketAt(FLAT, 8, 3).apply(z))
                < 1e-6);
    }

    @Test
    void theZLevelsLeaveNoMoreThanTheScallop() {
        List<FilletedFloor.Level> levels = FilletedFloor.levels(3, FilletedFloor.SCALLOP_MM);
        // the floor pass (at the fillet's foot) and the pass above the fillet close the staircase
        double[] h = new double[levels.size() + 2];
        double[] d = new double[levels.size() + 2];
        h[0] = 3;
        d[0] = 0;
        for (int i = 0; i < levels.size(); i++) {
            h[i + 1] = levels.get(i).heightMm();
            d[i + 1] = levels.get(i).offsetMm();
            assertEquals(filletAt(3, h[i + 1]), d[i + 1], 1e-9);
        }
        h[h.length - 1] = 0;
        d[d.length - 1] = 3;
        for (int i = 1; i < h.length; i++) {
            // the corner of the step between a level and the one above, inside the fillet's circle about (3, 3)
            double left = 3 - Math.hypot(3 - d[i], 3 - h[i - 1]);
            assertTrue(left <= FilletedFloor.SCALLOP_MM + 1e-9, "leaves " + left + " mm at " + h[i]);
            assertTrue(h[i] < h[i - 1]);
        }
        assertTrue(levels.size() > 50 && levels.size() < 400, levels.size() + " levels");
    }

    private static ToolpathPlanner.Plan planText(String text) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "fillets.stp"), Tolerance.DEFAULT);
    }

    @Test
    void aCutterWhoseCornerIsTheFilletFollowsItAsBefore() throws Exception {
        // the 8 mm cutter's 1 mm corner in a 1 mm fillet: the pocket as drawn, no Z-levels
        String text = Files.readString(PART).replace("(),$,#257,3.000,8.000,#35);", "(),$,#257,1.000,8.000,#35);");
        ToolpathSection exact = planText(text).toolpath().sections().get(2);
        String none = Files.readString(PART).replace("(),$,#257,3.000,8.000,#35);", "(),$,#257,$,8.000,#35);");
        ToolpathSection plain = planText(none).toolpath().sections().get(2);
        assertEquals(plain.moves(), exact.moves());
        assertTrue(
                section("WS FILLET CORNER").moves().size() > 2 * plain.moves().size());
    }

    @Test
    void aCutterWhoseCornerIsLargerThanTheFilletIsRefused() throws Exception {
        String text = Files.readString(PART).replace("(),$,#257,3.000,8.000,#35);", "(),$,#257,0.500,8.000,#35);");
        ToolpathPlanner.Plan p = planText(text);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS FILLET CORNER' (#")
                                && x.endsWith("the pocket's floor meets its walls in a 0.5 mm radius; a cutter with a 1"
                                        + " mm corner would leave a 1 mm one, material the drawing takes away: a cutter"
                                        + " whose corner is at most 0.5 mm mills it")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }
}
