package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.DrillingParameters;
import org.fresa.stepnc.DrillingStrategy;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Operation.OperationType;
import org.fresa.stepnc.Strategy;
import org.fresa.stepnc.Technology;
import org.fresa.stepnc.Tool;
import org.junit.jupiter.api.Test;

/** The moves of drilling, center drilling, multistep drilling, reaming and boring. */
class DrillCycleTest {

    static final double EPS = 1e-9;
    static final Tooling D10 = new Tooling(1, 10, 1000, 600, 600);
    static final Heights H = new Heights(20, 5, 0, -25);

    /**
     * Each move along the axis as "R z" (rapid), "F z @feed", "D s" (dwell), "M5" or "M3 rpm"
     * (spindle events, where the tool is).
     */
    static List<String> moves(ToolpathSection s) {
        List<String> out = new ArrayList<>();
        for (Move m : s.moves()) {
            double z = Math.round(m.end().z() * 1e6) / 1e6;
            if (m instanceof Move.Linear l) {
                out.add("F " + z + " @" + Math.round(l.feedMmPerMin() * 1e6) / 1e6);
            } else if (m instanceof Move.Rapid) {
                out.add("R " + z);
            } else if (m instanceof Move.Dwell d) {
                out.add("D " + d.seconds());
            } else if (m instanceof Move.SpindleStop) {
                out.add("M5");
            } else if (m instanceof Move.SpindleStart on) {
                out.add((on.clockwise() ? "M3 " : "M4 ") + on.rpm());
            } else {
                throw new AssertionError(m);
            }
        }
        return out;
    }

    static Tool drill(double topAngle, String unit) {
        return new Tool(
                1,
                "drill",
                "TWIST_DRILL",
                "MILLING_TOOL_DIMENSION",
                OptionalDouble.of(10),
                OptionalDouble.of(topAngle),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalInt.empty(),
                Optional.empty(),
                OptionalDouble.empty(),
                unit);
    }

    static Operation op(OperationType type, Tool tool, DrillingStrategy s, DrillingParameters p) {
        Strategy st = new Strategy(
                2,
                Strategy.StrategyType.DRILLING_TYPE_STRATEGY,
                "DRILLING_TYPE_STRATEGY",
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.of(s));
        return new Operation(
                3,
                type,
                type.name(),
                "",
                OptionalDouble.of(5),
                Optional.empty(),
                Optional.of(tool),
                Technology.NONE,
                Optional.of(st),
                Optional.empty(),
                Optional.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.of(p),
                List.of());
    }

    static DrillingStrategy reductions(double feedStart, double depthStart, double feedEnd, double depthEnd) {
        return new DrillingStrategy(
                OptionalDouble.empty(),
                OptionalDouble.of(feedStart),
                OptionalDouble.of(depthStart),
                OptionalDouble.empty(),
                OptionalDouble.of(feedEnd),
                OptionalDouble.of(depthEnd));
    }

