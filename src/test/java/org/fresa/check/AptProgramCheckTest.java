package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Hand-made APT programs: one that passes, and one for each rule the check must refuse. */
class AptProgramCheckTest {

    /** The slot of ProgramCheckTest in APT: a 2 degree ramp to Z-2, back along, then a half-circle at the floor. */
    static final String GOOD = """
            PARTNO slot
            UNITS/MM
            $$ slot tool 1 D6.000
            SPINDL/OFF
            LOADTL/1
            CUTTER/6.000
            SPINDL/3000,CLW
            RAPID
            GOTO/0.000,0.000,5.000
            FEDRAT/300.0,MMPM
            GOTO/0.000,0.000,0.000
            GOTO/57.272,0.000,-2.000
            GOTO/0.000,0.000,-2.000
            CIRCLE/5.000,0.000,-2.000,0,0,-1,5.000
            GOTO/10.000,0.000,-2.000
            DELAY/0.500
            RAPID
            GOTO/10.000,0.000,5.000
            SPINDL/OFF
            COOLNT/OFF
            FINI
            """;

    static final Limits MILL = Limits.milling().withHeights(0, -2, 0);

    private static Failure fails(String program) {
        return fails(program, MILL);
    }

    private static Failure fails(String program, Limits limits) {
        ProgramCheck.Verdict v = ProgramCheck.of(program, NcDialect.APT, limits);
        assertTrue(v.failure().isPresent(), "the check passed:\n" + program);
        return v.failure().get();
    }

    @Test
    void theSlotPasses() {
        ProgramCheck.Verdict v = ProgramCheck.of(GOOD, NcDialect.APT, MILL);
        assertTrue(v.ok(), () -> v.failure().get().message());
        assertEquals(22, v.blocks());
        assertEquals(NcDialect.APT, NcDialect.byPost("APT").orElseThrow());
    }

    @Test
    void spindleRuleRefusesCuttingWithNoSpindleStarted() {
        Failure f = fails(GOOD.replace("SPINDL/3000,CLW\n", ""));
        assertEquals("spindle", f.rule().name());
        assertEquals(10, f.line());
        assertTrue(f.message().contains("spindle stopped"), f.message());
    }

    @Test
    void spindleRuleRefusesCuttingAfterSpindlOff() {
        Failure f = fails(GOOD.replace("GOTO/0.000,0.000,-2.000\n", "SPINDL/OFF\nGOTO/0.000,0.000,-2.000\n"));
        assertEquals("spindle", f.rule().name());
        assertEquals(14, f.line());
    }

    @Test
    void spindleRuleRefusesCuttingAfterAToolChange() {
        // LOADTL stops the spindle as M06 does: the new tool cuts only after its SPINDL
        Failure f = fails(GOOD.replace("GOTO/57.272,0.000,-2.000\n", "LOADTL/2\nGOTO/57.272,0.000,-2.000\n"));
        assertEquals("spindle", f.rule().name());
        assertEquals(13, f.line());
    }

    @Test
    void entryAngleRuleRefusesAPlungeOfACutterThatDoesNotCutAtItsCentre() {
        Failure f = fails(GOOD.replace("GOTO/57.272,0.000,-2.000\n", "GOTO/0.000,0.000,-2.000\n"));
        assertEquals("entry angle", f.rule().name());
        assertEquals(12, f.line());
        assertTrue(f.message().contains("a plunge"), f.message());
    }

    @Test
    void entryAngleRuleRefusesAHelixSteeperThanThreeDegrees() {
        // a full turn of radius 5 dropping 2 mm: atan(2 / 31.4) = 3.6 degrees
        String p = GOOD.replace(
                "GOTO/57.272,0.000,-2.000\nGOTO/0.000,0.000,-2.000\n",
                "CIRCLE/5.000,0.000,0.000,0,0,1,5.000\nGOTO/0.000,0.000,-2.000\n");
        Failure f = fails(p);
        assertEquals("entry angle", f.rule().name());
        assertEquals(13, f.line());
        assertTrue(f.message().contains("3.6"), f.message());
        // two turns of the same helix, 1.8 degrees, pass
        String two = GOOD.replace(
                "GOTO/57.272,0.000,-2.000\nGOTO/0.000,0.000,-2.000\n",
                "CIRCLE/5.000,0.000,0.000,0,0,1,5.000\nGOTO/0.000,0.000,-1.000\n"
                        + "CIRCLE/5.000,0.000,-1.000,0,0,1,5.000\nGOTO/0.000,0.000,-2.000\n");
        ProgramCheck.Verdict v = ProgramCheck.of(two, NcDialect.APT, MILL);
        assertTrue(v.ok(), () -> v.failure().get().message());
    }

