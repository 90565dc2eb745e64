package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.fresa.geom.Tolerance;
import org.fresa.post.NcPosts;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The closed pocket with a round and a rectangular boss of steps-outside-profiles.stp written in
 * AP238's integrated form (aim-bosses.stp: the bosses related to the pocket's 'uncut volume', ISO
 * 10303-113 pocket WR16): the AIM binder gives the ARM binder's its_boss and the planner leaves
 * them standing alike; a boss the binder cannot read keeps the pocket refused, naming why.
 */
class AimBossesTest {

    static final Path AIM = Path.of("src/test/resources/stepnc/aim-bosses.stp");
    static final Path ARM = Path.of("src/test/resources/stepnc/steps-outside-profiles.stp");
    static final String WS = "WS POCKET WITH BOSSES";

    private static MachiningWorkingstep armPocket(StepNcProgram arm) {
        return arm.workingsteps().stream()
                .filter(w -> w.id().equals(WS))
                .findFirst()
                .orElseThrow();
    }

    @Test
    void theAimBossesAreTheArmsBosses() throws Exception {
        StepNcProgram aim = StepNcReader.read(AIM);
        assertEquals(
                List.of(WS),
                aim.workingsteps().stream().map(MachiningWorkingstep::id).toList());
        Feature a = aim.workingsteps().get(0).feature();
        Feature r = armPocket(StepNcReader.read(ARM)).feature();
        assertEquals(Feature.FeatureType.CLOSED_POCKET, a.type());
        assertEquals(r.id(), a.id());
        assertTrue(r.placement().eq(a.placement(), Tolerance.DEFAULT));
        assertEquals(r.depthMm(), a.depthMm());
        assertEquals(AimSlotsTest.rounded(r.profile()), AimSlotsTest.rounded(a.profile()));
        assertEquals(r.orthogonalRadiusMm(), a.orthogonalRadiusMm());
        assertEquals(r.planarRadiusMm(), a.planarRadiusMm());
        assertEquals(r.bottomCondition(), a.bottomCondition());
        assertEquals(2, r.bosses().size());
        assertEquals(
                r.bosses().stream().map(Feature::id).toList(),
                a.bosses().stream().map(Feature::id).toList());
        for (int i = 0; i < r.bosses().size(); i++) {
            Feature rb = r.bosses().get(i);
            Feature ab = a.bosses().get(i);
            String at = rb.id();
            assertEquals(Feature.FeatureType.BOSS, ab.type(), at);
            assertEquals(rb.entity(), ab.entity(), at);
            assertTrue(rb.placement().eq(ab.placement(), Tolerance.DEFAULT), at);
            assertEquals(rb.depthMm(), ab.depthMm(), at);
            assertTrue(rb.depthPlane().orElseThrow().eq(ab.depthPlane().orElseThrow(), Tolerance.DEFAULT), at);
            assertEquals(AimSlotsTest.rounded(rb.profile()), AimSlotsTest.rounded(ab.profile()), at);
            assertTrue(ab.bosses().isEmpty() && ab.courseOfTravel().isEmpty(), at);
        }
        // one round, one rectangular: both kinds of boundary the ARM part has
        assertTrue(a.bosses().get(0).profile().orElseThrow() instanceof org.fresa.stepnc.Profile.Circular);
        assertTrue(a.bosses().get(1).profile().orElseThrow() instanceof org.fresa.stepnc.Profile.Rectangular);
    }

    /** As the J.6-against-FDIS comparison: the pocket planned round its bosses, point for point within 1e-6 mm. */
    @Test
    void theAimPocketIsMachinedRoundItsBossesAsTheArmFilesPocket() throws Exception {
        ToolpathPlanner.Plan aim = ToolpathPlanner.plan(StepNcReader.read(AIM), Tolerance.DEFAULT);
        ToolpathPlanner.Plan arm = ToolpathPlanner.plan(StepNcReader.read(ARM), Tolerance.DEFAULT);
        assertEquals(1, aim.planned(), aim.problems().toString());
        assertEquals(
                arm.problems().stream().filter(x -> x.contains("'" + WS + "'")).toList(), aim.problems());
        List<ToolpathCsv.Row> a = ToolpathCsv.rows(aim.toolpath(), NcPosts.CHORD_TOLERANCE_MM);
        List<ToolpathCsv.Row> r = ToolpathCsv.rows(arm.toolpath(), NcPosts.CHORD_TOLERANCE_MM).stream()
                .filter(x -> x.workingstep().equals(WS))
                .toList();
        assertTrue(r.size() > 100, "rows " + r.size());
        assertEquals(r.size(), a.size());
        for (int i = 0; i < r.size(); i++) {
            ToolpathCsv.Row x = r.get(i);
            ToolpathCsv.Row y = a.get(i);
            assertEquals(x.workingstep() + " " + x.move(), y.workingstep() + " " + y.move(), "row " + i);
            assertTrue(x.point().distance(y.point()) <= 1e-6, "row " + i + ": " + x + " vs " + y);
            assertTrue(x.toolAxis().distance(y.toolAxis()) <= 1e-6, "row " + i);
            assertEquals(x.feedMmPerMin(), y.feedMmPerMin(), 1e-9, "row " + i);
        }
    }

