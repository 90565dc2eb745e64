package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class GradingRuleTest {

    private static final double FACTOR = 1e-6;

    /** Mould-mouth data of App. D: VL 1.66, VC 6.66, LP 96, CP 259, NP 35 (seed 6.1). */
    private static GradingRule mouth(double ctm) {
        return new GradingRule(SizeSystem.BR, 35, 6.66, 1.66, 259, 96, ctm, ShrinkageMode.ADDITIVE);
    }

    /** Real sole of App. F: VL 1.66, VC 6.66, LP 90, CP 270, NP 40 (seed 6.3). */
    private static GradingRule sole(double ctm, ShrinkageMode mode) {
        return new GradingRule(SizeSystem.BR, 40, 6.66, 1.66, 270, 90, ctm, mode);
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            30, 0.913542, 0.871429, 87.700, 225.700
            33, 0.965417, 0.948571, 92.680, 245.680
            34, 0.982708, 0.974286, 94.340, 252.340
            35, 1.000000, 1.000000, 96.000, 259.000
            36, 1.017292, 1.025714, 97.660, 265.660
            38, 1.051875, 1.077143, 100.980, 278.980
            40, 1.086458, 1.128571, 104.300, 292.300
            42, 1.121042, 1.180000, 107.620, 305.620
            45, 1.172917, 1.257143, 112.600, 325.600
            """)
    void mouldMouthFactorsMatchTheSeedTable(double nd, double alfa, double beta, double width, double length) {
        ScaleFactors f = mouth(0).factors(nd);
        assertAll(
                () -> assertEquals(alfa, f.alfa(), FACTOR),
                () -> assertEquals(beta, f.beta(), FACTOR),
                () -> assertEquals(width, 96 * f.width(), 1e-3),
                () -> assertEquals(length, 259 * f.length(), 1e-3));
    }

    @Test
    void theThesisCaseSize40FromPattern35HasTheStatedFactorsWithAndWithoutShrinkage() {
        ScaleFactors plain = mouth(0).factors(40);
        ScaleFactors shrunk = mouth(0.02).factors(40);
        assertAll(
                () -> assertEquals(1.086458333, plain.alfa(), 1e-9),
                () -> assertEquals(1.128571429, plain.beta(), 1e-9),
                () -> assertEquals(1.106458333, shrunk.width(), 1e-9),
                () -> assertEquals(1.148571429, shrunk.length(), 1e-9));
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            36, 0.926222, 0.901333, 0.946222, 0.921333, 248.760
            37, 0.944667, 0.926000, 0.964667, 0.946000, 255.420
            38, 0.963111, 0.950667, 0.983111, 0.970667, 262.080
            39, 0.981556, 0.975333, 1.001556, 0.995333, 268.740
            40, 1.000000, 1.000000, 1.020000, 1.020000, 275.400
            41, 1.018444, 1.024667, 1.038444, 1.044667, 282.060
            42, 1.036889, 1.049333, 1.056889, 1.069333, 288.720
            43, 1.055333, 1.074000, 1.075333, 1.094000, 295.380
            44, 1.073778, 1.098667, 1.093778, 1.118667, 302.040
            """)
    void realSoleFactorsWithAdditiveShrinkageMatchTheSeedTable(
            double nd, double alfa, double beta, double alfaCtm, double betaCtm, double cp) {
        ScaleFactors f = sole(0.02, ShrinkageMode.ADDITIVE).factors(nd);
        assertAll(
                () -> assertEquals(alfa, f.alfa(), FACTOR),
                () -> assertEquals(beta, f.beta(), FACTOR),
                () -> assertEquals(alfaCtm, f.width(), FACTOR),
                () -> assertEquals(betaCtm, f.length(), FACTOR),
                () -> assertEquals(cp, 270 * f.length(), 1e-3));
    }

    @Test
    void additiveAndMultiplicativeShrinkageDifferAwayFromThePatternSize() {
        assertAll(
                () -> assertEquals(302.040, sole(0.02, ShrinkageMode.ADDITIVE).lengthMm(44), 1e-3),
                () -> assertEquals(
                        302.573, sole(0.02, ShrinkageMode.MULTIPLICATIVE).lengthMm(44), 1e-3),
                () -> assertEquals(
                        sole(0.02, ShrinkageMode.ADDITIVE).lengthMm(40),
                        sole(0.02, ShrinkageMode.MULTIPLICATIVE).lengthMm(40),
                        1e-12));
    }

    @Test
    void lengthsAndWidthsGrowByTheStepsPerSize() {
        GradingRule r = sole(0, ShrinkageMode.MULTIPLICATIVE);
        for (int n = 30; n <= 50; n++) {
            assertEquals(270 + (n - 40) * 6.66, r.lengthMm(n), 1e-9);
            assertEquals(90 + (n - 40) * 1.66, r.widthMm(n), 1e-9);
        }
    }

    @Test
    void mondopointCountsWholeSizesInTensOfMillimetres() {
        GradingRule r = new GradingRule(SizeSystem.MONDOPOINT, 270, 10, 2.5, 270, 90, 0, ShrinkageMode.MULTIPLICATIVE);
        assertAll(
                () -> assertEquals(280, r.lengthMm(280), 1e-9),
                () -> assertEquals(265, r.lengthMm(265), 1e-9),
                () -> assertEquals(92.5, r.widthMm(280), 1e-9));
    }
}
