package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The rapid rule on hand-made programs: a rapid into the stock is refused, a rapid down into what
 * the program cleared before, beside the stock or at the security plane above it passes.
 */
class RapidRuleTest {

    /** A 10 mm cutter clears a 20 x 20 pocket layer at Z-4 (ramped in), then goes down again by rapid. */
    static final String TWO_LAYERS = """
            T1 M6
            S3000 M3
            G0 X10.000 Y10.000 Z5.000
            G0 X10.000 Y10.000 Z1.000
            G1 X10.000 Y10.000 Z0.000 F300
            G1 X30.000 Y10.000 Z-1.000
            G1 X10.000 Y10.000 Z-2.000
            G1 X30.000 Y10.000 Z-3.000
            G1 X10.000 Y10.000 Z-4.000
            G1 X30.000 Y10.000 Z-4.000
            G1 X30.000 Y30.000
            G1 X10.000 Y30.000
            G1 X10.000 Y10.000
            G1 X20.000 Y20.000
            G0 X20.000 Y20.000 Z5.000
            G0 X10.000 Y10.000 Z5.000
            G0 X10.000 Y10.000 Z-3.800
            G1 X30.000 Y10.000 Z-4.500
            G0 X30.000 Y10.000 Z5.000
            M5
            M30
            """;

    static final Limits POCKET = Limits.milling()
            .withHeights(0, -8, 0)
            .withTool(1, ToolLimits.notCentreCutting().withRadiusMm(5).withEntryAngleDeg(5));

    private static Failure fails(String program, NcDialect d, Limits l) {
        ProgramCheck.Verdict v = ProgramCheck.of(program, d, l);
        assertTrue(v.failure().isPresent(), "the check passed:\n" + program);
        return v.failure().get();
    }

    @Test
    void aRapidDownIntoTheLayerTheProgramClearedPasses() {
        ProgramCheck.Verdict v = ProgramCheck.of(TWO_LAYERS, NcDialect.LINUXCNC, POCKET);
        assertTrue(v.ok(), () -> v.failure().get().message());
    }

    @Test
    void aRapidDownWhereNothingWasCutIsRefusedWithItsDepth() {
        // the same rapid 20 mm beside the pocket: the stock there is untouched
        String p = TWO_LAYERS.replace(
                "G0 X10.000 Y10.000 Z5.000\nG0 X10.000 Y10.000 Z-3.800",
                "G0 X50.000 Y10.000 Z5.000\nG0 X50.000 Y10.000 Z-3.800");
        Failure f = fails(p, NcDialect.LINUXCNC, POCKET);
        assertEquals("rapid", f.rule().name());
        assertEquals("G0 X50.000 Y10.000 Z-3.800", f.text());
        assertTrue(f.reason().contains("3.8 mm below the stock's top Z 0 mm"), f.reason());
    }

    @Test
    void aRapidDownBeforeTheLayerAboveIsClearedIsRefused() {
        // down to Z-3.8 before the floor at Z-4 was cut: only the ramps (to Z-3 at X30) had gone there
        String p = TWO_LAYERS.replace(
                "G1 X10.000 Y10.000 Z-4.000\n",
                "G0 X10.000 Y10.000 Z5.000\nG0 X10.000 Y30.000 Z5.000\nG0 X10.000 Y30.000 Z-3.800\n");
        Failure f = fails(p, NcDialect.LINUXCNC, POCKET);
        assertEquals("rapid", f.rule().name());
        assertEquals("G0 X10.000 Y30.000 Z-3.800", f.text());
        assertTrue(f.reason().contains("3.8 mm below the stock's top"), f.reason());
    }

    @Test
    void aRapidSidewaysAtDepthThroughTheWallIsRefused() {
        // along the cleared floor, then on through the pocket's wall at Z-3.8
        String p = TWO_LAYERS.replace("G1 X30.000 Y10.000 Z-4.500", "G0 X60.000 Y10.000 Z-3.800");
        Failure f = fails(p, NcDialect.LINUXCNC, POCKET);
        assertEquals("rapid", f.rule().name());
        assertEquals("G0 X60.000 Y10.000 Z-3.800", f.text());
    }

    @Test
    void aRapidBesideTheStockBoxOrAboveItPasses() {
        Limits block = Limits.milling()
                .withStock(new Limits.Stock(0, 0, -50, 100, 100, 0))
                .withTool(1, ToolLimits.notCentreCutting().withRadiusMm(5));
        // 6 mm clear of the block's side, down to Z-20: air
        String beside = "T1 M6\nS1000 M3\nG0 X-11 Y50 Z5\nG0 X-11 Y50 Z-20\nG0 X-11 Y50 Z5\nM5\nM30\n";
        assertTrue(ProgramCheck.of(beside, NcDialect.LINUXCNC, block).ok());
        // 4 mm clear: the tool's rim is 1 mm over the block
        Failure f = fails(beside.replace("X-11", "X-4"), NcDialect.LINUXCNC, block);
        assertEquals("rapid", f.rule().name());
        assertTrue(f.reason().contains("20 mm below the stock's top Z 0 mm"), f.reason());
        // a security plane at Z-1 over the block: every rapid across it is a crash
        String low = "T1 M6\nS1000 M3\nG0 X-20 Y50 Z-1\nG0 X120 Y50 Z-1\nM5\nM30\n";
        Failure across = fails(low, NcDialect.LINUXCNC, block);
        assertEquals("rapid", across.rule().name());
        assertTrue(across.reason().contains("1 mm below the stock's top"), across.reason());
        assertTrue(ProgramCheck.of(low.replace("Z-1", "Z0.001"), NcDialect.LINUXCNC, block)
                .ok());
    }

