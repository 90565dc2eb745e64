package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class DhExpressionTest {

    @Test
    void jointVariableMinusAConstantIsAnOffset() {
        DhExpression e = DhExpression.parse("q2 - 90", 6);
        assertAll(() -> assertEquals(-90, e.constant()), () -> assertEquals(Map.of(2, 1.0), e.coefficients()));
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', textBlock = """
            352;            352
            -90;            -90
            180/2;          90
            -(90 - 45) * 2; -90
            1.5e2 + 0.5;    150.5
            2*(pi/pi)*45;   90
            """)
    void constantsAreEvaluated(String text, double value) {
        DhExpression e = DhExpression.parse(text, 6);
        assertAll(() -> assertTrue(e.isConstant()), () -> assertEquals(value, e.constant(), 1e-12));
    }

    @Test
    void theVariableMayStandAnywhereInTheSum() {
        DhExpression e = DhExpression.parse("180 + (q5 - 360)/1", 6);
        assertAll(() -> assertEquals(-180, e.constant()), () -> assertEquals(1.0, e.coefficient(5)));
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', textBlock = """
            q2*q2;     product of two joint variables
            90/q1;     divide by a joint variable
            q7;        no joint q7
            q2 +;      expected a number
            (q2 - 90;  expected ')'
            theta;     unknown name 'theta'
            90 90;     unexpected '9'
            1/0;       division by zero
            """)
    void badExpressionsSayWhy(String text, String because) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DhExpression.parse(text, 6));
        assertTrue(e.getMessage().contains(because), e.getMessage());
    }

    @Test
    void anEmptyCellIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> DhExpression.parse("  ", 6));
    }
}
