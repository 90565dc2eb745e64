package org.fresa.toolpath;

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
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;

/**
 * A closed pocket bounded by a GENERAL_CLOSED_PROFILE as GRIMA's writers put it
 * (testePrecedencias.p21): a POLYLINE of three points that does not come back to its first, and
 * an orthogonal_radius (12 mm) larger than the tool's radius (3 mm). The pocket of
 * src/test/resources/stepnc/steps-outside-profiles.stp (6 deep, at (60, 120)) is replaced by the
 * triangle (35, 105), (85, 105), (60, 138) with its corners rounded by 12 mm: at every 0.5 mm of
 * height the tool stays within it by 0.01 mm (out of the fillets' material), the floor is cleared,
 * a cutter 0.05 mm wider is seen leaving it, and the program passes the program check and rs274.
 */
class GeneralClosedPocketTest {

    static String part;
    static ToolpathPlanner.Plan plan;

    static final Geometry TRIANGLE = Swept.GF.createPolygon(new Coordinate[] {
        new Coordinate(35, 105), new Coordinate(85, 105), new Coordinate(60, 138), new Coordinate(35, 105)
    });
    static final Geometry ROUNDED = TRIANGLE.buffer(-12, 64).buffer(12, 64);

    @BeforeAll
    static void planThePart() throws Exception {
        part = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace(
                        "#300= CLOSED_POCKET('POCKET WITH BOSSES',#4,(#310),#301,#340,(#320,#330),$,#257,$,6.000,#302);",
                        "#300= CLOSED_POCKET('POCKET WITH BOSSES',#4,(#310),#301,#340,(),$,#257,$,12.000,#302);")
                .replace(
                        "#302= RECTANGULAR_CLOSED_PROFILE($,40.000,60.000);",
                        "#302= GENERAL_CLOSED_PROFILE($,#304);\n#304= POLYLINE('TRIANGLE',(#305,#306,#307));\n"
                                + "#305= CARTESIAN_POINT('',(-25.000,-15.000,0.000));\n"
                                + "#306= CARTESIAN_POINT('',(25.000,-15.000,0.000));\n"
                                + "#307= CARTESIAN_POINT('',(0.000,18.000,0.000));");
        plan = ToolpathPlanner.plan(StepNcReader.read(new StringReader(part), "triangle.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section() {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS POCKET WITH BOSSES"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not planned: " + plan.problems()));
    }

    @Test
    void theUnclosedPolylineIsClosedAndTheCornersKeepTheirFillets() {
        ToolpathSection sec = section();
        // entered by ramps inside the block, as a closed pocket is
        StepsAndOutsideProfilesTest.check(sec, 3, ROUNDED, -6, ROUNDED, false);
        assertTrue(sec.moves().stream().anyMatch(m -> m instanceof Move.Circular), "the fillets stay arcs");
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS POCKET WITH BOSSES': the pocket's POLYLINE does not end where it"
                                + " starts; closed by a line from its last point back to its first"),
                plan.problems().toString());
    }

    @Test
    void theVolumeCheckSeesTheSharpCornersCutIntoTheFillets() {
        // a cutter 0.05 mm wider leaves the pocket
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 3.05, ROUNDED, -6) > 1e-6);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 3, ROUNDED, -6) < 1e-6);
    }

    @Test
    void aRadiusThatDoesNotFitTheSidesIsRefused() throws Exception {
        String text = part.replace("(),$,#257,$,12.000,#302);", "(),$,#257,$,14.000,#302);");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "triangle.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS POCKET WITH BOSSES' (#")
                                && x.contains("orthogonal_radius 14 mm does not fit")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(part, "triangle.stp", dir);
    }
}
