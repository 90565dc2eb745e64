package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The thesis's worked ESCOM examples (seed 004 section 6), reproduced from its listings. */
class EscomPatternTest {

    private static final double MM = 1e-3;
    private static final GradingFrame THESIS = GradingFrame.alongY(Vec2.ZERO);

    private static EscomPattern mouth40(double ctm) {
        GradingRule r = new GradingRule(SizeSystem.BR, 35, 6.66, 1.66, 259, 96, ctm, ShrinkageMode.ADDITIVE);
        return ThesisPatterns.mouldMouth35().graded(PantographMap.of(THESIS, r.factors(40)));
    }

    private static EscomPattern sole(double nd, double ctm) {
        GradingRule r = new GradingRule(SizeSystem.BR, 40, 6.66, 1.66, 270, 90, ctm, ShrinkageMode.ADDITIVE);
        return ThesisPatterns.sole40().graded(PantographMap.of(THESIS, r.factors(nd)));
    }

    @ParameterizedTest(name = "P{0}")
    @CsvSource(textBlock = """
            1, -31.5073, -23.7000, -32.0873, -24.1200
            2, 29.3344, -25.9571, 29.8744, -26.4171
            3, 36.9396, -6.7714, 37.6196, -6.8914
            4, 36.9396, 15.8000, 37.6196, 16.0800
            5, 33.6802, 49.6571, 34.3002, 50.5371
            6, 45.6313, 107.2143, 46.4712, 109.1143
            7, 56.4958, 123.5786, 57.5358, 125.7686
            8, 67.3604, 162.5143, 68.6004, 165.3943
            9, 67.3604, 174.9286, 68.6004, 178.0286
            10, 54.3229, 227.9714, 55.3229, 232.0114
            11, 51.0635, 232.4857, 52.0035, 236.6057
            12, 44.5448, 242.6429, 45.3648, 246.9429
            13, 15.7536, 247.1571, 16.0436, 251.5371
            14, 8.6917, 240.3857, 8.8517, 244.6457
            15, 4.3458, 237.0000, 4.4258, 241.2000
            16, -34.5494, 168.1571, -35.1854, 171.1371
            17, -37.4828, 156.8714, -38.1728, 159.6514
            18, -38.5693, 106.0857, -39.2793, 107.9657
            19, -36.9396, 38.3714, -37.6196, 39.0514
            20, -38.5693, 4.5143, -39.2793, 4.5943
            21, 0.0000, -40.6286, 0.0000, -41.3486
            22, 34.7667, -16.9286, 35.4067, -17.2286
            23, 37.5915, 4.5143, 38.2835, 4.5943
            24, 34.7667, 77.8714, 35.4067, 79.2514
            25, 64.1010, 141.0714, 65.2810, 143.5714
            26, 63.0146, 203.1429, 64.1746, 206.7429
            27, 30.4208, 251.4457, 30.9808, 255.9017
            28, -20.6427, 202.0143, -21.0227, 205.5943
            29, -39.9817, 129.7857, -40.7177, 132.0857
            30, -36.3964, 71.1000, -37.0664, 72.3600
            31, -36.9396, -11.2857, -37.6196, -11.4857
            """)
    void theMouldMouthsThirtyOnePointsGradeToSize40AsInTheSeed(int n, double x0, double y0, double x2, double y2) {
        Vec2 plain = mouth40(0).point("P" + n);
        Vec2 shrunk = mouth40(0.02).point("P" + n);
        // the seed rounds to 4 decimals
        assertAll(
                () -> assertEquals(x0, plain.x(), 6e-5),
                () -> assertEquals(y0, plain.y(), 6e-5),
                () -> assertEquals(x2, shrunk.x(), 6e-5),
                () -> assertEquals(y2, shrunk.y(), 6e-5));
    }