    /** Without its bosses the same pocket is cleared where they stand: the comparison above can fail. */
    @Test
    void withoutItsUncutVolumeThePocketIsClearedWhereTheBossesStand() throws Exception {
        String text = Files.readString(AIM);
        String from = "#104=COMPOSITE_SHAPE_ASPECT('uncut volume','',#71,.F.);";
        assertTrue(text.contains(from));
        StepNcProgram p = StepNcReader.read(
                new StringReader(text.replace(from, "#104=COMPOSITE_SHAPE_ASPECT('','',#71,.F.);")), "none.stp");
        assertTrue(p.workingsteps().get(0).feature().bosses().isEmpty());
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        // the tool's centre passes within its radius of the round boss's centre (45, 120): through it
        boolean through = ToolpathCsv.rows(plan.toolpath(), NcPosts.CHORD_TOLERANCE_MM).stream()
                .anyMatch(x -> x.point().z() < -1
                        && Math.hypot(x.point().x() - 45, x.point().y() - 120) < 6 + 3);
        assertTrue(through);
        boolean round = ToolpathCsv.rows(
                        ToolpathPlanner.plan(StepNcReader.read(AIM), Tolerance.DEFAULT)
                                .toolpath(),
                        NcPosts.CHORD_TOLERANCE_MM)
                .stream()
                .anyMatch(x -> x.point().z() < -1
                        && Math.hypot(x.point().x() - 45, x.point().y() - 120) < 6 + 3 - 1e-3);
        assertFalse(round);
    }

    private static final String END = "ENDSEC;\nEND-ISO-10303-21;";

