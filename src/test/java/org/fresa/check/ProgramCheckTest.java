package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Hand-made programs: one that passes, and one for each rule that the check must refuse. */
class ProgramCheckTest {

    /** A 20 mm slot at Z0..-2: spindle on, a 2 degree ramp in, along, out. */
    static final String GOOD = """
            %
            (slot)
            G21 G90 G94 G17 G40 G49 G80 G54
            M5
            T1 M6
            G43 H1
            S3000 M3
            G0 X0.000 Y0.000 Z5.000
            G1 X0.000 Y0.000 Z0.000 F300.0
            G1 X57.272 Y0.000 Z-2.000
            G1 X0.000 Y0.000 Z-2.000
            G0 X0.000 Y0.000 Z5.000
            M5
            G40 G49 G80
            M30
            %
            """;

    static final Limits MILL = Limits.milling().withHeights(0, -2, 0);

    private static Failure fails(String program, NcDialect d, Limits l) {
        ProgramCheck.Verdict v = ProgramCheck.of(program, d, l);
        assertTrue(v.failure().isPresent(), "the check passed:\n" + program);
        return v.failure().get();
    }

    @Test
    void aSlotRampedAtTwoDegreesPasses() {
        ProgramCheck.Verdict v = ProgramCheck.of(GOOD, NcDialect.LINUXCNC, MILL);
        assertTrue(v.ok(), () -> v.failure().get().message());
        assertEquals(17, v.blocks());
    }

    @Test
    void spindleRuleRefusesCuttingAfterM5WithNoM3() {
        // a STEP-NC workingstep whose spindle is $: M5, tool change, then a feed move
        String p = GOOD.replace("S3000 M3\n", "");
        Failure f = fails(p, NcDialect.LINUXCNC, MILL);
        assertEquals("spindle", f.rule().name());
        assertEquals(8, f.line());
        assertTrue(f.message().contains("spindle stopped"), f.message());
    }

    @Test
    void spindleRuleRefusesCuttingAfterTheSpindleIsStopped() {
        String p = GOOD.replace("G1 X0.000 Y0.000 Z-2.000\n", "M5\nG1 X0.000 Y0.000 Z-2.000\n");
        Failure f = fails(p, NcDialect.LINUXCNC, MILL);
        assertEquals("spindle", f.rule().name());
        assertEquals(12, f.line());
    }

    @Test
    void spindleRuleOnASheetCutterAsksForTheJet() {
        Limits plasma = Limits.sheetCutting("plasma", "M07", "M08");
        String on = "N10 G21 G90 G17 G40 G94\nN20 G0 X0 Y0\nN30 M07\nN40 G1 X10 Y0 F2000\nN50 M08\nN60 M30\n";
        assertTrue(ProgramCheck.of(on, NcDialect.ISO, plasma).ok());
        Failure f = fails(on.replace("N30 M07\n", ""), NcDialect.ISO, plasma);
        assertEquals("spindle", f.rule().name());
        assertTrue(f.message().contains("plasma off"), f.message());
    }

    @Test
    void wordRuleRefusesASpindleSpeedOfLongMaxValue() {
        Failure f = fails(GOOD.replace("S3000", "S9223372036854775807"), NcDialect.LINUXCNC, MILL);
        assertEquals("words", f.rule().name());
        assertEquals(7, f.line());
    }

    @Test
    void wordRuleRefusesAFeedOf309Digits() {
        String huge = String.format(java.util.Locale.ROOT, "%.1f", 1e308);
        Failure f = fails(GOOD.replace("F300.0", "F" + huge), NcDialect.LINUXCNC, MILL);
        assertEquals("words", f.rule().name());
        assertTrue(f.reason().contains("characters"), f.reason());
    }

    @Test
    void wordRuleRefusesASpindleSpeedOfZeroAndAFeedBelowTheRange() {
        assertEquals(
                "words",
                fails(GOOD.replace("S3000", "S0"), NcDialect.LINUXCNC, MILL)
                        .rule()
                        .name());
        assertEquals(
                "words",
                fails(GOOD.replace("F300.0", "F0.0"), NcDialect.LINUXCNC, MILL)
                        .rule()
                        .name());
        assertEquals(
                "words",
                fails(GOOD.replace("Z5.000", "Z50000.000"), NcDialect.LINUXCNC, MILL)
                        .rule()
                        .name());
    }

    @Test
    void wordRuleRefusesAnAddressWithoutANumber() {
        Failure f = fails(GOOD.replace("G1 X57.272", "G1 XNaN X57.272"), NcDialect.LINUXCNC, MILL);
        assertEquals("words", f.rule().name());
    }

    @Test
    void entryAngleRuleRefusesARampOf66Degrees() {
        // cavity 05: the 10 mm cutter dropping 3 mm over 1.35 mm of path
        String p = GOOD.replace("G1 X57.272 Y0.000 Z-2.000", "G1 X1.350 Y0.000 Z-3.000");
        Failure f = fails(p, NcDialect.LINUXCNC, Limits.milling().withHeights(0, Double.NaN, 0));
        assertEquals("entry angle", f.rule().name());
        assertEquals(10, f.line());
        assertTrue(f.reason().contains("65.7 degrees"), f.reason());
    }