    @ParameterizedTest(name = "C{0}")
    @CsvSource(textBlock = """
            1, 0, -0.291, -3.385, 37.244, -0.296, -3.405, 37.945, true
            2, 1, 5.213, -5.295, 31.761, 5.343, -5.387, 32.312, true
            3, 2, -60.428, 4.514, 98.019, -61.406, 4.594, 99.689, true
            4, 4, 127.639, 60.167, 94.545, 129.869, 61.233, 96.166, false
            5, 6, -11.472, 163.528, 78.839, -11.588, 166.428, 80.195, true
            6, 8, -81.741, 166.404, 149.344, -83.060, 169.351, 151.908, true
            7, 11, 28.133, 232.043, 19.537, 28.651, 236.134, 19.905, true
            8, 14, 131.584, 119.703, 173.055, 133.851, 121.799, 176.089, true
            9, 16, 128.276, 127.921, 168.268, 130.407, 130.188, 171.136, true
            10, 17, -467.480, 61.886, 431.182, -475.494, 62.983, 438.528, false
            11, 19, 9.047, 1.442, 47.715, 9.156, 1.468, 48.536, true
            """)
    void theMouldMouthsThreePointCirclesAtSize40MatchTheSeed(
            int circle,
            int element,
            double cx0,
            double cy0,
            double r0,
            double cx2,
            double cy2,
            double r2,
            boolean ccw) {
        Arc2 plain = (Arc2) mouth40(0).toContour().get(element);
        Arc2 shrunk = (Arc2) mouth40(0.02).toContour().get(element);
        assertAll(
                () -> assertEquals(cx0, plain.center().x(), MM),
                () -> assertEquals(cy0, plain.center().y(), MM),
                () -> assertEquals(r0, plain.radius(), MM),
                () -> assertEquals(cx2, shrunk.center().x(), MM),
                () -> assertEquals(cy2, shrunk.center().y(), MM),
                () -> assertEquals(r2, shrunk.radius(), MM),
                () -> assertEquals(ccw, plain.ccw()));
    }

    @Test
    void theFixedRadiusCirclesPickTheSeedsCentresAndKeepRadius25() {
        Contour plain = mouth40(0).toContour();
        Contour shrunk = mouth40(0.02).toContour();
        Arc2 c12 = (Arc2) plain.get(9);
        Arc2 c13 = (Arc2) plain.get(13);
        assertAll(
                () -> assertEquals(72.836, c12.center().x(), MM),
                () -> assertEquals(244.772, c12.center().y(), MM),
                () -> assertEquals(-8.752, c13.center().x(), MM),
                () -> assertEquals(258.294, c13.center().y(), MM),
                () -> assertEquals(25, c12.radius(), 1e-9),
                () -> assertEquals(25, c13.radius(), 1e-9),
                () -> assertEquals(5.568, c12.start().distance(c12.end()), MM),
                () -> assertEquals(5.509, c13.start().distance(c13.end()), MM),
                () -> assertEquals(73.797, ((Arc2) shrunk.get(9)).center().x(), MM),
                () -> assertEquals(248.855, ((Arc2) shrunk.get(9)).center().y(), MM),
                () -> assertEquals(-8.622, ((Arc2) shrunk.get(13)).center().x(), MM),
                () -> assertEquals(262.525, ((Arc2) shrunk.get(13)).center().y(), MM));
    }

    @Test
    void theMouldMouthPatternIsAbout259LongAsTheThesisSays() {
        Box2 b = ThesisPatterns.mouldMouth35().toContour().bounds();
        assertAll(
                () -> assertEquals(-36.809, b.minX(), MM),
                () -> assertEquals(62.000, b.maxX(), MM),
                () -> assertEquals(-36.001, b.minY(), MM),
                () -> assertEquals(222.924, b.maxY(), MM),
                () -> assertTrue(ThesisPatterns.mouldMouth35().toContour().isCcw()));
    }

