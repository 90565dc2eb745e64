package org.fresa.grading;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Vec2;
import org.fresa.grading.EscomPattern.Circle3;
import org.fresa.grading.EscomPattern.CircleR;
import org.fresa.grading.EscomPattern.Element;
import org.fresa.grading.EscomPattern.Line;
import org.fresa.grading.ThreePointArcs.CenterChoice;

/** The thesis's two patterns, point for point from its listings (seed 004, sections 3.6 and 6.3). */
final class ThesisPatterns {
    private ThesisPatterns() {}

    /** Mould mouth, pattern No. 35 (App. D, Fig. d.4): 31 points, 7 lines, 13 circles. */
    static EscomPattern mouldMouth35() {
        double[][] p = {
            {-29, -21},
            {27, -23},
            {34, -6},
            {34, 14},
            {31, 44},
            {42, 95},
            {52, 109.5},
            {62, 144},
            {62, 155},
            {50, 202},
            {47, 206},
            {41, 215},
            {14.5, 219},
            {8, 213},
            {4, 210},
            {-31.8, 149},
            {-34.5, 139},
            {-35.5, 94},
            {-34, 34},
            {-35.5, 4},
            {0, -36},
            {32, -15},
            {34.6, 4},
            {32, 69},
            {59, 125},
            {58, 180},
            {28, 222.8},
            {-19, 179},
            {-36.8, 115},
            {-33.5, 63},
            {-34, -10},
        };
        List<Element> path = List.of(
                c3(1, 21, 2),
                c3(2, 22, 3),
                c3(3, 23, 4),
                line(4, 5),
                c3(5, 24, 6),
                line(6, 7),
                c3(7, 25, 8),
                line(8, 9),
                c3(9, 26, 10),
                new CircleR("P10", "P11", 25, CenterChoice.XLARGE),
                line(11, 12),
                c3(12, 27, 13),
                line(13, 14),
                new CircleR("P14", "P15", 25, CenterChoice.XSMALL),
                c3(15, 28, 16),
                line(16, 17),
                c3(17, 29, 18),
                c3(18, 30, 19),
                line(19, 20),
                c3(20, 31, 1));
        return new EscomPattern(points(p), path);
    }

    /** The real sole, pattern No. 40 (App. F): 28 points, 4 lines, 12 circles. */
    static EscomPattern sole40() {
        double[][] p = {
            {-22, -19},
            {22, -19},
            {32, 12},
            {32, 107},
            {33, 136},
            {26, 183},
            {11, 214},
            {-12, 237},
            {-47, 229},
            {-59, 165},
            {-48, 131},
            {-28, 107},
            {-22, 62},
            {-29, 43},
            {-32.5, 21},
            {-32, 10},
            {0, -29},
            {29, -7},
            {30.5, 61},
            {32.5, 156},
            {20, 198},
            {0.5, 227},
            {-33, 239},
            {-58, 197},
            {-56, 146.5},
            {-19, 84},
            {-32, 32},
            {-29, -7},
        };
        List<Element> path = List.of(
                c3(1, 17, 2),
                c3(2, 18, 3),
                c3(3, 19, 4),
                line(4, 5),
                c3(5, 20, 6),
                c3(6, 21, 7),
                c3(7, 22, 8),
                c3(8, 23, 9),
                c3(9, 24, 10),
                c3(10, 25, 11),
                line(11, 12),
                c3(12, 26, 13),
                line(13, 14),
                c3(14, 27, 15),
                line(15, 16),
                c3(16, 28, 1));
        return new EscomPattern(points(p), path);
    }

    private static Map<String, Vec2> points(double[][] p) {
        Map<String, Vec2> m = new LinkedHashMap<>();
        for (int i = 0; i < p.length; i++) {
            m.put("P" + (i + 1), new Vec2(p[i][0], p[i][1]));
        }
        return m;
    }

    private static Line line(int a, int b) {
        return new Line("P" + a, "P" + b);
    }

    private static Circle3 c3(int a, int m, int b) {
        return new Circle3("P" + a, "P" + m, "P" + b);
    }
}
