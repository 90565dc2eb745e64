package org.fresa.grading;

import java.util.List;
import java.util.OptionalDouble;

/**
 * The thesis's size-system comparison (Ahrens 1986, table 3.2), copied as data: one row per
 * line of the table, a missing entry ("—") as an empty value. In the table Brazilian = French - 2
 * and American = English + 1 1/2; French 40, 42 and 44 have no English equivalent.
 */
public final class SizeTable {

    /** One line of table 3.2. */
    public record Row(
            OptionalDouble american, OptionalDouble english, OptionalDouble french, OptionalDouble brazilian) {}

    private static final double NONE = Double.NaN;

    private static final double[][] TABLE_3_2 = {
        {7, 5.5, 38, 36},
        {7.5, 6, 39, 37},
        {8, 6.5, NONE, NONE},
        {NONE, NONE, 40, 38},
        {8.5, 7, NONE, NONE},
        {9, 7.5, 41, 39},
        {9.5, 8, NONE, NONE},
        {NONE, NONE, 42, 40},
        {10, 8.5, NONE, NONE},
        {10.5, 9, 43, 41},
        {11, 9.5, NONE, NONE},
        {NONE, NONE, 44, 42},
        {11.5, 10, NONE, NONE},
        {12, 10.5, 45, 43},
        {12.5, 11, NONE, NONE},
        {13, 11.5, NONE, NONE},
    };

    private SizeTable() {}

    /** The rows of table 3.2 in the thesis's order. */
    public static List<Row> thesisTable32() {
        return java.util.Arrays.stream(TABLE_3_2)
                .map(r -> new Row(opt(r[0]), opt(r[1]), opt(r[2]), opt(r[3])))
                .toList();
    }

    private static OptionalDouble opt(double d) {
        return Double.isNaN(d) ? OptionalDouble.empty() : OptionalDouble.of(d);
    }
}
