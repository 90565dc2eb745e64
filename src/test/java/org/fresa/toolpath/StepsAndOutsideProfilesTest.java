package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * Steps and a general outside profile (src/test/resources/stepnc/steps-outside-profiles.stp,
 * a 120 x 150 x 30 block, top at z 0): at every 0.5 mm of height the tool's cross-section along
 * its moves stays within the feature's volume (or outside the block) by 0.01 mm, checked with
 * JTS; the floor is cleared where the tool reaches; the tool goes down only outside the block;
 * the program check and LinuxCNC's interpreter accept the program. The same checks run with a
 * cutter 0.05 mm wider than the one planned must fail, so that they can.
 */
class StepsAndOutsideProfilesTest {

    static final Path PART = Path.of("src/test/resources/stepnc/steps-outside-profiles.stp");
    static final double SLICE_MM = 0.5;
    /** The block: the tool may go anywhere outside it. */
    static final Geometry BLOCK = SlotProfilesTest.box(0, 0, 120, 150);

    static final Geometry OUTSIDE =
            SlotProfilesTest.box(-1000, -1000, 1000, 1000).difference(BLOCK);

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

    /**
     * The tool of this radius along the section stays within the feature (its region in XY, the
     * same at every height down to its floor) or outside the block by 0.01 mm; its lowest move is
     * at the floor expected; the floor region is cleared where the tool's disc reaches; with
     * fromOutside, every descent ends outside the block grown by the radius.
     */
    static void check(ToolpathSection sec, double radius, Geometry feature, double floorZ, Geometry floorRegion) {
        check(sec, radius, feature, floorZ, floorRegion, true);
    }

    static void check(
            ToolpathSection sec,
            double radius,
            Geometry feature,
            double floorZ,
            Geometry floorRegion,
            boolean fromOutside) {
        FeatureVolumeCheck.assertFloor(sec, floorZ, 1e-6);
        Geometry allowed = feature.union(OUTSIDE);
        FeatureVolumeCheck.assertInside(sec, SlotProfilesTest.flat(radius), z -> allowed);
        // 5 um inside the walls: the tool's buffered discs fall short of a round wall by up to 2 um
        FeatureVolumeCheck.assertFloorCleared(sec, radius, floorRegion.buffer(-0.005, 64));
        if (!fromOutside) {
            return;
        }
        var at = sec.start();
        Geometry grown = BLOCK.buffer(radius);
        for (Move m : sec.moves()) {
            if (m instanceof Move.Linear
                    && m.end().z() < at.z() - 1e-9
                    && m.end().z() < 0) {
                assertTrue(
                        !grown.contains(Swept.GF.createPoint(new org.locationtech.jts.geom.Coordinate(
                                m.end().x(), m.end().y()))),
                        sec.label() + " goes down into the block at " + m.end());
            }
            at = m.end();
        }
    }

    // step 1: x 105..120 over the whole block, 8 deep
    static final Geometry STEP_OPEN = SlotProfilesTest.box(105, 0, 120, 150);
    // step 2: y 0..10 from x 20 to the block's end, 5 deep
    static final Geometry STEP_CLOSED = SlotProfilesTest.box(20, 0, 120, 10);
    // the part kept by the outside profile: 80 x 120 centred at (50, 75)
    static final Geometry PART_KEPT = SlotProfilesTest.box(10, 15, 90, 135);
    static final Geometry AROUND_PART =
            SlotProfilesTest.box(-1000, -1000, 1000, 1000).difference(PART_KEPT);

    @Test
    void everyWorkingstepIsPlanned() {
        assertEquals(6, plan.planned(), plan.problems().toString());
        assertEquals(6, plan.workingsteps());
    }

    @Test
    void aStepOpenAtBothEndsIsRoughedWithItsAllowancesAndFinishedFromTheOpenSide() {
        ToolpathSection rough = section("WS STEP ROUGH");
        // the allowances: 0.5 mm on the wall, 0.2 mm on the floor
        check(rough, 5.5, STEP_OPEN, -7.8, SlotProfilesTest.box(105.5, 0, 120, 150));
        ToolpathSection finish = section("WS STEP FINISH");
        check(finish, 5, STEP_OPEN, -8, STEP_OPEN);
        // climb milling with M3: the passes run -y, the step's material (towards the wall, -x) on the right
        var at = finish.start();
        for (Move m : finish.moves()) {
            if (m.end().z() < 0 && at.z() == m.end().z() && Math.abs(m.end().x() - at.x()) < 1e-9) {
                assertTrue(
                        m.end().y() <= at.y() || m.end().x() > 120,
                        "a pass runs +y at x " + m.end().x());
            }
            at = m.end();
        }
    }