    static Stream<Arguments> unreadBosses() {
        return Stream.of(
                // boss WR1: the description names the boundary
                Arguments.of(
                        "CHARACTERIZED_OBJECT('','circular')",
                        "CHARACTERIZED_OBJECT('','conical')",
                        "",
                        "'ROUND BOSS' described 'conical'"),
                // boss WR4, WR5: a fillet at its foot, which ISO 14649-10's boss has not
                Arguments.of(
                        "#114=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#113),#7);",
                        "#114=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#113,#9000),#7);",
                        "#9000=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(1.0),#1) REPRESENTATION_ITEM('fillet radius'));\n",
                        "'ROUND BOSS' has 'fillet radius' 1 mm"),
                // boss WR2: its height
                Arguments.of(
                        "#127=SHAPE_DEFINING_RELATIONSHIP('boss height'",
                        "#127=SHAPE_DEFINING_RELATIONSHIP('height'",
                        "",
                        "'ROUND BOSS' has 0 'boss height's"),
                Arguments.of(
                        "#119=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(6.0),#1) REPRESENTATION_ITEM('distance'));",
                        "#119=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(6.0),#1) REPRESENTATION_ITEM('length'));",
                        "",
                        "'ROUND BOSS' has a 'boss height' without a positive 'distance'"),
                // boss WR12: its maximum feature limit, where given, is its height
                Arguments.of(
                        "#116=SHAPE_REPRESENTATION('maximum feature limit',(#79),#7);",
                        "#116=SHAPE_REPRESENTATION('maximum feature limit',(#9000),#7);",
                        "#9000=PLANE('',#9001);\n#9001=AXIS2_PLACEMENT_3D('',#9002,#18,#19);\n"
                                + "#9002=CARTESIAN_POINT('',(0.0,0.0,-4.0));\n",
                        "'ROUND BOSS' is 6 mm high and its maximum feature limit 4 mm below its top"),
                // boss WR6: the profile its description names, read whole
                Arguments.of(
                        "#129=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(12.0),#1) REPRESENTATION_ITEM('diameter'));",
                        "#129=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(12.0),#1) REPRESENTATION_ITEM('radius'));",
                        "",
                        "'ROUND BOSS' is bounded by a CIRCULAR_CLOSED_PROFILE with 'radius'"),
                Arguments.of(
                        "#133=SHAPE_ASPECT('','circular profile occurrence'",
                        "#133=SHAPE_ASPECT('','enclosed boundary occurrence'",
                        "",
                        "'ROUND BOSS' (circular) has 0 CIRCULAR_CLOSED_PROFILEs"),
                // a rectangle's corner radius, which ISO 14649-10's rectangle has not
                Arguments.of(
                        "#172=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#153,#169,#170),#7);",
                        "#172=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#153,#169,#170,#9000),#7);",
                        "#9000=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(2.0),#1) REPRESENTATION_ITEM('corner radius'));\n",
                        "'SQUARE BOSS' is bounded by a RECTANGULAR_CLOSED_PROFILE with 'corner radius'"),
                // boss WR7, boss_top: its top, at its placement
                Arguments.of(
                        "#137=LOCATION_SHAPE_REPRESENTATION('',(#112),#7);",
                        "#137=LOCATION_SHAPE_REPRESENTATION('',(#9000),#7);",
                        "#9000=CARTESIAN_POINT('',(45.0,120.0,-2.0));\n",
                        "'ROUND BOSS''s top is -2 mm from its placement"),
                Arguments.of(
                        "#142=FEATURE_COMPONENT_RELATIONSHIP('boss height start','boss top usage',#135,#141);",
                        "",
                        "",
                        "'ROUND BOSS' has 0 BOSS_TOPs"),
                Arguments.of("#135=BOSS_TOP('','planar'", "#135=BOSS_TOP('','complex'", "", "a 'complex' top"),
                // a taper (boss WR10), which ISO 14649-10's boss leaves to its slope
                Arguments.of(
                        END,
                        END,
                        "#9000=SHAPE_ASPECT('','change in boundary occurrence',#151,.F.);\n"
                                + "#9001=TAPER('','angle taper',#53,.F.);\n"
                                + "#9002=FEATURE_COMPONENT_RELATIONSHIP('','taper usage',#9000,#9001);\n",
                        "'SQUARE BOSS' has a 'change in boundary occurrence' (a taper"),
                // pocket WR16: an uncut volume's other shape, or none
                Arguments.of(
                        "#110=(BOSS() CHARACTERIZED_OBJECT",
                        "#110=(PROTRUSION() CHARACTERIZED_OBJECT",
                        "",
                        "PROTRUSION #110 (a PROTRUSION, whose shape the binder does not read)"),
                Arguments.of(
                        "#105=FEATURE_COMPONENT_RELATIONSHIP('ROUND BOSS','boss usage',#104,#110);\n"
                                + "#106=FEATURE_COMPONENT_RELATIONSHIP('SQUARE BOSS','boss usage',#104,#150);",
                        "",
                        "",
                        "an 'uncut volume' relating no BOSS"));
    }

    /** A boss the binder cannot read leaves the pocket refused, naming why, never milled through it. */
    @ParameterizedTest
    @MethodSource("unreadBosses")
    void aBossTheBinderCannotReadKeepsThePocketRefused(String from, String to, String added, String expected)
            throws Exception {
        String text = Files.readString(AIM);
        assertTrue(text.contains(from), from);
        String changed = text.replace(from, to).replace(END, added + END);
        StepNcProgram p = StepNcReader.read(new StringReader(changed), "changed.stp");
        Feature f = p.workingsteps().get(0).feature();
        assertTrue(f.bosses().isEmpty());
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(0, plan.planned(), plan.problems().toString());
        long ws = p.workingsteps().get(0).instanceId();
        assertTrue(plan.sectionOf(ws).isEmpty());
        String why = String.valueOf(plan.refusals().get(ws));
        assertTrue(why.contains("around an 'uncut volume' the AIM binder cannot read"), why);
        assertTrue(why.contains(expected), why);
        assertTrue(why.contains("milled without it, the boss would be cut away"), why);
    }
}
