package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class ToolTurnsTest {

    private static final Robot IRB140 = Robots.irb140();
    private static final Robot ADEPT = Robots.adeptOne();

    @Test
    void aSpindleTriesTheCurrentTurnThenHalfAndQuarterTurnsWrappedIntoPlusMinus180() {
        assertEquals(List.of(30.0, -150.0, 120.0, -60.0), new ToolTurns(true, 180).firstDeg(IRB140, 30));
        assertEquals(List.of(170.0, -10.0, -100.0, 80.0), new ToolTurns(true, 180).firstDeg(IRB140, 170));
    }

    @Test
    void aToolThatMayNotTurnAndAnArmThatTurnsItWithOneJointTryTheCurrentTurnOnly() {
        assertEquals(List.of(30.0), new ToolTurns(false, 180).firstDeg(IRB140, 30));
        assertEquals(List.of(30.0), new ToolTurns(true, 180).firstDeg(ADEPT, 30));
    }

    @Test
    void turnsAreHeldWithinTheLargestTurnAllowed() {
        assertEquals(List.of(30.0, -90.0, 90.0, -60.0), new ToolTurns(true, 90).firstDeg(IRB140, 30));
        assertEquals(List.of(0.0, 90.0, -90.0), new ToolTurns(true, 90).firstDeg(IRB140, 0));
        assertThrows(IllegalArgumentException.class, () -> new ToolTurns(true, 181));
    }

    @Test
    void theTrajectoryTheLiveCheckAndThePlacementSearchTakeTheTrajectorysOptions() {
        assertEquals(new ToolTurns(true, 180), ToolTurns.of(TrajectorySolver.Options.DEFAULT));
        assertEquals(new ToolTurns(false, 180), ToolTurns.of(TrajectorySolver.Options.DEFAULT.withFreeRotation(false)));
    }
}
