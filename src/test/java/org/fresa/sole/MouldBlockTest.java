package org.fresa.sole;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.model.ContourFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The layout of the pair in the mould block against the thesis's own numbers (App. F, section 6.6.1). */
class MouldBlockTest {

    /** The thesis's pattern data: CP 270, DPI 29, XTANP 60. */
    static final MouldBlock.Pattern THESIS = new MouldBlock.Pattern(270, 29, 60);
    /** POSTICOS: D 27.6, DLM 225, E 25, S 64.5, CM 285. */
    static final MouldBlock INSERTS = new MouldBlock(27.6, 225, 25, 64.5, 285, THESIS);
    /** CAVIDADES: D 20, DLM 225, E 0, S 11, CM 350. */
    static final MouldBlock CAVITIES = new MouldBlock(20, 225, 0, 11, 350, THESIS);

    /** Brazilian grading of the real sole: VL 1.66 over LP 90, VC 6.66 over CP 270, base 40, CTM 0.02 (additive). */
    static SizeScale size(int nd) {
        double alfa = (90 + (nd - 40) * 1.66) / 90;
        double beta = (270 + (nd - 40) * 6.66) / 270;
        return new SizeScale(Integer.toString(nd), Vec2.of(0, 0), alfa + 0.02, beta + 0.02, 1.02);
    }

    @ParameterizedTest
    @CsvSource({
        "36, 248.760, 320.573, 109.339, 291.773, 88.339",
        "37, 255.420, 321.680, 106.724, 292.880, 85.724",
        "38, 262.080, 322.787, 104.109, 293.987, 83.109",
        "39, 268.740, 323.893, 101.495, 295.093, 80.495",
        "40, 275.400, 325.000, 98.880, 296.200, 77.880",
        "41, 282.060, 326.107, 96.265, 297.307, 75.265",
        "42, 288.720, 327.213, 93.651, 298.413, 72.651",
        "43, 295.380, 328.320, 91.036, 299.520, 70.036",
        "44, 302.040, 329.427, 88.421, 300.627, 67.421"
    })
    void theRightSolesPartZeroIsTheThesissTable(
            int nd, double cp, double xzInserts, double yzInserts, double xzCavities, double yzCavities) {
        MouldBlock.PartZero inserts = INSERTS.partZero(size(nd), Foot.RIGHT);
        MouldBlock.PartZero cavities = CAVITIES.partZero(size(nd), Foot.RIGHT);
        assertEquals(cp, inserts.patternLengthMm(), 5e-4);
        assertEquals(xzInserts, inserts.machineMm().x(), 5e-4);
        assertEquals(yzInserts, inserts.machineMm().y(), 5e-4);
        assertEquals(xzCavities, cavities.machineMm().x(), 5e-4);
        assertEquals(yzCavities, cavities.machineMm().y(), 5e-4);
    }

    @Test
    void theLeftSoleIsTheMirrorAboutTheLineDlmPlusE() {
        MouldBlock.PartZero right = CAVITIES.partZero(size(40), Foot.RIGHT);
        MouldBlock.PartZero left = CAVITIES.partZero(size(40), Foot.LEFT);
        assertEquals(153.8, left.machineMm().x(), 1e-9);
        assertEquals(right.machineMm().y(), left.machineMm().y(), 0);
        assertEquals(2 * (225 + 0), left.machineMm().x() + right.machineMm().x(), 1e-9);
        assertEquals(-71.2, cavities40MirrorLine(), 1e-9);
        assertEquals(-75.0, INSERTS.partZero(size(40), Foot.RIGHT).mirrorLinePartXMm(), 1e-9);
    }

    private static double cavities40MirrorLine() {
        return CAVITIES.partZero(size(40), Foot.RIGHT).mirrorLinePartXMm();
    }

    @Test
    void theInsertBlockTakesSizesUpTo41() {
        assertTrue(INSERTS.misfit(size(41)).isEmpty());
        String why = INSERTS.misfit(size(42)).orElseThrow();
        assertTrue(why.contains("288.720") && why.contains("285.000"), why);
        assertFalse(CAVITIES.misfit(size(44)).isPresent());
    }

    @Test
    void thePatternMeasuredOnTheSampleOutlineIsTheThesissData() throws Exception {
        Contour outline;
        try (Reader r = Files.newBufferedReader(Path.of("samples/sole/men40.contour"))) {
            outline = ContourFile.read(r, "men40.contour").get(0);
        }
        MouldBlock.Pattern p = MouldBlock.Pattern.measured(outline.bounds(), Vec2.of(0, 0));
        // the thesis rounds the drawing's 269.2 / 29.00 / 59.7 to CP 270, DPI 29, XTANP 60
        assertEquals(29.0, p.heelOverhangMm(), 0.01);
        assertEquals(59.72, p.innerReachMm(), 0.01);
        assertEquals(269.23, p.lengthMm(), 0.01);
    }
}