    @Test
    void drillingFeedsSlowerOverTheStartAndEndDepthsAndLeavesAtRapid() {
        Tool t = drill(31, "deg");
        double tip = ToolpathPlanner.tipLength(
                op(OperationType.DRILLING, t, DrillingStrategy.NONE, DrillingParameters.NONE), D10);
        assertEquals(5 * Math.tan(Math.toRadians(31)), tip, EPS);
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.DRILLING, t, reductions(0.5, 2, 0.25, 4), DrillingParameters.NONE), D10, tip);
        Heights through = new Heights(20, 5, 0, -25 - tip);
        double z1 = Math.round(-(2 + tip) * 1e6) / 1e6;
        double z2 = Math.round((-21 - tip) * 1e6) / 1e6;
        double z3 = Math.round((-25 - tip) * 1e6) / 1e6;
        assertEquals(
                List.of(
                        "R 5.0",
                        "F " + z1 + " @300.0",
                        "F " + z2 + " @600.0",
                        "F " + z3 + " @150.0",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, through, D10, c)));
    }

    @Test
    void overlappingZonesGiveTheEndFeedFromWhereTheEndZoneBegins() {
        DrillCycle c = new DrillCycle(0, 20, 0.5, 10, 0.25, 0, 0, 0, 0);
        assertEquals(
                List.of("R 5.0", "F -15.0 @300.0", "F -25.0 @150.0", "R 5.0", "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, H, D10, c)));
    }

    @Test
    void centerDrillingGoesToTheCuttingDepthWithoutAllowance() {
        Operation center = op(
                OperationType.CENTER_DRILLING,
                drill(0.5235987755982988, "rad"),
                DrillingStrategy.NONE,
                DrillingParameters.NONE);
        // STEP Modeler's center drill: 30 deg written in radians
        assertEquals(5 * Math.tan(Math.toRadians(30)), ToolpathPlanner.tipLength(center, D10), EPS);
        DrillCycle c = ToolpathPlanner.drillCycle(center, D10, ToolpathPlanner.tipLength(center, D10));
        assertEquals(
                List.of("R 5.0", "F -3.0 @600.0", "R 5.0", "R 20.0"),
                moves(HoleMaking.drill("c", Vec2.ZERO, new Heights(20, 5, 0, -3), D10, c)));
    }

    @Test
    void multistepDrillingStepsByFirstDepthAndDepthOfStepAndLiftsByTheRetractDistance() {
        DrillingParameters p = new DrillingParameters(
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.of(2),
                OptionalDouble.of(12),
                OptionalDouble.of(6),
                OptionalDouble.empty(),
                Optional.empty());
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.MULTISTEP_DRILLING, drill(31, "deg"), DrillingStrategy.NONE, p), D10, 0);
        assertAll(
                () -> assertEquals(12, c.firstPeck(), EPS),
                () -> assertEquals(6, c.peck(), EPS),
                () -> assertEquals(2, c.retractDistance(), EPS));
        assertEquals(
                List.of(
                        "R 5.0",
                        "F -12.0 @600.0",
                        "R -10.0",
                        "R -11.0",
                        "F -18.0 @600.0",
                        "R -16.0",
                        "R -17.0",
                        "F -24.0 @600.0",
                        "R -22.0",
                        "R -23.0",
                        "F -25.0 @600.0",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("m", Vec2.ZERO, H, D10, c)));
    }

    @Test
    void multistepDrillingWithoutStepsPecksByOneDiameterBackToTheRetractHeight() {
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.MULTISTEP_DRILLING, drill(31, "deg"), DrillingStrategy.NONE, DrillingParameters.NONE),
                D10,
                0);
        assertEquals(
                List.of(
                        "R 5.0",
                        "F -10.0 @600.0",
                        "R 5.0",
                        "R -9.0",
                        "F -20.0 @600.0",
                        "R 5.0",
                        "R -19.0",
                        "F -25.0 @600.0",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("m", Vec2.ZERO, H, D10, c)));
    }

    @Test
    void reamingHasNoPointAndLeavesAtTheFeed() {
        Operation ream = op(OperationType.REAMING, drill(31, "deg"), DrillingStrategy.NONE, DrillingParameters.NONE);
        assertEquals(0, ToolpathPlanner.tipLength(ream, D10));
        assertEquals(
                List.of("R 5.0", "F -25.0 @600.0", "F 5.0 @600.0", "R 20.0"),
                moves(HoleMaking.drill("r", Vec2.ZERO, H, D10, ToolpathPlanner.drillCycle(ream, D10, 0))));
    }

    /** Also: dwell_time_bottom and spindle_stop_at_bottom (the spindle starts again out of the hole). */
    @Test
    void boringLeavesAtFeedOnRetractWhenTheFileGivesIt() {
        DrillingParameters p = new DrillingParameters(
                OptionalDouble.of(1.5),
                OptionalDouble.of(0.5),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.of(true));
        Operation bore = op(OperationType.BORING, drill(31, "deg"), reductions(0.5, 3, 1, 0), p);
        assertEquals(
                List.of(
                        "R 5.0",
                        "F -3.0 @300.0",
                        "F -25.0 @600.0",
                        "D 1.5",
                        "M5",
                        "F 5.0 @300.0",
                        "M3 1000.0",
                        "R 20.0"),
                moves(HoleMaking.drill("b", Vec2.ZERO, H, D10, ToolpathPlanner.drillCycle(bore, D10, 0))));
        Operation plain = op(OperationType.BORING, drill(31, "deg"), DrillingStrategy.NONE, DrillingParameters.NONE);
        assertEquals(
                List.of("R 5.0", "F -25.0 @600.0", "F 5.0 @600.0", "R 20.0"),
                moves(HoleMaking.drill("b", Vec2.ZERO, H, D10, ToolpathPlanner.drillCycle(plain, D10, 0))));
    }

    @Test
    void spindleReductionsAndWhatTheMovesCannotHonourAreNamedAsNotInTheMoves() {
        DrillingParameters p = new DrillingParameters(
                OptionalDouble.of(1.5),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.of(0.5),
                Optional.of(true));
        DrillingStrategy s = new DrillingStrategy(
                OptionalDouble.of(0.75),
                OptionalDouble.of(0.5),
                OptionalDouble.of(2),
                OptionalDouble.of(0.5),
                OptionalDouble.of(0.75),
                OptionalDouble.of(8));
        // boring has no steps to dwell at; without a spindle speed there is none to reduce or start again at
        assertEquals(
                List.of(
                        "reduced_cut_at_start 0.75 (no spindle speed)",
                        "reduced_cut_at_end 0.5 (no spindle speed)",
                        "dwell_time_step 0.5 s (no steps)",
                        "spindle_stop_at_bottom (no spindle speed to start again at)"),
                ToolpathPlanner.notInTheMoves(op(OperationType.BORING, drill(31, "deg"), s, p)));
        DrillingParameters dwells = new DrillingParameters(
                OptionalDouble.of(1.5),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.of(0.5),
                Optional.empty());
        assertEquals(
                List.of(),
                ToolpathPlanner.notInTheMoves(
                        op(OperationType.MULTISTEP_DRILLING, drill(31, "deg"), DrillingStrategy.NONE, dwells)));
        assertEquals(
                List.of(),
                ToolpathPlanner.notInTheMoves(op(
                        OperationType.DRILLING,
                        drill(31, "deg"),
                        reductions(0.5, 2, 0.75, 8),
                        DrillingParameters.NONE)));
    }

    static DrillingParameters dwells(double bottomS, double stepS, double firstMm, double stepMm, double retractMm) {
        return new DrillingParameters(
                OptionalDouble.of(bottomS),
                OptionalDouble.empty(),
                OptionalDouble.of(retractMm),
                OptionalDouble.of(firstMm),
                OptionalDouble.of(stepMm),
                OptionalDouble.of(stepS),
                Optional.empty());
    }

    @Test
    void drillingDwellsAtTheBottomForDwellTimeBottom() {
        DrillingParameters p = new DrillingParameters(
                OptionalDouble.of(2),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty());
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.DRILLING, drill(31, "deg"), DrillingStrategy.NONE, p), D10, 0);
        assertEquals(
                List.of("R 5.0", "F -25.0 @600.0", "D 2.0", "R 5.0", "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, H, D10, c)));
        ToolpathSection s = HoleMaking.drill("d", Vec2.ZERO, H, D10, c);
        Move.Dwell d = (Move.Dwell) s.moves().get(2);
        assertEquals(new org.fresa.geom.Vec3(0, 0, -25), d.end(), "the dwell is where the tool is");
    }

    @Test
    void multistepDrillingDwellsAtEachStepAndTheBottomsTimeAtTheLast() {
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(
                        OperationType.MULTISTEP_DRILLING,
                        drill(31, "deg"),
                        DrillingStrategy.NONE,
                        dwells(1.5, 0.5, 12, 6, 2)),
                D10,
                0);
        assertAll(() -> assertEquals(1.5, c.dwellBottomS()), () -> assertEquals(0.5, c.dwellStepS()));
        assertEquals(
                List.of(
                        "R 5.0",
                        "F -12.0 @600.0",
                        "D 0.5",
                        "R -10.0",
                        "R -11.0",
                        "F -18.0 @600.0",
                        "D 0.5",
                        "R -16.0",
                        "R -17.0",
                        "F -24.0 @600.0",
                        "D 0.5",
                        "R -22.0",
                        "R -23.0",
                        "F -25.0 @600.0",
                        "D 1.5",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("m", Vec2.ZERO, H, D10, c)));
    }

    @Test
    void aDwellTimeStepOutsideMultistepDrillingAndZeroDwellsGiveNoDwell() {
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.DRILLING, drill(31, "deg"), DrillingStrategy.NONE, dwells(0, 0.5, 12, 6, 2)), D10, 0);
        assertAll(() -> assertEquals(0, c.dwellStepS()), () -> assertEquals(0, c.dwellBottomS()));
        assertEquals(
                List.of("R 5.0", "F -25.0 @600.0", "R 5.0", "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, H, D10, c)));
    }

    @Test
    void reducedCutAtStartAndEndChangeTheSpindleSpeedWhereTheirZonesBegin() {
        DrillingStrategy s = new DrillingStrategy(
                OptionalDouble.of(0.75),
                OptionalDouble.of(0.5),
                OptionalDouble.of(2),
                OptionalDouble.of(0.5),
                OptionalDouble.empty(),
                OptionalDouble.of(4));
        DrillCycle c = ToolpathPlanner.drillCycle(
                op(OperationType.DRILLING, drill(31, "deg"), s, DrillingParameters.NONE), D10, 0);
        // the end zone reduces the speed only: the feed is split there all the same
        assertEquals(
                List.of(
                        "R 5.0",
                        "M3 750.0",
                        "F -2.0 @300.0",
                        "M3 1000.0",
                        "F -21.0 @600.0",
                        "M3 500.0",
                        "F -25.0 @600.0",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, H, D10, c)));
        // pecks come back into the zone at the speed they left it
        DrillCycle pecks = new DrillCycle(0, 2, 1, 4, 1, 12, 12, 0, 0).withSpeedFactors(0.75, 0.5);
        assertEquals(
                List.of(
                        "R 5.0",
                        "M3 750.0",
                        "F -2.0 @600.0",
                        "M3 1000.0",
                        "F -12.0 @600.0",
                        "R 5.0",
                        "R -11.0",
                        "F -21.0 @600.0",
                        "M3 500.0",
                        "F -24.0 @600.0",
                        "R 5.0",
                        "R -23.0",
                        "F -25.0 @600.0",
                        "R 5.0",
                        "R 20.0"),
                moves(HoleMaking.drill("d", Vec2.ZERO, H, D10, pecks)));
    }

    @Test
    void withoutASpindleSpeedThereIsNoSpeedChangeAndNoSpindleStop() {
        Tooling noSpeed = new Tooling(1, 10, 0, 600, 600);
        DrillCycle c = new DrillCycle(0, 2, 1, 4, 1, 0, 0, 0, 1)
                .withSpeedFactors(0.75, 0.5)
                .withSpindleStopAtBottom(true)
                .withDwells(1, 0);
        assertEquals(
                List.of("R 5.0", "F -25.0 @600.0", "D 1.0", "F 5.0 @600.0", "R 20.0"),
                moves(HoleMaking.drill("b", Vec2.ZERO, H, noSpeed, c)));
    }

    @Test
    void aDrillCycleRefusesNegativeOrEndlessDwellsAndSpeedFactors() {
        DrillCycle c = DrillCycle.PLAIN;
        for (double bad : new double[] {-1, Double.NaN, Double.POSITIVE_INFINITY}) {
            org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> c.withDwells(bad, 0));
            org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> c.withDwells(0, bad));
            org.junit.jupiter.api.Assertions.assertThrows(
                    IllegalArgumentException.class, () -> c.withSpeedFactors(bad, 1));
        }
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> c.withSpeedFactors(1, 0));
    }

    /** A hole on a side face: the dwell and spindle events go with the tool into the workpiece frame. */
    @Test
    void placingMovesDwellsAndSpindleEventsWithTheTool() {
        DrillCycle c = DrillCycle.PLAIN.withRetractFeed(1).withDwells(1.5, 0).withSpindleStopAtBottom(true);
        ToolpathSection local = HoleMaking.drill("b", Vec2.ZERO, H, D10, c);
        org.fresa.geom.Transform3 side =
                org.fresa.geom.Transform3.translation(100, 0, 50).times(org.fresa.geom.Transform3.rotX(-90));
        ToolpathSection placed = Placing.place(local, side);
        assertEquals(moves(local).size(), placed.moves().size());
        for (int i = 0; i < local.moves().size(); i++) {
            Move a = local.moves().get(i);
            Move b = placed.moves().get(i);
            assertEquals(a.getClass(), b.getClass());
            assertEquals(0, side.applyToPoint(a.end()).distance(b.end()), 1e-9);
        }
        Move.Dwell d = (Move.Dwell) placed.moves().stream()
                .filter(m -> m instanceof Move.Dwell)
                .findFirst()
                .orElseThrow();
        assertEquals(1.5, d.seconds());
        Move.SpindleStart on = (Move.SpindleStart) placed.moves().stream()
                .filter(m -> m instanceof Move.SpindleStart)
                .findFirst()
                .orElseThrow();
        assertAll(() -> assertEquals(1000, on.rpm()), () -> assertEquals(true, on.clockwise()));
    }

    @Test
    void anIncludedPointAngleAndAMissingAngleReadAsTheirPointLengths() {
        Operation inc = op(OperationType.DRILLING, drill(118, "deg"), DrillingStrategy.NONE, DrillingParameters.NONE);
        assertEquals(5 / Math.tan(Math.toRadians(59)), ToolpathPlanner.tipLength(inc, D10), EPS);
        Operation steep =
                op(OperationType.DRILLING, drill(89.9, "deg"), DrillingStrategy.NONE, DrillingParameters.NONE);
        assertEquals(5 * Math.tan(Math.toRadians(31)), ToolpathPlanner.tipLength(steep, D10), EPS);
    }
}