    @Test
    void entryAngleRuleLetsADrillOrAPlungingCentreCutterGoStraightDown() {
        String p = GOOD.replace("G1 X57.272 Y0.000 Z-2.000", "G1 X0.000 Y0.000 Z-2.000");
        assertEquals("entry angle", fails(p, NcDialect.LINUXCNC, MILL).rule().name());
        assertTrue(ProgramCheck.of(p, NcDialect.LINUXCNC, MILL.withTool(1, ToolLimits.drill()))
                .ok());
        assertTrue(ProgramCheck.of(p, NcDialect.LINUXCNC, MILL.withTool(1, ToolLimits.centreCuttingPlunge()))
                .ok());
    }

    @Test
    void entryAngleRuleMeasuresAHelixAlongItsArc() {
        // a helix of radius 5 descending 2 mm in one turn: atan(2 / 31.416) = 3.6 degrees
        String helix = GOOD.replace("G1 X57.272 Y0.000 Z-2.000", "G3 X0.000 Y0.000 Z-2.000 I5.000 J0.000");
        Failure f = fails(helix, NcDialect.LINUXCNC, MILL);
        assertEquals("entry angle", f.rule().name());
        assertTrue(f.reason().contains("3.6 degrees"), f.reason());
        // two turns (P2) halve it: 1.8 degrees
        assertTrue(ProgramCheck.of(helix.replace("J0.000", "J0.000 P2"), NcDialect.LINUXCNC, MILL)
                .ok());
        assertTrue(ProgramCheck.of(helix.replace("J0.000", "J0.000 TURN=1"), NcDialect.SINUMERIK_840D, MILL)
                .ok());
    }

    @Test
    void entryAngleRuleLeavesDescentsInTheAirAlone() {
        String p = GOOD.replace("G1 X0.000 Y0.000 Z0.000 F300.0", "G1 X0.000 Y0.000 Z0.000 F300.0\nG1 Z0.000");
        assertTrue(ProgramCheck.of(p, NcDialect.LINUXCNC, MILL).ok());
        String air = GOOD.replace(
                "G0 X0.000 Y0.000 Z5.000\nG1 X0.000 Y0.000 Z0.000", "G0 X0.000 Y0.000 Z9.000\nG1 X0.000 Y0.000 Z0.000");
        assertTrue(ProgramCheck.of(air, NcDialect.LINUXCNC, MILL).ok());
        assertEquals(
                "entry angle",
                fails(air, NcDialect.LINUXCNC, MILL.withHeights(-1e-6 + 1, -2, 0))
                        .rule()
                        .name());
    }

    @Test
    void floorRuleRefusesAMoveBelowTheFloorBeyondTheBreakthrough() {
        Limits floor = MILL.withHeights(0, -1.5, 0.4);
        Failure f = fails(GOOD, NcDialect.LINUXCNC, floor);
        assertEquals("floor", f.rule().name());
        assertEquals(10, f.line());
        assertTrue(f.reason().contains("0.5 mm below the floor Z -1.5 mm"), f.reason());
        assertTrue(ProgramCheck.of(GOOD, NcDialect.LINUXCNC, MILL.withHeights(0, -1.5, 0.5))
                .ok());
    }

    @Test
    void dwellWordsAreTimesNotMovesOrFeeds() {
        String p840 = "N10 G71 G90 G17\nN20 T1 D1\nN30 M6\nN40 S2000 M3\nN50 G0 X0 Y0 Z5\nN60 G4 F2.000\n"
                + "N70 G1 X10 Y0 Z5 F200\nN80 M5\nN90 M30\n";
        assertTrue(ProgramCheck.of(p840, NcDialect.SINUMERIK_840D, MILL).ok());
        // without the feed of N70, the 840D's dwell F is no feed rate
        Failure f = fails(p840.replace(" F200", ""), NcDialect.SINUMERIK_840D, MILL);
        assertTrue(f.reason().contains("no feed rate"), f.reason());
        String iso = "N10 G21 G90 G17\nN20 S2000 M3\nN30 G0 X0 Y0 Z5\nN40 G04 X2.000\nN50 G1 X10 F200\nN60 M30\n";
        assertTrue(ProgramCheck.of(iso, NcDialect.ISO, MILL).ok());
    }

    @Test
    void theSevenMDialectCountsMicrometresAndIncrements() {
        String p = """
                N05 %
                N10 G00 G40 G53 G90 Y150000 Z600000 B0
                N15 G53 X450000
                N20 G54 X 0 Y 0 Z 30000
                N25 T01 M06
                N30 M21
                N35 G43 Z 5000 S 3200 M03
                N40 G00 G90 X 34979 Y 46847
                N45 G01 G91 Z-8000F 290
                N50 G90 X 49458 Y 46847
                N55 G00 G91 Z 200000
                N60 G40 G53 G90 X450000 Y150000 Z600000 B0 M05
                N65 M30
                """;
        Limits thesis = Limits.milling().withHeights(0, -3, 0).withTool(1, ToolLimits.centreCuttingPlunge());
        assertTrue(ProgramCheck.of(p, NcDialect.SINUMERIK_7M, thesis).ok());
        Failure deep = fails(p, NcDialect.SINUMERIK_7M, thesis.withHeights(0, -2, 0));
        assertEquals("floor", deep.rule().name());
        assertEquals("block N45 (line 9)", deep.where());
        Failure plunge = fails(p, NcDialect.SINUMERIK_7M, Limits.milling().withHeights(0, -3, 0));
        assertEquals("entry angle", plunge.rule().name());
        assertTrue(plunge.reason().contains("90.0 degrees (a plunge)"), plunge.reason());
    }