    @Test
    void floorRuleRefusesAMoveBelowTheFloor() {
        Failure f = fails(GOOD.replace(
                "GOTO/57.272,0.000,-2.000\nGOTO/0.000,0.000,-2.000\n",
                "GOTO/57.272,0.000,-2.000\nGOTO/0.000,0.000,-2.500\n"));
        assertEquals("floor", f.rule().name());
        assertEquals(13, f.line());
    }

    @Test
    void floorRuleSeesTheLowestPointOfAnArcInAVerticalPlane() {
        // a half circle about -Y from (0,0,-2) to (10,0,-2) through (5,0,-7): counter-clockwise about -Y dips
        // (with a cutter that may plunge, so that only the floor is in question)
        Failure f = fails(
                GOOD.replace("CIRCLE/5.000,0.000,-2.000,0,0,-1,5.000", "CIRCLE/5.000,0.000,-2.000,0,-1,0,5.000"),
                MILL.withOtherTools(ToolLimits.centreCuttingPlunge()));
        assertEquals("floor", f.rule().name());
        assertEquals(15, f.line());
        assertTrue(f.message().contains("Z -7"), f.message());
    }

    @Test
    void wordRuleRefusesOutOfRangeWords() {
        Failure speed = fails(GOOD.replace("SPINDL/3000,CLW", "SPINDL/300000,CLW"));
        assertEquals("words", speed.rule().name());
        assertEquals(7, speed.line());
        Failure feed = fails(GOOD.replace("FEDRAT/300.0,MMPM", "FEDRAT/0.0,MMPM"));
        assertEquals("words", feed.rule().name());
        assertEquals(10, feed.line());
        Failure far = fails(GOOD.replace("GOTO/0.000,0.000,5.000", "GOTO/20000.000,0.000,5.000"));
        assertEquals("words", far.rule().name());
        assertEquals(9, far.line());
        Failure dwell = fails(GOOD.replace("DELAY/0.500", "DELAY/7200"));
        assertEquals("words", dwell.rule().name());
        assertEquals(16, dwell.line());
    }

    @Test
    void statementsThatCannotBeReadAreRefused() {
        assertTrue(fails(GOOD.replace("UNITS/MM", "UNITS/INCHES")).message().contains("only UNITS/MM"));
        assertTrue(fails(GOOD.replace("GOTO/0.000,0.000,5.000", "GOTO/0.000,0.000"))
                .message()
                .contains("x,y,z"));
        assertTrue(fails(GOOD.replace("GOTO/0.000,0.000,5.000", "GOTO/0.000,abc,5"))
                .message()
                .contains("'ABC'"));
        assertTrue(fails(GOOD.replace("COOLNT/OFF", "TLON")).message().contains("'TLON'"));
        assertTrue(fails(GOOD.replace("CUTTER/6.000", "CUTTER/0")).message().contains("diameter"));
        assertTrue(fails(GOOD.replace("0,0,-1,5.000", "0,0,-2,5.000")).message().contains("unit vector"));
        assertTrue(fails(GOOD.replace("0,0,-1,5.000", "0,0,-1,4.000")).message().contains("not on the CIRCLE"));
        assertTrue(fails(GOOD.replace("GOTO/10.000,0.000,-2.000\nDELAY", "DELAY/1\nGOTO/10.000,0.000,-2.000\nDELAY"))
                .message()
                .contains("followed by the GOTO"));
        Failure f = fails(GOOD.replace("FEDRAT/300.0,MMPM", "FEDRAT/300.0,IPM"));
        assertEquals("words", f.rule().name());
        assertEquals(10, f.line());
    }
}
