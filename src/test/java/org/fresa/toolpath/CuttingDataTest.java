package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.DrillingParameters;
import org.fresa.stepnc.DrillingStrategy;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.StepNcReader;
import org.fresa.stepnc.Technology;
import org.junit.jupiter.api.Test;

/**
 * Technology from the file, checked: src/test/resources/org/fresa/toolpath/technology.stp
 * drills one Ø6 blind hole five times, each workingstep with its own MILLING_TECHNOLOGY in ISO
 * 14649-10 units (cutting speed m/s, spindle rev/s, feed m/s).
 */
class CuttingDataTest {

    static final Path TECHNOLOGY = Path.of("src/test/resources/org/fresa/toolpath/technology.stp");
    static final double EPS = 1e-9;

    static ToolpathPlanner.Plan plan(boolean trust) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(TECHNOLOGY), Tolerance.DEFAULT, new PlanningChoices(trust, 1));
    }

    static Optional<ToolpathSection> section(ToolpathPlanner.Plan p, String workingstep) {
        return p.toolpath().sections().stream()
                .filter(x -> x.label().equals(workingstep))
                .findFirst();
    }

    @Test
    void aWorkingstepWithoutSpindleSpeedTakesItFromTheCuttingSpeedAndSaysSo() throws Exception {
        ToolpathPlanner.Plan p = plan(false);
        // 1.8 m/s = 108 m/min on a Ø6 drill: n = 1000 v / (pi D)
        assertAll(
                () -> assertEquals(
                        1000 * 108 / (Math.PI * 6),
                        section(p, "WS SPEED FROM CUTTING SPEED").orElseThrow().spindleRpm(),
                        EPS),
                () -> assertTrue(
                        p.problems()
                                .contains("workingstep 'WS SPEED FROM CUTTING SPEED': no spindle speed in"
                                        + " the file: 5729.578 rpm from the cutting speed 1.8 m/s for the 6 mm tool"
                                        + " (n = 1000 v / (pi D))"),
                        p.problems().toString()));
    }

    @Test
    void aWorkingstepWithNeitherSpindleNorCuttingSpeedIsRefusedWithItsName() throws Exception {
        ToolpathPlanner.Plan p = plan(false);
        assertAll(
                () -> assertTrue(section(p, "WS NO SPEED").isEmpty()),
                () -> assertTrue(
                        p.problems()
                                .contains("workingstep 'WS NO SPEED' (#11): no spindle speed and no"
                                        + " cutting speed in the file (MILLING_TECHNOLOGY #52): the tool would cut with the spindle"
                                        + " stopped"),
                        p.problems().toString()));
    }

    @Test
    void aSpindleAHundredTimesBelowItsCuttingSpeedIsRefusedWithBothValues() throws Exception {
        ToolpathPlanner.Plan p = plan(false);
        assertAll(
                () -> assertTrue(section(p, "WS SPINDLE 100 TIMES TOO SLOW").isEmpty()),
                () -> assertTrue(
                        p.problems()
                                .contains("workingstep 'WS SPINDLE 100 TIMES TOO SLOW' (#12): spindle"
                                        + " 5.84 rpm and cutting speed 0.1835 m/s (584.0986 rpm for the 6 mm tool) disagree by a"
                                        + " factor of 100; correct the file, or plan from the cutting speed with"
                                        + " --trust-cutting-speed"),
                        p.problems().toString()));
    }

    @Test
    void trustingTheCuttingSpeedPlansTheDisagreeingWorkingstepFromIt() throws Exception {
        ToolpathPlanner.Plan p = plan(true);
        assertAll(
                () -> assertEquals(
                        1000 * 0.1835 * 60 / (Math.PI * 6),
                        section(p, "WS SPINDLE 100 TIMES TOO SLOW")
                                .orElseThrow()
                                .spindleRpm(),
                        EPS),
                () -> assertTrue(
                        p.problems()
                                .contains(
                                        "workingstep 'WS SPINDLE 100 TIMES TOO SLOW': spindle 5.84 rpm"
                                                + " and cutting speed 0.1835 m/s (584.0986 rpm for the 6 mm tool) disagree by a factor of"
                                                + " 100: planned at 584.0986 rpm from the cutting speed (--trust-cutting-speed)"),
                        p.problems().toString()),
                () -> assertEquals(3, p.planned()));
    }

    @Test
    void aWorkingstepWithoutFeedIsRefusedNotGivenADefault() throws Exception {
        ToolpathPlanner.Plan p = plan(true);
        assertAll(
                () -> assertTrue(section(p, "WS NO FEED").isEmpty()),
                () -> assertTrue(
                        p.problems()
                                .contains("workingstep 'WS NO FEED' (#13): no feed in the file"
                                        + " (MILLING_TECHNOLOGY #54: feedrate unset, no feed_per_tooth with a tooth count): no feed is"
                                        + " guessed"),
                        p.problems().toString()));
    }

    @Test
    void aSpindleWithinTenTimesOfItsCuttingSpeedIsTheFilesSpindle() throws Exception {
        ToolpathPlanner.Plan p = plan(false);
        String name = "WS SPINDLE AND CUTTING SPEED AGREE";
        assertAll(
                () -> assertEquals(80 * 60, section(p, name).orElseThrow().spindleRpm(), EPS),
                () -> assertTrue(
                        p.problems().stream().noneMatch(q -> q.contains(name)),
                        p.problems().toString()),
                () -> assertEquals(2, p.planned()),
                () -> assertEquals(5, p.workingsteps()));
    }

    /**
     * STEP Modeler's units (spindle rpm, cutting speed m/min, feed without unit): a Ø10 drill with
     * cutting speed 110 m/min and spindle unset turns at 3501.4087 rpm, and its feed 0.245 mm/rev
     * is converted at that speed, not left to a default.
     */
    @Test
    void aChipLoadIsConvertedAtTheSpindleSpeedTakenFromTheCuttingSpeed() {
        Technology stepModeler = new Technology(
                7,
                OptionalDouble.of(0.245),
                "unstated",
                Optional.empty(),
                OptionalDouble.of(110),
                "m/min",
                OptionalDouble.empty(),
                "rpm",
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                false);
        Operation op = drillingWith(stepModeler);
        CuttingData c = CuttingData.of(op, 10, false);
        double n = 1000 * 110 / (Math.PI * 10);
        assertAll(
                () -> assertEquals(n, c.spindleRpm(), EPS),
                () -> assertTrue(c.fromCuttingSpeed()),
                () -> assertEquals(0.245 * n, c.feed().feedMmPerMin(), EPS),
                () -> assertEquals("mm/rev", c.feed().readAs()),
                () -> assertEquals(
                        List.of("no spindle speed in the file: 3501.4087 rpm from the cutting speed 110 m/min"
                                + " for the 10 mm tool (n = 1000 v / (pi D))"),
                        c.notes()));
    }

    /**
     * STEP Tools' AIM rendering of ISO 14649-11's example (annex J.6) declares its feeds in mm/s
     * and keeps the example's figures: a Ø20 drill at 960 rpm fed 0.03 mm/s, 1.8 mm/min, is
     * 0.0019 mm a revolution. It is planned as written, and the planner is told.
     */
    @Test
    void aFeedTooSlowForTheCutterToFormAChipIsSaidWithItsFigures() {
        Technology aim = new Technology(
                3500,
                OptionalDouble.of(0.03),
                "millimetre/second",
                Optional.empty(),
                OptionalDouble.empty(),
                "unstated",
                OptionalDouble.of(960),
                "rpm",
                OptionalDouble.empty(),
                OptionalDouble.of(1.8),
                OptionalDouble.of(960),
                false);
        CuttingData c = CuttingData.of(drillingWith(aim), 20, false);
        assertAll(
                () -> assertEquals(1.8, c.feed().feedMmPerMin(), EPS),
                () -> assertEquals(
                        List.of("feed 0.03 millimetre/second = 1.8 mm/min at 960 rpm: 0.0019 mm per revolution,"
                                + " less than a 20 mm cutter forms a chip with (0.02); planned as written: check the"
                                + " file's feed and its unit"),
                        c.notes()));
        // the same drill fed 0.2 mm a revolution (192 mm/min) is a handbook feed: nothing to say
        Technology handbook = new Technology(
                3500,
                OptionalDouble.of(3.2),
                "millimetre/second",
                Optional.empty(),
                OptionalDouble.empty(),
                "unstated",
                OptionalDouble.of(960),
                "rpm",
                OptionalDouble.empty(),
                OptionalDouble.of(192),
                OptionalDouble.of(960),
                false);
        assertEquals(
                List.of(), CuttingData.of(drillingWith(handbook), 20, false).notes());
    }

    private static Operation drillingWith(Technology t) {
        Operation base = DrillCycleTest.op(
                Operation.OperationType.DRILLING,
                DrillCycleTest.drill(0.54, "rad"),
                DrillingStrategy.NONE,
                DrillingParameters.NONE);
        return new Operation(
                base.instanceId(),
                base.type(),
                base.entity(),
                base.id(),
                base.retractPlaneMm(),
                base.startPoint(),
                base.tool(),
                t,
                base.strategy(),
                base.approach(),
                base.retract(),
                base.axialCuttingDepthMm(),
                base.radialCuttingDepthMm(),
                base.allowanceSideMm(),
                base.allowanceBottomMm(),
                base.cuttingDepthMm(),
                base.overcutLengthMm(),
                base.drilling(),
                List.of());
    }

    @Test
    void everyPlannedWorkingstepHasASpindleSpeed() throws Exception {
        for (boolean trust : List.of(false, true)) {
            ToolpathPlanner.Plan p = plan(trust);
            assertTrue(
                    p.toolpath().sections().stream().allMatch(s -> s.spindleRpm() > 0),
                    p.toolpath().toString());
        }
    }
}