    @Test
    void entryAngleRuleLeavesPlungesBesideTheStockAlone() {
        String p = GOOD.replace("G1 X57.272 Y0.000 Z-2.000", "G1 X0.000 Y0.000 Z-2.000\nG1 X57.272 Y0.000 Z-2.000");
        Limits.Stock block = new Limits.Stock(10, -50, -20, 100, 50, 0);
        Limits mill = Limits.milling().withStock(block);
        // the cutter of radius 4 at X0 stands 6 mm clear of the block's side: it plunges in the air
        assertTrue(ProgramCheck.of(
                        p,
                        NcDialect.LINUXCNC,
                        mill.withTool(1, ToolLimits.notCentreCutting().withRadiusMm(4)))
                .ok());
        Failure f = fails(
                p,
                NcDialect.LINUXCNC,
                mill.withTool(1, ToolLimits.notCentreCutting().withRadiusMm(12)));
        assertEquals("entry angle", f.rule().name());
    }

    @Test
    void aCutterMayGoStraightDownIntoAHoleDrilledBeforeAtLeastHalfItsDiameter() {
        String drill = "T1 M6\nS1000 M3\nG0 X20 Y20 Z5\nG1 Z-10 F100\nG0 Z5\n";
        String mill = "T2 M6\nS1000 M3\nG0 X20 Y20 Z5\nG1 Z%s F100\nG0 Z5\nM5\nM2\n";
        Limits l = MILL.withHeights(0, -10, 0).withTool(1, ToolLimits.drill().withRadiusMm(5));
        Limits wide = l.withTool(2, ToolLimits.notCentreCutting().withRadiusMm(10));
        // a 10 mm pilot under a 20 mm cutter: its core is over the void down to the drill's tip
        assertTrue(ProgramCheck.of(drill + mill.formatted("-10"), NcDialect.LINUXCNC, wide)
                .ok());
        // deeper than the drill went, before the drill, a pilot narrower than half the cutter, off its axis
        assertEquals(
                "entry angle",
                fails(drill + mill.formatted("-10.5"), NcDialect.LINUXCNC, wide)
                        .rule()
                        .name());
        assertEquals(
                "entry angle",
                fails(mill.formatted("-10").replace("M2\n", "") + drill + "M2\n", NcDialect.LINUXCNC, wide)
                        .rule()
                        .name());
        Limits huge = l.withTool(2, ToolLimits.notCentreCutting().withRadiusMm(10.5));
        assertEquals(
                "entry angle",
                fails(drill + mill.formatted("-10"), NcDialect.LINUXCNC, huge)
                        .rule()
                        .name());
        Limits small = l.withTool(2, ToolLimits.notCentreCutting().withRadiusMm(6));
        assertTrue(
                ProgramCheck.of(drill + mill.formatted("-10").replace("X20 Y20", "X22 Y20"), NcDialect.LINUXCNC, small)
                        .ok());
        assertEquals(
                "entry angle",
                fails(drill + mill.formatted("-10").replace("X20 Y20", "X22.1 Y20"), NcDialect.LINUXCNC, small)
                        .rule()
                        .name());
    }

    @Test
    void entryAngleRuleFollowsTheToolAxisThePostStates() {
        String p = GOOD.replace(
                        "(slot)",
                        "(slot tool 1 D8.000)\n(tool axis 0.000 -1.000 0.000 is not +Z: needs the part turned)")
                .replace("G1 X57.272 Y0.000 Z-2.000", "G1 X0.000 Y2.000 Z0.000");
        // along -Y the move to Y2 goes against the axis: a plunge; the descent to Z0 is sideways
        Failure f = fails(p, NcDialect.LINUXCNC, Limits.milling());
        assertEquals("entry angle", f.rule().name());
        assertEquals(11, f.line());
    }

    @Test
    void spindleRuleLetsAReamerLeaveItsHoleWithTheSpindleStopped() {
        String ream = "G21 G90 G17\nT3 M6\nS1080 M3\nG0 X20 Y60 Z10\nG1 X20 Y60 Z-30 F180\nM5\nG1 X20 Y60 Z10\nM30\n";
        Limits l = Limits.milling().withTool(3, ToolLimits.drill());
        assertTrue(ProgramCheck.of(ream, NcDialect.LINUXCNC, l).ok());
        Failure f = fails(ream.replace("G1 X20 Y60 Z10", "G1 X21 Y60 Z10"), NcDialect.LINUXCNC, l);
        assertEquals("spindle", f.rule().name());
    }
}
