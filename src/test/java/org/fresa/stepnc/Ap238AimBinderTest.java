package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

/**
 * AP238 in its integrated form (AIM), read from hand-made files: the same model as the ARM, every
 * value converted from its own unit.
 */
class Ap238AimBinderTest {

    static final Path INCH = Path.of("src/test/resources/stepnc/aim-inch-hole-and-pocket.stp");
    private static final double EPS = 1e-9;

    static StepNcProgram inMillimetres() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#1=(CONVERSION_BASED_UNIT('INCH',#3) LENGTH_UNIT() NAMED_UNIT(#4));",
                        "#1=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));");
        return StepNcReader.read(new StringReader(text), "mm.stp");
    }

    private static void near(Vec3 expected, Vec3 actual) {
        assertTrue(expected.distance(actual) <= EPS, "expected " + expected + ", found " + actual);
    }

    @Test
    void theWorkplanRunsItsWorkingstepsInSequencePositionOrder() throws Exception {
        StepNcProgram p = StepNcReader.read(INCH);
        assertTrue(p.integratedForm());
        assertEquals("AIM", p.form());
        assertEquals("INCH PART", p.projectId());
        assertEquals(
                List.of("WS DRILL HOLE1", "WS ROUGH POCKET1"),
                p.workingsteps().stream().map(MachiningWorkingstep::id).toList());
        assertTrue(p.skipped().isEmpty(), p.skipped().toString());
        assertEquals("MAIN WORKPLAN", p.mainWorkplan().orElseThrow().id());
        assertEquals("SETUP1", p.workingsteps().get(0).setup().orElseThrow().id());
        assertEquals(
                List.of("PLATE"), p.workpieces().stream().map(Workpiece::id).toList());
        // the project is a MACHINING_PROJECT, the workingsteps are in the main workplan's sequence
        assertFalse(
                p.warnings().stream().anyMatch(w -> w.contains("PROJECT")),
                p.warnings().toString());
    }

    @Test
    void anSiPrefixScalesTheFilesLengths() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#1=(CONVERSION_BASED_UNIT('INCH',#3) LENGTH_UNIT() NAMED_UNIT(#4));",
                        "#1=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.CENTI.,.METRE.));");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "cm.stp");
        near(new Vec3(10, 20, 0), p.workingsteps().get(0).feature().location());
        assertEquals(5, p.workingsteps().get(0).feature().depthMm().getAsDouble(), EPS);
        // 5 cm/minute
        assertEquals(
                50,
                p.workingsteps().get(0).operation().technology().feedMmPerMin().getAsDouble(),
                1e-9);
    }

    @Test
    void inchLengthsAndInchPerMinuteFeedsComeOutInMillimetres() throws Exception {
        StepNcProgram p = StepNcReader.read(INCH);
        MachiningWorkingstep drill = p.workingsteps().get(0);
        Feature hole = drill.feature();
        assertEquals(Feature.FeatureType.ROUND_HOLE, hole.type());
        assertEquals("HOLE1", hole.id());
        near(new Vec3(25.4, 50.8, 0), hole.location());
        assertEquals(12.7, hole.depthMm().getAsDouble(), EPS);
        assertEquals(6.35, hole.diameterMm().getAsDouble(), EPS);
        assertEquals("FLAT_HOLE_BOTTOM", hole.bottomCondition().orElseThrow());
        near(new Vec3(0, 0, 25.4), drill.securityPlane().orElseThrow().translationPart());
        Operation op = drill.operation();
        assertEquals(Operation.OperationType.DRILLING, op.type());
        assertEquals(10.16, op.retractPlaneMm().getAsDouble(), EPS);
        assertEquals(6.35, op.tool().orElseThrow().diameterMm().getAsDouble(), EPS);
        assertEquals(118, op.tool().orElseThrow().topAngle().getAsDouble(), 1e-6);
        // 5 inch/minute = 127 mm/min; 1200 revolutions/minute
        assertEquals(127, op.technology().feedMmPerMin().getAsDouble(), 1e-9);
        assertEquals("inch/minute", op.technology().feedrateUnit());
        assertEquals(1200, op.technology().spindleRpm().getAsDouble(), 1e-9);

        MachiningWorkingstep rough = p.workingsteps().get(1);
        Feature pocket = rough.feature();
        assertEquals(Feature.FeatureType.CLOSED_POCKET, pocket.type());
        near(new Vec3(76.2, 25.4, 0), pocket.location());
        assertEquals(12.7, pocket.depthMm().getAsDouble(), EPS);
        assertEquals(7.62, pocket.orthogonalRadiusMm().getAsDouble(), EPS);
        Profile.General g = (Profile.General) pocket.profile().orElseThrow();
        assertTrue(g.closed());
        assertEquals(4, g.segments().size());
        near(new Vec3(-25.4, -19.05, 0), g.segments().get(0).start());
        near(new Vec3(25.4, -19.05, 0), g.segments().get(0).end());
        Operation mill = rough.operation();
        assertEquals(Operation.OperationType.BOTTOM_AND_SIDE_ROUGH_MILLING, mill.type());
        assertEquals(6.35, mill.axialCuttingDepthMm().getAsDouble(), EPS);
        assertEquals(
                Strategy.StrategyType.CONTOUR_PARALLEL,
                mill.strategy().orElseThrow().type());
        assertEquals("CW", mill.strategy().orElseThrow().rotationDirection().orElseThrow());
        assertEquals(
                ApproachRetract.Kind.PLUNGE_RAMP, mill.approach().orElseThrow().kind());
        assertEquals(10, mill.approach().orElseThrow().angle().getAsDouble(), 1e-9);
        assertEquals(12.7, mill.tool().orElseThrow().diameterMm().getAsDouble(), EPS);
        assertEquals(4, mill.tool().orElseThrow().teeth().getAsInt());
        assertTrue(
                p.spellings().stream().anyMatch(s -> s.contains("lengths in INCH (25.4 mm), converted to mm")),
                p.spellings().toString());
    }

    @Test
    void theSameFileInMillimetresKeepsItsNumbers() throws Exception {
        StepNcProgram p = inMillimetres();
        Feature hole = p.workingsteps().get(0).feature();
        near(new Vec3(1, 2, 0), hole.location());
        assertEquals(0.5, hole.depthMm().getAsDouble(), EPS);
        assertEquals(0.25, hole.diameterMm().getAsDouble(), EPS);
        // 5 mm/minute: kept, and reported as too slow to cut
        assertEquals(
                5,
                p.workingsteps().get(0).operation().technology().feedMmPerMin().getAsDouble(),
                1e-9);
        assertTrue(
                p.warnings().stream().anyMatch(w -> w.contains("too slow to cut")),
                p.warnings().toString());
        assertFalse(
                p.spellings().stream().anyMatch(s -> s.startsWith("lengths in")),
                p.spellings().toString());
    }

    @Test
    void aWorkingstepOutsideEverySequenceIsNamedWithThatReason() throws Exception {
        String text =
                Files.readString(INCH).replace("#304=MACHINING_PROCESS_SEQUENCE_RELATIONSHIP('','',#300,#400,1.);", "");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "t.stp");
        assertEquals(1, p.workingsteps().size());
        assertEquals(1, p.skipped().size());
        assertEquals("WS DRILL HOLE1", p.skipped().get(0).id());
        assertTrue(
                p.skipped().get(0).reason().contains("in no workplan's sequence"),
                p.skipped().get(0).reason());
    }

    @Test
    void anOperationTheBindingDoesNotKnowIsKeptWithItsNameForThePlannerToRefuse() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#420=DRILLING_OPERATION('DRILL HOLE1','drilling','','');",
                        "#420=FACING_TURNING_OPERATION('FACE','roughing','','');");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "t.stp");
        Operation op = p.workingsteps().get(0).operation();
        assertEquals(Operation.OperationType.OTHER, op.type());
        assertTrue(op.entity().startsWith("FACING_TURNING_OPERATION"), op.entity());
    }

    @Test
    void explicitToolpathsAreReadInSequenceWithTheirArcsTraversedAsTheFileSays() throws Exception {
        StepNcProgram p = StepNcReader.read(Path.of("src/test/resources/stepnc/aim-cc1-toolpaths.stp"));
        MachiningWorkingstep ws = p.workingsteps().get(0);
        assertEquals("TOOLPATH_FEATURE", ws.feature().entity());
        Operation op = ws.operation();
        assertEquals(Operation.OperationType.FREEFORM_OPERATION, op.type());
        assertEquals(
                List.of("TP 1", "TP 2", "TP 3"),
                op.toolpaths().stream().map(ExplicitToolpath::id).toList());
        assertEquals(
                List.of(true, false, true),
                op.toolpaths().stream().map(ExplicitToolpath::rapid).toList());
        assertEquals(300, op.technology().feedMmPerMin().getAsDouble(), 1e-9);
        assertEquals(1200, op.technology().spindleRpm().getAsDouble(), 1e-9);
        List<Profile.Segment> cut = op.toolpaths().get(1).curve();
        assertEquals(5, cut.size());
        // sense_agreement .T.: along the circle (counter-clockwise); .F.: against it (clockwise)
        Profile.Arc ccw = (Profile.Arc) cut.get(2);
        near(new Vec3(30, 0, -1), ccw.start());
        near(new Vec3(40, 10, -1), ccw.end());
        assertTrue(ccw.ccw());
        Profile.Arc cw = (Profile.Arc) cut.get(3);
        near(new Vec3(40, 10, -1), cw.start());
        near(new Vec3(50, 20, -1), cw.end());
        near(new Vec3(50, 10, -1), cw.center());
        assertFalse(cw.ccw());
        // a segment whose same_sense is .F. is traversed from its curve's end
        near(new Vec3(50, 20, -1), cut.get(4).start());
        near(new Vec3(60, 20, -1), cut.get(4).end());
    }
}
