package org.fresa.setting;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SettingRangeTest {

    static final SettingRange Z = SettingRange.of("--z-top", "zTopMm", -10_000, 10_000, "mm");
    static final SettingRange CUT = SettingRange.above("--cut", "cutFraction", 0, 1, "");
    static final SettingRange SHRINK = SettingRange.below("--shrinkage", "shrinkage", 0, 0.5, "");
    static final SettingRange GROUP = SettingRange.wholeNumbers("--heel-group", "heelGroup", 1, 400, "sizes");

    @ParameterizedTest
    @ValueSource(
            doubles = {
                Double.NaN,
                Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY,
                1e308,
                -1e308,
                Double.MAX_VALUE,
                -Double.MAX_VALUE,
                10_000.000001
            })
    void nanInfinitiesAndHugeValuesLieOutsideARange(double v) {
        assertFalse(Z.contains(v));
    }

    @Test
    void theBoundsAreIncludedOrNotAsDeclared() {
        assertAll(
                () -> assertTrue(Z.contains(-10_000) && Z.contains(10_000)),
                () -> assertFalse(CUT.contains(0)),
                () -> assertTrue(CUT.contains(1)),
                () -> assertTrue(SHRINK.contains(0)),
                () -> assertFalse(SHRINK.contains(0.5)),
                () -> assertTrue(GROUP.contains(3)),
                () -> assertFalse(GROUP.contains(2.5)));
    }

    @Test
    void theMessageNamesTheOptionTheRangeAndTheValue() {
        CamInputException e = assertThrows(CamInputException.class, () -> Z.check(1e308));
        assertAll(
                () -> assertEquals("--z-top: expected a number from -10000 to 10000 mm, found 1E308", e.getMessage()),
                () -> assertEquals("expected a number above 0 and at most 1, found NaN", CUT.problem(Double.NaN)),
                () -> assertEquals(
                        "expected a number of at least 0 and below 0.5, found -Infinity",
                        SHRINK.problem(Double.NEGATIVE_INFINITY)),
                () -> assertEquals("expected a whole number from 1 to 400 sizes, found 0", GROUP.problem(0)));
    }

    @Test
    void aReaderGetsTheRangeAndTheValueBack() {
        SettingRange.OutOfRange e = assertThrows(SettingRange.OutOfRange.class, () -> Z.require(-2e4));
        assertAll(
                () -> assertEquals(Z, e.range()),
                () -> assertEquals(-2e4, e.value()),
                () -> assertEquals(5.0, Z.require(5.0)));
    }

    @Test
    void theSpindleAndFeedRangesAreTheMachinesOwn() {
        assertAll(
                () -> assertFalse(SettingRanges.Pocket.SPINDLE.contains(0)),
                () -> assertTrue(SettingRanges.Pocket.SPINDLE.contains(100_000)),
                () -> assertFalse(SettingRanges.Pocket.FEED.contains(0.09)),
                () -> assertTrue(SettingRanges.Sole.TOOL_FEED.contains(100_000)));
    }
}
