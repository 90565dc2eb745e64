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
 * An open general outside profile: the outside profile of
 * src/test/resources/stepnc/steps-outside-profiles.stp with its feature boundary an open
 * composite curve across the block, from (0, 20) along +x to (40, 20), a quarter circle of radius
 * 15 counter-clockwise about (40, 35) to (55, 35), then along +x to the block's side at (120, 35):
 * the material kept on its left (north), 6 deep, a 10 mm cutter. The checks are those of
 * {@link StepsAndOutsideProfilesTest}: the tool within the removed side or outside the block by
 * 0.01 mm at every 0.5 mm of height, the 10 mm next to the profile cleared, descents outside the
 * block, a cutter 0.05 mm wider seen cutting into the part kept, the program check and rs274.
 */
class OpenOutsideProfileTest {

    static String part;
    static ToolpathPlanner.Plan plan;

    /** The part kept: north of the profile, within the block. */
    static final Geometry KEPT = SlotProfilesTest.box(0, 35, 120, 150)
            .union(SlotProfilesTest.box(0, 20, 40, 35))
            .union(SlotProfilesTest.disc(40, 35, 15).intersection(SlotProfilesTest.box(40, 20, 55, 35)));

    static final Geometry AROUND_KEPT =
            SlotProfilesTest.box(-1000, -1000, 1000, 1000).difference(KEPT);

    @BeforeAll
    static void planThePart() throws Exception {
        // the profile frame is the part's centre (50, 75): the points are written relative to it
        part = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace(
                        "#18= GENERAL_OUTSIDE_PROFILE('OUTSIDE PROFILE',#4,(#23),#85,#86,#27,#28);",
                        "#18= GENERAL_OUTSIDE_PROFILE('OUTSIDE PROFILE',#4,(#23),#85,#86,#27,#31);\n"
                                + "#31= GENERAL_PROFILE(#87,#32);\n"
                                + "#32= COMPOSITE_CURVE('ACROSS',(#33,#35,#36),.F.);\n"
                                + "#33= COMPOSITE_CURVE_SEGMENT(.CONTINUOUS.,.T.,#140);\n"
                                + "#35= COMPOSITE_CURVE_SEGMENT(.CONTINUOUS.,.T.,#143);\n"
                                + "#36= COMPOSITE_CURVE_SEGMENT(.CONTINUOUS.,.T.,#146);\n"
                                + "#140= TRIMMED_CURVE('A',#141,(#150),(#151),.T.,.CARTESIAN.);\n"
                                + "#141= LINE('A',#150,#142);\n#142= VECTOR('A',#97,40.000);\n"
                                + "#143= TRIMMED_CURVE('ARC',#144,(#151),(#152),.T.,.CARTESIAN.);\n"
                                + "#144= CIRCLE('ARC',#145,15.000);\n"
                                + "#145= AXIS2_PLACEMENT_3D('ARC CENTRE',#153,#96,#97);\n"
                                + "#146= TRIMMED_CURVE('B',#147,(#152),(#154),.T.,.CARTESIAN.);\n"
                                + "#147= LINE('B',#152,#148);\n#148= VECTOR('B',#97,65.000);\n"
                                + "#150= CARTESIAN_POINT('',(-50.000,-55.000,0.000));\n"
                                + "#151= CARTESIAN_POINT('',(-10.000,-55.000,0.000));\n"
                                + "#152= CARTESIAN_POINT('',(5.000,-40.000,0.000));\n"
                                + "#153= CARTESIAN_POINT('',(-10.000,-40.000,0.000));\n"
                                + "#154= CARTESIAN_POINT('',(70.000,-40.000,0.000));");
        plan = ToolpathPlanner.plan(StepNcReader.read(new StringReader(part), "open.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section() {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS OUTSIDE PROFILE"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not planned: " + plan.problems()));
    }

    @Test
    void theOpenProfileIsCutAsAContourOnItsRightFromTheAirToTheAir() {
        ToolpathSection sec = section();
        Geometry next = KEPT.buffer(9.5, 64).difference(KEPT).intersection(StepsAndOutsideProfilesTest.BLOCK);
        StepsAndOutsideProfilesTest.check(sec, 5, AROUND_KEPT, -6, next);
        // two layers of 3 mm, each round the quarter circle on an arc
        assertEquals(
                2, sec.moves().stream().filter(m -> m instanceof Move.Circular).count());
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS OUTSIDE PROFILE': the stock reaches 35 mm beyond the open outside"
                                + " profile; the pass cuts the 10 mm next to it"),
                plan.problems().toString());
    }

    @Test
    void theVolumeCheckCatchesACutterWiderThanPlanned() {
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 5.05, AROUND_KEPT, -6) > 1e-6);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 5, AROUND_KEPT, -6) < 1e-6);
    }

    @Test
    void anOpenProfileEndingInsideTheBlockIsRefused() throws Exception {
        String text = part.replace(
                "#154= CARTESIAN_POINT('',(70.000,-40.000,0.000));",
                "#154= CARTESIAN_POINT('',(60.000,-40.000,0.000));");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "open.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS OUTSIDE PROFILE' (#")
                                && x.endsWith("only profiles from edge to edge across the block are cut")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(part, "open.stp", dir);
    }
}