    @ParameterizedTest(name = "P{0}")
    @CsvSource(textBlock = """
            1, -22.4400, -19.3800, -23.2516, -20.3173, -21.6284, -18.4427
            2, 22.4400, -19.3800, 23.2516, -20.3173, 21.6284, -18.4427
            3, 32.6400, 12.2400, 33.8204, 12.8320, 31.4596, 11.6480
            5, 33.6600, 138.7200, 34.8773, 145.4293, 32.4427, 132.0107
            8, -12.2400, 241.7400, -12.6827, 253.4320, -11.7973, 230.0480
            9, -47.9400, 233.5800, -49.6738, 244.8773, -46.2062, 222.2827
            10, -60.1800, 168.3000, -62.3564, 176.4400, -58.0036, 160.1600
            11, -48.9600, 133.6200, -50.7307, 140.0827, -47.1893, 127.1573
            16, -32.6400, 10.2000, -33.8204, 10.6933, -31.4596, 9.7067
            17, 0.0000, -29.5800, 0.0000, -31.0107, 0.0000, -28.1493
            23, -33.6600, 243.7800, -34.8773, 255.5707, -32.4427, 231.9893
            24, -59.1600, 200.9400, -61.2996, 210.6587, -57.0204, 191.2213
            26, -19.3800, 85.6800, -20.0809, 89.8240, -18.6791, 81.5360
            28, -29.5800, -7.1400, -30.6498, -7.4853, -28.5102, -6.7947
            """)
    void theRealSolesPointsGradeToSizes40And42And38AsInTheSeed(
            int n, double x40, double y40, double x42, double y42, double x38, double y38) {
        Vec2 p40 = sole(40, 0.02).point("P" + n);
        Vec2 p42 = sole(42, 0.02).point("P" + n);
        Vec2 p38 = sole(38, 0.02).point("P" + n);
        assertAll(
                () -> assertEquals(x40, p40.x(), 6e-5),
                () -> assertEquals(y40, p40.y(), 6e-5),
                () -> assertEquals(x42, p42.x(), 6e-5),
                () -> assertEquals(y42, p42.y(), 6e-5),
                () -> assertEquals(x38, p38.x(), 6e-5),
                () -> assertEquals(y38, p38.y(), 6e-5));
    }

