package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * Dovetail slots (src/test/resources/stepnc/slots-dovetail.stp: square-U profiles whose sides
 * meet the base at 60 deg): the end mill mills the neck, the dovetail mill the undercut sides;
 * at every height each tool's cross-section along its moves stays within the dovetail's there
 * (or outside the block, past an open end) by 0.01 mm, checked with JTS; together they leave no
 * material in the through slot's cross-section at any height; LinuxCNC's interpreter accepts the
 * program; a dovetail mill that does not fit is refused with the reason.
 */
class DovetailSlotTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-dovetail.stp");
    static final double COT60 = 1 / Math.tan(Math.toRadians(60));

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    /** The dovetail mill of the part: 16 mm at its tip, its flank 30 deg from its axis, a 10 mm edge. */
    static SlotProfilesTest.Shape dovetailMill() {
        return h -> h <= 10 ? 8 - h * Math.tan(Math.toRadians(30)) : 0;
    }

    /** Half the width of a dovetail of this base and depth at height z (its top at z 0). */
    static DoubleUnaryOperator half(double baseMm, double depthMm) {
        return z -> baseMm / 2 - (z + depthMm) * COT60;
    }

    static ToolpathSection section(String label) {
        return FeatureVolumeCheck.section(plan, label);
    }

    @Test
    void everyWorkingstepIsPlannedAndTheNecksSayWhatTheyLeave() {
        assertEquals(4, plan.planned(), plan.problems().toString());
        assertTrue(
                plan.problems().stream()
                        .anyMatch(p -> p.contains("WS THROUGH NECK")
                                && p.contains("mills the dovetail's 13.071797 mm neck; its sides, undercut by"
                                        + " 3.464102 mm, need a DOVETAIL_MILL")),
                plan.problems().toString());
    }

    @Test
    void throughTheBlockTheNeckAndTheSidesStayInTheDovetailAndClearIt() {
        SlotProfilesTest.Slot s = new SlotProfilesTest.Slot(
                0, 120, 15, 6, half(20, 6), SlotProfilesTest.End.OPEN, SlotProfilesTest.End.OPEN);
        ToolpathSection neck = section("WS THROUGH NECK");
        ToolpathSection sides = section("WS THROUGH SIDES");
        double neckHalf = 10 - 6 * COT60;
        SlotProfilesTest.check(
                neck, s, SlotProfilesTest.flat(5), -6, SlotProfilesTest.box(0, 15 - neckHalf, 120, 15 + neckHalf), 5);
        SlotProfilesTest.check(sides, s, dovetailMill(), -6, SlotProfilesTest.box(0, 5, 120, 25), 8);
        // along each side, the flank on it
        assertEquals(
                List.of(13.0, 17.0),
                sides.moves().stream()
                        .filter(m -> m.end().z() < -5.999)
                        .map(m -> m.end().y())
                        .distinct()
                        .sorted()
                        .toList());
        // and nothing is left of the dovetail at any height inside the block
        for (double z = -6; z <= 0; z += 0.5) {
            double w = half(20, 6).applyAsDouble(z);
            Geometry cut = SlotProfilesTest.slice(neck, SlotProfilesTest.flat(5), z).stream()
                    .reduce(Swept.GF.createPolygon(), Geometry::union);
            for (Geometry g : SlotProfilesTest.slice(sides, dovetailMill(), z)) {
                cut = cut.union(g);
            }
            double left = SlotProfilesTest.box(0, 15 - w, 120, 15 + w)
                    .difference(cut.buffer(0.01, 64))
                    .getArea();
            assertTrue(left < 1e-6, "at z " + z + " the tools leave " + left + " mm2 of the dovetail");
        }
    }

    @Test
    void fromItsOpenStartToItsFlatEndTheSidesStayInTheDovetail() {
        SlotProfilesTest.Slot s = new SlotProfilesTest.Slot(
                0, 80, 42, 8, half(24, 8), SlotProfilesTest.End.OPEN, new SlotProfilesTest.End('f', 0, 0));
        ToolpathSection sides = section("WS FLAT END SIDES");
        // the floor it can reach: its disc short of the flat end
        SlotProfilesTest.check(sides, s, dovetailMill(), -8, SlotProfilesTest.box(0, 30, 80, 54), 8);
        assertTrue(sides.start().x() < -8, "it goes down past the open start: " + sides.start());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }

    @Test
    void aDovetailMillThatDoesNotFitIsRefusedWithTheReason() throws Exception {
        String part = Files.readString(PART);
        String tool = "#52= MILLING_TOOL_DIMENSION(16.000,$,30.000,10.0,0.0,$,$);";
        assertTrue(part.contains(tool));
        String[][] cases = {
            {
                tool.replace("30.000", "25.000"),
                "the dovetail mill's flank leans 25 deg from its axis, the dovetail's"
                        + " sides 30 deg (60 deg to the base): over the 6 mm depth it would leave or cut"
            },
            {tool.replace("30.000", "$"), "the DOVETAIL_MILL gives no tool_circumference_angle"},
            {tool.replace("16.000", "22.000"), "the dovetail mill (22 mm) is wider than the dovetail's base (20 mm)"},
            {tool.replace("16.000", "6.000"), "the dovetail mill (6 mm) tapers to nothing below the dovetail's top"},
            {
                tool.replace("10.0,0.0", "4.0,0.0"),
                "the dovetail mill's cutting edge (4 mm) is shorter than the" + " dovetail (6 mm deep)"
            },
            {
                "#16= SLOT('THROUGH',#4,(#20,#21),#81,#82,#24,#25,(#26,#26));" + "#30= FLAT_SLOT_END_TYPE($,$);",
                "a DOVETAIL_MILL enters the dovetail from an open end"
            }
        };
        for (String[] c : cases) {
            String text = c[0].startsWith("#16=")
                    ? part.replace("(#26,#26));", "(#30,#30));\n#30= FLAT_SLOT_END_TYPE($,$);")
                    : part.replace(tool, c[0]);
            ToolpathPlanner.Plan p = SlotProfilesTest.planText(text);
            assertTrue(SlotProfilesTest.problemOf(p, "WS THROUGH SIDES").contains(c[1]), c[1] + " / " + p.problems());
        }
        // a straight tool wider than the neck
        ToolpathPlanner.Plan wide = SlotProfilesTest.planText(part.replace(
                "#48= MILLING_TOOL_DIMENSION(10.000,$,$,25.0,0.0,$,$);",
                "#48= MILLING_TOOL_DIMENSION(14.000,$,$,25.0,0.0,$,$);"));
        assertTrue(
                SlotProfilesTest.problemOf(wide, "WS THROUGH NECK")
                        .contains("the tool (14 mm) is wider than the dovetail's neck (13.071797 mm)"),
                wide.problems().toString());
    }
}
