package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The thesis's Appendix C targets (robot base frame) solved by each robot, checked with the
 * independent forward kinematics of {@link SpecKinematics}.
 */
class AppendixCTest {

    static final Path CSV = Path.of("samples/robot/thesis-appendix-c.csv");

    /**
     * The targets of one table, with the tool axis by the thesis's conventions: down on the top
     * face; on part 2 (6-axis robots) +y on the XZ face (points 1016-2257) and +x on the ZY face
     * (2258-3106), into the material. The Adept One always holds the tool vertical (the thesis
     * turned the part instead).
     */
    static List<ToolTarget> targets(String table, boolean sixAxis) throws IOException {
        List<ToolTarget> out = new ArrayList<>();
        for (String line : Files.readAllLines(CSV)) {
            String[] p = line.split(",");
            if (!p[0].equals(table)) {
                continue;
            }
            int point = Integer.parseInt(p[1]);
            Vec3 pos = new Vec3(Double.parseDouble(p[5]), Double.parseDouble(p[6]), Double.parseDouble(p[7]));
            Vec3 axis = new Vec3(0, 0, -1);
            if (sixAxis && table.contains("ex2") && point >= 1016 && point <= 2257) {
                axis = Vec3.UNIT_Y;
            } else if (sixAxis && table.contains("ex2") && point >= 2258) {
                axis = Vec3.UNIT_X;
            }
            out.add(ToolTarget.of("C" + point, pos, axis));
        }
        return out;
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            C.0.1 ex1 Adept One,    adept-one,  LEVENBERG_MARQUARDT
            C.0.2 ex1 ABB IRB-140,  irb140,     LEVENBERG_MARQUARDT
            C.0.3 ex1 Tricept 806,  tricept806, LEVENBERG_MARQUARDT
            C.0.4 ex2 Adept One,    adept-one,  LEVENBERG_MARQUARDT
            C.0.5 ex2 ABB IRB-140,  irb140,     LEVENBERG_MARQUARDT
            C.0.6 ex2 Tricept 806,  tricept806, LEVENBERG_MARQUARDT
            C.0.2 ex1 ABB IRB-140,  irb140,     THESIS_DLS
            C.0.5 ex2 ABB IRB-140,  irb140,     THESIS_DLS
            C.0.4 ex2 Adept One,    adept-one,  THESIS_DLS
            C.0.6 ex2 Tricept 806,  tricept806, THESIS_DLS
            """)
    void everyAppendixCTargetIsReachedWithinTheLimitsToANanometre(
            String table, String robotName, IkOptions.Method method) throws IOException {
        Robot robot = Robots.byName(robotName).orElseThrow();
        List<ToolTarget> targets = targets(table, robot.controlsFullOrientation());
        assertEquals(39, targets.size());
        IkOptions ik = method == IkOptions.Method.THESIS_DLS ? IkOptions.THESIS : IkOptions.DEFAULT;
        TrajectorySolver.Result r =
                new TrajectorySolver(robot, TrajectorySolver.Options.DEFAULT.withIk(ik)).solve(targets, null);
        assertEquals(0, r.unreachable(), () -> table + " " + r.notes());
        TrajectoryPoint previousOk = null;
        for (TrajectoryPoint p : r.points()) {
            double[] q = p.q();
            for (int i = 0; i < q.length; i++) {
                JointLimit l = robot.joints().get(i);
                assertTrue(l.contains(q[i], 0), () -> p + " joint out of limits");
            }
            double[][] m = switch (robotName) {
                case "irb140" -> SpecKinematics.irb140(q);
                case "adept-one" -> SpecKinematics.adeptOne(q);
                default -> SpecKinematics.tricept(q);
            };
            Transform3 t = p.target();
            double pos = Math.sqrt(
                    Math.pow(m[0][3] - t.tx(), 2) + Math.pow(m[1][3] - t.ty(), 2) + Math.pow(m[2][3] - t.tz(), 2));
            Transform3 reached = new Transform3(
                    m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2], m[0][3], m[1][3],
                    m[2][3]);
            assertTrue(pos <= 1e-6, () -> p.label() + " position error " + pos);
            assertTrue(
                    t.rotationAngleTo(reached) <= 1e-8,
                    () -> p.label() + " rotation error " + t.rotationAngleTo(reached));
            assertTrue(p.posErrMm() <= 1e-6 && p.rotErrRad() <= 1e-8);
            // continuity is the default solver's promise; the thesis's method falls back to its five
            // guesses when the warm start fails and may land in another configuration
            if (ik == IkOptions.DEFAULT
                    && p.status() == TrajectoryPoint.Status.OK
                    && previousOk != null
                    && robot instanceof SerialRobot) {
                for (int i = 0; i < q.length; i++) {
                    if (robot.joints().get(i).type() == JointType.REVOLUTE) {
                        assertTrue(Math.abs(q[i] - previousOk.q()[i]) <= 20, () -> "jump at " + p.label());
                    }
                }
            }
            if (p.status() == TrajectoryPoint.Status.OK) {
                previousOk = p;
            }
            if (p.status() != TrajectoryPoint.Status.OK) {
                previousOk = p.status() == TrajectoryPoint.Status.RELINK ? null : previousOk;
            }
        }
    }
}