    @ParameterizedTest(name = "C{0}")
    @CsvSource(textBlock = """
            1, 0, 0.000, 0.200, 29.200, 0.000, 0.204, 29.784, 0.000, -0.385, 30.626, 0.000, 0.800, 28.950, true
            2, 1, -12.789, 9.335, 44.868, -13.044, 9.522, 45.765, -14.428, 9.955, 48.334, -11.672, 9.088, 43.207, true
            3, 2, 782.583, 59.500, 752.085, 798.235, 60.690, 767.127, 845.914, 63.625, 813.680, 750.785, 57.755, 720.801, false
            4, 4, -80.083, 143.179, 113.310, -81.684, 146.043, 115.576, -87.365, 153.109, 122.484, -76.036, 138.977, 108.702, true
            5, 5, -98.346, 141.962, 130.943, -100.313, 144.801, 133.562, -106.329, 152.061, 140.741, -94.326, 137.537, 126.414, true
            6, 6, -52.750, 173.250, 75.661, -53.805, 176.715, 77.174, -56.402, 185.912, 80.439, -51.216, 167.510, 73.924, true
            7, 7, -24.895, 212.853, 27.374, -25.393, 217.110, 27.922, -26.320, 228.146, 28.729, -24.466, 206.068, 27.121, true
            8, 8, 50.500, 177.594, 110.222, 51.510, 181.146, 112.426, 55.937, 189.912, 119.058, 47.115, 172.379, 105.826, true
            9, 9, -1.453, 164.839, 57.547, -1.482, 168.135, 58.698, -0.333, 176.235, 62.023, -2.616, 160.036, 55.387, true
            10, 11, -65.365, 79.118, 46.621, -66.672, 80.700, 47.554, -70.151, 84.596, 50.343, -63.207, 76.805, 44.778, false
            11, 13, 18.250, 24.205, 50.851, 18.615, 24.689, 51.868, 20.500, 25.885, 54.956, 16.745, 23.492, 48.795, true
            12, 15, 12.307, 9.054, 44.317, 12.553, 9.235, 45.204, 13.900, 9.651, 47.731, 11.218, 8.820, 42.687, true
            """)
    void theRealSolesCirclesAtSizes38To42MatchTheSeed(
            int circle,
            int element,
            double cx,
            double cy,
            double r,
            double cx40,
            double cy40,
            double r40,
            double cx42,
            double cy42,
            double r42,
            double cx38,
            double cy38,
            double r38,
            boolean ccw) {
        Arc2 base = (Arc2) sole(40, 0).toContour().get(element);
        Arc2 a40 = (Arc2) sole(40, 0.02).toContour().get(element);
        Arc2 a42 = (Arc2) sole(42, 0.02).toContour().get(element);
        Arc2 a38 = (Arc2) sole(38, 0.02).toContour().get(element);
        // centres far from their arcs (C3, R 750) move by 1e-3 for a 1e-6 change of a point, so
        // the seed's 3-decimal centres are compared at 2e-3 there
        double tol = r > 500 ? 2e-3 : MM;
        assertAll(
                () -> assertEquals(cx, base.center().x(), tol),
                () -> assertEquals(cy, base.center().y(), tol),
                () -> assertEquals(r, base.radius(), tol),
                () -> assertEquals(cx40, a40.center().x(), tol),
                () -> assertEquals(cy40, a40.center().y(), tol),
                () -> assertEquals(r40, a40.radius(), tol),
                () -> assertEquals(cx42, a42.center().x(), tol),
                () -> assertEquals(cy42, a42.center().y(), tol),
                () -> assertEquals(r42, a42.radius(), tol),
                () -> assertEquals(cx38, a38.center().x(), tol),
                () -> assertEquals(cy38, a38.center().y(), tol),
                () -> assertEquals(r38, a38.radius(), tol),
                () -> assertEquals(ccw, base.ccw()));
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            40, 0.00, -59.722, 33.228, -29.000, 240.227
            40, 0.02, -60.916, 33.892, -29.580, 245.032
            42, 0.02, -63.121, 35.118, -31.011, 256.875
            38, 0.02, -58.711, 32.666, -28.149, 233.189
            """)
    void theRealSolesExtentsMatchTheSeed(double nd, double ctm, double minX, double maxX, double minY, double maxY) {
        Box2 b = sole(nd, ctm).toContour().bounds();
        assertAll(
                () -> assertEquals(minX, b.minX(), MM),
                () -> assertEquals(maxX, b.maxX(), MM),
                () -> assertEquals(minY, b.minY(), MM),
                () -> assertEquals(maxY, b.maxY(), MM));
    }

    /**
     * Seed 6.3's tangent kinks at the base size. Our exact values differ from the seed's by up
     * to 0.04 degrees (C7 to C8: 8.347 here, 8.38 in the seed; C1 to C2: 1.95 against 1.98): the
     * seed most likely took the tangents from its 3-decimal centres. The circles themselves agree
     * to 1e-3 mm, so the test allows 0.05 degrees.
     */
    @ParameterizedTest
    @CsvSource(textBlock = """
            0, 1.98
            1, 0.22
            2, 1.64
            3, -1.65
            4, -2.30
            5, -0.78
            6, 4.51
            7, 8.38
            8, -6.70
            9, 3.80
            10, -3.09
            11, 1.30
            12, -1.46
            13, -1.00
            14, -3.82
            15, 1.87
            """)
    void theRealSoleKeepsTheSeedsTangentKinksAtTheBaseSize(int element, double kinkDeg) {
        Contour c = sole(40, 0).toContour();
        Curve2 a = c.get(element);
        Curve2 b = c.get((element + 1) % c.size());
        double kink = Math.toDegrees(Math.atan2(
                a.endTangent().cross(b.startTangent()), a.endTangent().dot(b.startTangent())));
        assertEquals(kinkDeg, kink, 0.05);
    }
}
