package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

class ForwardKinematicsTest {

    static final Path REFERENCE = Path.of("samples/robot/irb140-reference-fk.csv");

    /** Rows of the reference: q1..q6 (deg), flange x, y, z (mm), tool axis zx, zy, zz. */
    static List<double[]> referenceRows() throws IOException {
        List<double[]> rows = new ArrayList<>();
        List<String> lines = Files.readAllLines(REFERENCE);
        for (String line : lines.subList(1, lines.size())) {
            if (line.isBlank()) {
                continue;
            }
            String[] p = line.split(",");
            double[] v = new double[p.length];
            for (int i = 0; i < p.length; i++) {
                v[i] = Double.parseDouble(p[i]);
            }
            rows.add(v);
        }
        return rows;
    }

    @Test
    void irb140ReproducesTheRoboticsToolboxReferenceToTenNanometres() throws IOException {
        SerialRobot robot = Robots.irb140();
        List<double[]> rows = referenceRows();
        assertEquals(25, rows.size());
        for (double[] r : rows) {
            double[] q = {r[0], r[1], r[2], r[3], r[4], r[5]};
            Transform3 t = robot.forward(q);
            assertAll(
                    () -> assertEquals(r[6], t.tx(), 1e-8),
                    () -> assertEquals(r[7], t.ty(), 1e-8),
                    () -> assertEquals(r[8], t.tz(), 1e-8),
                    () -> assertEquals(r[9], t.r02(), 1e-10),
                    () -> assertEquals(r[10], t.r12(), 1e-10),
                    () -> assertEquals(r[11], t.r22(), 1e-10));
        }
    }

    @Test
    void irb140AtZeroHasTheFlangeAt515_0_712PointingAlongX() {
        Transform3 t = Robots.irb140().forward(0, 0, 0, 0, 0, 0);
        assertAll(
                () -> assertEquals(515, t.tx(), 1e-12),
                () -> assertEquals(0, t.ty(), 1e-12),
                () -> assertEquals(712, t.tz(), 1e-12),
                () -> assertEquals(1, t.r02(), 1e-15));
    }

    @Test
    void everyBuiltInRobotAgreesWithTheIndependentSpecKinematics() {
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(5);
        for (int k = 0; k < 200; k++) {
            double[] qi = new double[6];
            double[] qa = new double[4];
            double[] qt = new double[6];
            List<JointLimit> li = Robots.irb140().joints();
            for (int i = 0; i < 6; i++) {
                qi[i] = li.get(i).min()
                        + rnd.nextDouble() * (li.get(i).max() - li.get(i).min());
            }
            List<JointLimit> la = Robots.adeptOne().joints();
            for (int i = 0; i < 4; i++) {
                qa[i] = la.get(i).min()
                        + rnd.nextDouble() * (la.get(i).max() - la.get(i).min());
            }
            qt[0] = 1400 + rnd.nextDouble() * 200;
            qt[1] = 1400 + rnd.nextDouble() * 200;
            qt[2] = 1400 + rnd.nextDouble() * 200;
            List<JointLimit> lt = Robots.tricept806().joints();
            for (int i = 3; i < 6; i++) {
                qt[i] = lt.get(i).min()
                        + rnd.nextDouble() * (lt.get(i).max() - lt.get(i).min());
            }
            assertSame(SpecKinematics.irb140(qi), Robots.irb140().forward(qi), 1e-9);
            assertSame(SpecKinematics.adeptOne(qa), Robots.adeptOne().forward(qa), 1e-9);
            assertSame(SpecKinematics.tricept(qt), Robots.tricept806().forward(qt), 1e-8);
        }
    }

    static void assertSame(double[][] m, Transform3 t, double tolMm) {
        assertSame(m, t, tolMm, 1e-11);
    }

    static void assertSame(double[][] m, Transform3 t, double tolMm, double tolR) {
        assertAll(
                () -> assertEquals(m[0][3], t.tx(), tolMm),
                () -> assertEquals(m[1][3], t.ty(), tolMm),
                () -> assertEquals(m[2][3], t.tz(), tolMm),
                () -> assertEquals(m[0][0], t.r00(), tolR),
                () -> assertEquals(m[1][1], t.r11(), tolR),
                () -> assertEquals(m[0][2], t.r02(), tolR),
                () -> assertEquals(m[1][2], t.r12(), tolR),
                () -> assertEquals(m[2][2], t.r22(), tolR),
                () -> assertEquals(m[2][0], t.r20(), tolR));
    }

    @Test
    void theGeometricJacobianMatchesFiniteDifferencesOfTheForwardKinematics() {
        DenavitHartenbergChain c = Robots.irb140().chain();
        double[] q = {10, 20, -30, 40, 50, 60};
        double[][] j = c.jacobian(q);
        Transform3 t0 = c.forward(q);
        for (int i = 0; i < 6; i++) {
            double[] qp = q.clone();
            double hDeg = 1e-6;
            qp[i] += hDeg;
            Transform3 t1 = c.forward(qp);
            double h = Math.toRadians(hDeg);
            assertEquals(j[0][i], (t1.tx() - t0.tx()) / h, 1e-3);
            assertEquals(j[1][i], (t1.ty() - t0.ty()) / h, 1e-3);
            assertEquals(j[2][i], (t1.tz() - t0.tz()) / h, 1e-3);
        }
    }
}
