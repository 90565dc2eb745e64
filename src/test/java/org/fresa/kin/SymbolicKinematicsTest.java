package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

class SymbolicKinematicsTest {

    @Test
    void theSymbolicForwardKinematicsOfTheIrb140EvaluatesToTheNumericOne() {
        List<SymbolicKinematics.DhRow> rows =
                SymbolicKinematics.rowsOf(Robots.irb140().chain());
        assertEquals("q2 - 90", rows.get(1).thetaDeg());
        SymbolicKinematics.Result r = SymbolicKinematics.of(rows, false);
        double[] q = {10, 20, 30, 40, 50, 60};
        Transform3 t = Robots.irb140().forward(q);
        double[][] expected = {
            {t.r00(), t.r01(), t.r02(), t.tx()},
            {t.r10(), t.r11(), t.r12(), t.ty()},
            {t.r20(), t.r21(), t.r22(), t.tz()}
        };
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 4; j++) {
                assertEquals(
                        expected[i][j],
                        SymbolicKinematics.evaluate(r.transform().get(i).get(j), q),
                        1e-9,
                        r.transform().get(i).get(j));
            }
        }
        assertTrue(r.transform().get(0).get(3).contains("q1"));
    }

    @Test
    void theSymbolicJacobianOfTheAdeptOneEvaluatesToTheNumericOne() {
        SymbolicKinematics.Result r = SymbolicKinematics.of(
                SymbolicKinematics.rowsOf(Robots.adeptOne().chain()), true);
        double[] q = {30, -45, 100, 20};
        double[][] j = Robots.adeptOne().chain().jacobian(q);
        assertEquals(6, r.jacobian().size());
        for (int row = 0; row < 6; row++) {
            for (int c = 0; c < 4; c++) {
                assertEquals(
                        j[row][c],
                        SymbolicKinematics.evaluate(r.jacobian().get(row).get(c), q),
                        1e-9,
                        row + "," + c + ": " + r.jacobian().get(row).get(c));
            }
        }
    }

    @Test
    void cellsAcceptExpressions() {
        List<SymbolicKinematics.DhRow> rows = List.of(
                new SymbolicKinematics.DhRow("100", "0", "0", "q1 - 90"),
                new SymbolicKinematics.DhRow("50 + 50", "0", "0", "2*q2/2"));
        SymbolicKinematics.Result r = SymbolicKinematics.of(rows, false);
        // q1 = 90, q2 = 90: first link along x (100), second along y (100)
        assertEquals(100, SymbolicKinematics.evaluate(r.transform().get(0).get(3), 90, 90), 1e-9);
        assertEquals(100, SymbolicKinematics.evaluate(r.transform().get(1).get(3), 90, 90), 1e-9);
    }
}
