package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Strategy;
import org.fresa.stepnc.Technology;
import org.junit.jupiter.api.Test;

/**
 * The loop sense of a pocket's or hole's passes. With the spindle turning clockwise (M3), a tooth
 * takes its thickest chip first (climb milling) where the material is on the tool's right; the
 * walls of a pocket lie outside its loops, on the right of a loop run counter-clockwise.
 */
class CutModeTest {

    private static Operation rough(String rotation, String cutmode) {
        Strategy s = new Strategy(
                2,
                Strategy.StrategyType.CONTOUR_PARALLEL,
                "CONTOUR_PARALLEL",
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.empty(),
                Optional.ofNullable(rotation),
                Optional.ofNullable(cutmode),
                Optional.empty());
        return new Operation(
                3,
                Operation.OperationType.BOTTOM_AND_SIDE_ROUGH_MILLING,
                "BOTTOM_AND_SIDE_ROUGH_MILLING",
                "rough",
                OptionalDouble.of(5),
                Optional.empty(),
                Optional.empty(),
                Technology.NONE,
                Optional.of(s),
                Optional.empty(),
                Optional.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                List.of());
    }

    @Test
    void climbAsksForCounterClockwiseLoopsAndConventionalForClockwiseOnes() {
        assertEquals(false, ToolpathPlanner.clockwise(rough(null, "CLIMB")));
        assertEquals(true, ToolpathPlanner.clockwise(rough(null, "CONVENTIONAL")));
        assertEquals(false, ToolpathPlanner.clockwise(rough(null, null)));
    }

    @Test
    void aStatedRotationDirectionIsFollowedWhateverTheCutMode() {
        assertEquals(true, ToolpathPlanner.clockwise(rough("CW", "CLIMB")));
        assertEquals(false, ToolpathPlanner.clockwise(rough("CCW", "CONVENTIONAL")));
    }
}
