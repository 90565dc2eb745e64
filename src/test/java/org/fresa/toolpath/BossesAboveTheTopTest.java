package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * A boss taller than its pocket: the round boss of the closed pocket of
 * src/test/resources/stepnc/steps-outside-profiles.stp (6 deep) standing 10 mm above the pocket's
 * top, 16 deep to the floor. The region engine goes from loop to loop in straight rapid moves 5 mm
 * over its top, which would run into it: the traverses are raised to 5 mm over the boss's top,
 * and where the tool would still cross below it (a filleted pocket's floor pass at the retract
 * height) the plan is refused.
 */
class BossesAboveTheTopTest {

    static final String ROUND_BOSS = "#321= AXIS2_PLACEMENT_3D('ROUND BOSS',#322,#96,#97);";
    static final String TALL_BOSS = "#320= BOSS('ROUND BOSS',#4,(),#321,#341,#323,$);\n"
            + "#321= AXIS2_PLACEMENT_3D('ROUND BOSS',#324,#96,#97);\n"
            + "#324= CARTESIAN_POINT('TALL BOSS TOP',(45.000,120.000,10.000));\n"
            + "#341= PLANE('BOSS DEPTH 16',#342);\n"
            + "#342= AXIS2_PLACEMENT_3D('DEPTH 16',#343,#96,#97);\n"
            + "#343= CARTESIAN_POINT('DEPTH 16',(0.000,0.000,-16.000));";

    static ToolpathPlanner.Plan plan(String text) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "tall.stp"), Tolerance.DEFAULT);
    }

    /** The lowest height at which a rapid move of the section goes across (mm). */
    static double lowestTraverse(ToolpathSection sec) {
        double lowest = Double.POSITIVE_INFINITY;
        Vec3 at = sec.start();
        for (Move m : sec.moves()) {
            if (m instanceof Move.Rapid
                    && Math.hypot(m.end().x() - at.x(), m.end().y() - at.y()) > 1e-6) {
                lowest = Math.min(lowest, Math.min(at.z(), m.end().z()));
            }
            at = m.end();
        }
        return lowest;
    }

    @Test
    void theTraversesClearABossStandingAboveThePocketsTop() throws Exception {
        String text = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace("#320= BOSS('ROUND BOSS',#4,(),#321,#340,#323,$);\n" + ROUND_BOSS, TALL_BOSS);
        assertTrue(text.contains("TALL BOSS TOP"));
        ToolpathPlanner.Plan p = plan(text);
        ToolpathSection sec = p.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS POCKET WITH BOSSES"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(p.problems().toString()));
        assertTrue(lowestTraverse(sec) >= 15 - 1e-9, "a traverse at " + lowestTraverse(sec));
        // the cuts are those of the pocket with its boss as high as its top
        StepsAndOutsideProfilesTest.check(
                sec,
                3,
                StepsAndOutsideProfilesTest.POCKET_AROUND_BOSSES,
                -6,
                StepsAndOutsideProfilesTest.POCKET_AROUND_BOSSES,
                false);
        assertTrue(
                p.problems()
                        .contains("workingstep 'WS POCKET WITH BOSSES': a boss stands 10 mm above the pocket's top:"
                                + " the tool goes from loop to loop 5 mm over it"),
                p.problems().toString());
    }

    @Test
    void aFilletedPocketWhoseFloorPassWouldCrossBelowATallBossIsRefused() throws Exception {
        String text = Files.readString(FilletedPocketsTest.PART)
                .replace(
                        "#41= AXIS2_PLACEMENT_3D('ROUND BOSS',#111,#96,#97);",
                        "#41= AXIS2_PLACEMENT_3D('ROUND BOSS',#113,#96,#97);\n"
                                + "#113= CARTESIAN_POINT('TALL BOSS TOP',(85.000,35.000,10.000));");
        assertTrue(text.contains("TALL BOSS TOP"));
        ToolpathPlanner.Plan p = plan(text);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS FILLET BOSS' (#")
                                && x.contains("not over its tallest boss, whose top is at 10 mm")),
                p.problems().toString());
    }
}