    @Test
    void aStepWithAClosedStartKeepsTheToolWithinItsEnd() {
        check(section("WS STEP CLOSED START"), 3, STEP_CLOSED, -5, STEP_CLOSED);
    }

    @Test
    void anOutsideProfileIsMilledAsAContourOutsideThePartInLayers() {
        ToolpathSection sec = section("WS OUTSIDE PROFILE");
        check(
                sec,
                5,
                AROUND_PART,
                -6,
                PART_KEPT.buffer(10, 64).difference(PART_KEPT).intersection(BLOCK));
        long arcs = sec.moves().stream().filter(m -> m instanceof Move.Circular).count();
        // two layers of 3 mm, four rounded corners each: the offset corners stay arcs
        assertEquals(8, arcs);
        // the block's far corner (120, 0) is sqrt(30^2 + 15^2) from the part's corner (90, 15)
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS OUTSIDE PROFILE': the stock reaches 33.54102 mm beyond"
                                + " the outside profile; the contour cuts the 10 mm next to it"),
                plan.problems().toString());
    }

    // the open pocket: x 0..25 between y 60 and 100, and the half circle of radius 20 about (25, 80) beyond
    static final Geometry OPEN_POCKET = SlotProfilesTest.box(0, 60, 25, 100)
            .union(SlotProfilesTest.disc(25, 80, 20).intersection(SlotProfilesTest.box(25, 50, 50, 110)));

    @Test
    void anOpenPocketIsEnteredFromBeyondItsOpenSideAtDepthAndClearedInLayers() {
        ToolpathSection sec = section("WS OPEN POCKET");
        check(sec, 5, OPEN_POCKET, -10, OPEN_POCKET);
        // no ramp: every move going down is straight down, outside the block
        var at = sec.start();
        for (Move m : sec.moves()) {
            if (m.end().z() < at.z() - 1e-9) {
                assertEquals(at.x(), m.end().x(), 1e-9);
                assertTrue(m.end().x() <= -5 - 1, "goes down at " + m.end());
            }
            at = m.end();
        }
        assertTrue(sec.moves().stream().anyMatch(m -> m instanceof Move.Circular), "the round end stays an arc");
    }

    // the pocket 60 x 40 at (60, 120) with 6 mm corners, less its round boss and its rectangular one
    static final Geometry BOSSES = SlotProfilesTest.disc(45, 120, 6).union(SlotProfilesTest.box(67, 112, 77, 128));
    static final Geometry POCKET_AROUND_BOSSES =
            SlotProfilesTest.box(30, 100, 90, 140).buffer(-6, 64).buffer(6, 64).difference(BOSSES);

    @Test
    void aClosedPocketLeavesItsBossesStandingAndClearsTheFloorAroundThem() {
        ToolpathSection sec = section("WS POCKET WITH BOSSES");
        // entered by ramps along its loops, inside the block
        check(sec, 3, POCKET_AROUND_BOSSES, -6, POCKET_AROUND_BOSSES, false);
        assertTrue(sec.moves().stream().anyMatch(m -> m instanceof Move.Circular), "round the round boss on arcs");
    }

    /** The area (mm2) the tool of this radius sweeps outside the feature (or the block's outside) at height z. */
    static double outsideAt(ToolpathSection sec, double radius, Geometry feature, double z) {
        return FeatureVolumeCheck.outsideAt(sec, SlotProfilesTest.flat(radius), z, feature.union(OUTSIDE));
    }

    @Test
    void theVolumeCheckCatchesACutterWiderThanPlanned() {
        // 0.05 mm more radius than planned: each feature's volume check at its floor sees the tool leave it
        assertTrue(outsideAt(section("WS STEP FINISH"), 5.05, STEP_OPEN, -8) > 1e-6);
        assertTrue(outsideAt(section("WS STEP CLOSED START"), 3.05, STEP_CLOSED, -5) > 1e-6);
        assertTrue(outsideAt(section("WS OUTSIDE PROFILE"), 5.05, AROUND_PART, -6) > 1e-6);
        assertTrue(outsideAt(section("WS OPEN POCKET"), 5.05, OPEN_POCKET, -10) > 1e-6);
        assertTrue(outsideAt(section("WS POCKET WITH BOSSES"), 3.05, POCKET_AROUND_BOSSES, -6) > 1e-6);
        // and the planned radius does not
        assertTrue(outsideAt(section("WS POCKET WITH BOSSES"), 3, POCKET_AROUND_BOSSES, -6) < 1e-6);
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }

    private static ToolpathPlanner.Plan planText(String text) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "steps.stp"), Tolerance.DEFAULT);
    }

    private static String problemOf(ToolpathPlanner.Plan p, String workingstep) {
        return p.problems().stream()
                .filter(x -> x.startsWith("workingstep '" + workingstep + "' (#"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(workingstep + " not refused: " + p.problems()));
    }

    @Test
    void whatIsNotMilledIsRefusedWithTheReason() throws Exception {
        String part = Files.readString(PART);
        ToolpathPlanner.Plan p = planText(
                part
                        // a wall overhanging its floor, a boss larger than the closed step, an open outside profile
                        // ending inside the block
                        .replace(
                                "#16= STEP('STEP OPEN',#4,(#20,#21),#81,#82,#24,#25,());",
                                "#16= STEP('STEP OPEN',#4,(#20,#21),#81,#82,#24,#29,());\n#29= VEE_PROFILE($,0.000,60.000,90.000);")
                        .replace(
                                "#17= STEP('STEP CLOSED START',#4,(#22),#83,#84,#26,#25,());",
                                "#17= STEP('STEP CLOSED START',#4,(#22),#83,#84,#26,#25,(#30));\n"
                                        + "#30= BOSS('BOSS',#4,(),#83,#84,#28,$);")
                        .replace(
                                "#18= GENERAL_OUTSIDE_PROFILE('OUTSIDE PROFILE',#4,(#23),#85,#86,#27,#28);",
                                "#18= GENERAL_OUTSIDE_PROFILE('OUTSIDE PROFILE',#4,(#23),#85,#86,#27,#31);\n"
                                        + "#31= GENERAL_PROFILE($,#32);\n#32= POLYLINE('OPEN',(#110,#111,#112));")
                        // the open pocket's open side moved 5 mm into the block
                        .replace(
                                "#85= AXIS2_PLACEMENT_3D('OUTSIDE PROFILE',#101,#96,#97);",
                                "#85= AXIS2_PLACEMENT_3D('OUTSIDE PROFILE',#101,#96,#97);\n"
                                        + "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#89,#88,(),$,#257,$,$,#235,$);\n"
                                        + "#89= AXIS2_PLACEMENT_3D('INSIDE',#135,#96,#97);\n#135= CARTESIAN_POINT('',(5.0,0.0,0.0));")
                        .replace("#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#257,$,$,#235,$);", "")
                        // a planar face whose boundary (a line swept along itself) holds none of the round boss
                        .replace("(#10,#11,#12,#13,#14,#15)", "(#10,#11,#12,#13,#14,#15,#400)")
                        .replace(
                                "#125= CUTTING_COMPONENT",
                                "#400= MACHINING_WORKINGSTEP('WS FACE WITH BOSS',#62,#401,#310,$);\n"
                                        + "#401= PLANAR_FACE('FACE',#4,(#310),#85,#340,#402,#403,$,(#320));\n"
                                        + "#402= LINEAR_PATH($,120.000,#56);\n#403= LINEAR_PROFILE($,150.000);\n#125= CUTTING_COMPONENT"));
        assertTrue(
                problemOf(p, "WS FACE WITH BOSS")
                        .endsWith("boss 'ROUND BOSS' is not inside the planar face clear of its boundary: only"
                                + " free-standing bosses are left standing"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS STEP ROUGH")
                        .contains("the step's wall_boundary gives profile_angle 60 and tilt_angle 90: a wall at 60 deg"
                                + " to its floor meets the block's top at 60 or 120 deg"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS STEP CLOSED START")
                        .endsWith("boss 'BOSS' is not inside the step clear of its boundary: only free-standing"
                                + " bosses are left standing"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS OUTSIDE PROFILE").endsWith("only profiles from edge to edge across the block are cut"),
                p.problems().toString());
        assertTrue(
                problemOf(p, "WS OPEN POCKET").endsWith("is not on the edge of the workpiece's block"),
                p.problems().toString());
        // the pocket with bosses is still planned
        assertEquals(1, p.planned(), p.problems().toString());
    }
}
