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
    void theSolutionsWithinTheLimitsAreThoseOfAllSolutionsWithinTheLimitsInTheirOrder() {
        DenavitHartenbergChain c = Robots.irb140().chain();
        SphericalWristSeeds seeds = SphericalWristSeeds.of(c).orElseThrow();
        SplittableRandom rnd = new SplittableRandom(5);
        int kept = 0;
        int dropped = 0;
        for (int k = 0; k < 500; k++) {
            // poses about the arm, some out of reach, many with solutions out of the limits
            Transform3 t = Transform3.translation(
                            -900 + 1800 * rnd.nextDouble(),
                            -900 + 1800 * rnd.nextDouble(),
                            -300 + 1300 * rnd.nextDouble())
                    .times(Transform3.rotZ(360 * rnd.nextDouble()))
                    .times(Transform3.rotX(360 * rnd.nextDouble()));
            double[] target = new double[Pose.SIZE];
            Pose.fromTransform(t, target, 0);
            List<double[]> expected = new java.util.ArrayList<>();
            List<double[]> all = seeds.solutions(target, false);
            for (double[] s : all) {
                boolean in = true;
                for (int i = 0; i < 6; i++) {
                    in &= s[i] >= c.qMin[i] - 1e-9 && s[i] <= c.qMax[i] + 1e-9;
                }
                if (in) {
                    expected.add(s);
                }
            }
            List<double[]> within = seeds.solutionsWithinLimits(target, 1e-9);
            assertEquals(expected.size(), within.size());
            for (int i = 0; i < within.size(); i++) {
                assertTrue(java.util.Arrays.equals(expected.get(i), within.get(i)));
            }
            kept += within.size();
            dropped += all.size() - within.size();
        }
        assertTrue(kept > 100 && dropped > 100, kept + " kept, " + dropped + " dropped");
    }

    @Test
    void otherChainsHaveNoClosedForm() {
        assertTrue(SphericalWristSeeds.of(Robots.adeptOne().chain()).isEmpty());
    }
}
