package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

class SphericalWristSeedsTest {

    @Test
    void theClosedFormOfTheIrb140GivesEightExactSolutionsAndOneIsTheOriginal() {
        DenavitHartenbergChain c = Robots.irb140().chain();
        SphericalWristSeeds seeds = SphericalWristSeeds.of(c).orElseThrow();
        SplittableRandom rnd = new SplittableRandom(3);
        for (int k = 0; k < 100; k++) {
            double[] qDeg = {
                -170 + 340 * rnd.nextDouble(),
                -80 + 180 * rnd.nextDouble(),
                -220 + 260 * rnd.nextDouble(),
                -190 + 380 * rnd.nextDouble(),
                -110 + 220 * rnd.nextDouble(),
                -390 + 780 * rnd.nextDouble()
            };
            Transform3 t = c.forward(qDeg);
            double[] target = new double[Pose.SIZE];
            Pose.fromTransform(t, target, 0);
            List<double[]> sols = seeds.solutions(target);
            assertTrue(sols.size() >= 4, "solutions: " + sols.size());
            boolean original = false;
            for (double[] s : sols) {
                double[] d = c.toUser(s);
                double[][] m = SpecKinematics.irb140(d);
                assertEquals(t.tx(), m[0][3], 1e-8);
                assertEquals(t.ty(), m[1][3], 1e-8);
                assertEquals(t.tz(), m[2][3], 1e-8);
                assertEquals(t.r02(), m[0][2], 1e-10);
                assertEquals(t.r10(), m[1][0], 1e-10);
                boolean same = true;
                for (int i = 0; i < 6; i++) {
                    double diff = Math.IEEEremainder(d[i] - qDeg[i], 360);
                    same &= Math.abs(diff) < 1e-6;
                }
                original |= same;
            }
            assertTrue(original, () -> java.util.Arrays.toString(qDeg));
        }
    }

    @Test
    void otherChainsHaveNoClosedForm() {
        assertTrue(SphericalWristSeeds.of(Robots.adeptOne().chain()).isEmpty());
    }
}