    @Test
    void aDrillMayRapidBackDownItsOwnHoleButAWiderCutterMayNot() {
        // a peck: down 10, out, back down by rapid to 1 mm above the last depth, on
        String peck = "T1 M6\nS1000 M3\nG0 X20 Y20 Z5\nG1 Z-10 F100\nG0 Z5\nG0 Z-9\nG1 Z-20\nG0 Z5\nM5\nM30\n";
        Limits drill = Limits.milling()
                .withHeights(0, -20, 0)
                .withTool(1, ToolLimits.drill().withRadiusMm(4));
        ProgramCheck.Verdict v = ProgramCheck.of(peck, NcDialect.LINUXCNC, drill);
        assertTrue(v.ok(), () -> v.failure().get().message());
        // a 20 mm end mill after it by rapid into the 8 mm hole: it meets the stock round the hole
        String after = peck.replace("M5\nM30\n", "T2 M6\nS1000 M3\nG0 X20 Y20 Z5\nG0 Z-5\nM5\nM30\n");
        Failure f = fails(
                after,
                NcDialect.LINUXCNC,
                drill.withTool(2, ToolLimits.notCentreCutting().withRadiusMm(10)));
        assertEquals("rapid", f.rule().name());
        assertEquals("G0 Z-5", f.text());
    }

    @Test
    void aptRapidsAreJudgedAsGCodeRapidsAre() {
        String apt = """
                PARTNO slot
                UNITS/MM
                LOADTL/1
                SPINDL/3000,CLW
                RAPID
                GOTO/0.000,0.000,5.000
                RAPID
                GOTO/0.000,0.000,-1.000
                FINI
                """;
        Failure f = fails(apt, NcDialect.APT, POCKET);
        assertEquals("rapid", f.rule().name());
        assertEquals("GOTO/0.000,0.000,-1.000", f.text());
        // the same after the tool has fed down there
        String fed = apt.replace(
                "RAPID\nGOTO/0.000,0.000,-1.000",
                "FEDRAT/300.0,MMPM\nGOTO/0.000,0.000,0.000\nGOTO/57.272,0.000,-2.000\nGOTO/0.000,0.000,-2.000\n"
                        + "RAPID\nGOTO/0.000,0.000,5.000\nRAPID\nGOTO/0.000,0.000,-1.000");
        ProgramCheck.Verdict v = ProgramCheck.of(
                fed,
                NcDialect.APT,
                POCKET.withTool(1, ToolLimits.notCentreCutting().withRadiusMm(5)));
        assertTrue(v.ok(), () -> v.failure().get().message());
    }

    @Test
    void withNoStatedTopOfTheStockThereIsNothingToCompare() {
        String p = "T1 M6\nS1000 M3\nG0 X0 Y0 Z-50\nG0 X100 Y0 Z-50\nM5\nM30\n";
        assertTrue(ProgramCheck.of(p, NcDialect.LINUXCNC, Limits.milling()).ok());
    }

    @Test
    void aCapsulesTraceOnARowIsExactlyThePointsWithinItsRadius() {
        java.util.Random rnd = new java.util.Random(7);
        int checked = 0;
        for (int n = 0; n < 400; n++) {
            org.fresa.geom.Vec3 a = new org.fresa.geom.Vec3(rnd.nextDouble() * 20 - 10, rnd.nextDouble() * 20 - 10, 0);
            org.fresa.geom.Vec3 b =
                    n % 5 == 0 ? a : new org.fresa.geom.Vec3(rnd.nextDouble() * 20 - 10, rnd.nextDouble() * 20 - 10, 0);
            double r = 0.1 + rnd.nextDouble() * 6;
            double y = rnd.nextDouble() * 34 - 17;
            double[] span = Material.rowSpan(a, b, r, y);
            for (double x = -17; x <= 17; x += 0.02) {
                double d = distance(a, b, x, y);
                boolean in = span != null && x >= span[0] - 1e-9 && x <= span[1] + 1e-9;
                if (Math.abs(d - r) > 1e-6) {
                    assertEquals(d < r, in, "row " + y + " x " + x + " r " + r + " " + a + " " + b);
                    checked++;
                }
            }
        }
        assertTrue(checked > 600_000, "points checked: " + checked);
    }

    private static double distance(org.fresa.geom.Vec3 a, org.fresa.geom.Vec3 b, double x, double y) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double q = dx * dx + dy * dy;
        double t = q == 0 ? 0 : Math.max(0, Math.min(1, ((x - a.x()) * dx + (y - a.y()) * dy) / q));
        return Math.hypot(a.x() + t * dx - x, a.y() + t * dy - y);
    }

    @Test
    void aFeedStraightDownWhereTheProgramClearedIsNoEntryButBesideItIsAPlunge() {
        // after the first layer, straight down at feed from Z-3.8 to Z-4 inside the cleared floor
        String p = TWO_LAYERS.replace(
                "G0 X10.000 Y10.000 Z-3.800\n", "G0 X10.000 Y10.000 Z-3.000\nG1 X10.000 Y10.000 Z-4.000\n");
        ProgramCheck.Verdict v = ProgramCheck.of(p, NcDialect.LINUXCNC, POCKET);
        assertTrue(v.ok(), () -> v.failure().get().message());
        // on below the cleared floor it is a plunge into the material
        String deeper = TWO_LAYERS.replace(
                "G0 X10.000 Y10.000 Z-3.800\n", "G0 X10.000 Y10.000 Z-3.800\nG1 X10.000 Y10.000 Z-4.500\n");
        Failure f = fails(deeper, NcDialect.LINUXCNC, POCKET);
        assertEquals("entry angle", f.rule().name());
        assertEquals("G1 X10.000 Y10.000 Z-4.500", f.text());
    }
}
