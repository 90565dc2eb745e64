package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** A Tricept's leg range is held to the rule of a serial joint's: finite, max above min. */
class JointLimitTest {

    @ParameterizedTest
    @CsvSource(textBlock = """
            1800, 900
            900,  900
            NaN,  1800
            900,  Infinity
            """)
    void limitsThatAreNotFiniteOrNotIncreasingAreRefusedLikeADhJoints(double min, double max) {
        IllegalArgumentException leg =
                assertThrows(IllegalArgumentException.class, () -> new JointLimit("q1", JointType.PRISMATIC, min, max));
        assertThrows(IllegalArgumentException.class, () -> DhJoint.prismatic(0, 0, 0, 0, min, max));
        assertTrue(leg.getMessage().contains("joint q1: limits must have max > min"), leg.getMessage());
    }
}
