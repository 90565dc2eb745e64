package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.fresa.cell.RobotTools;
import org.fresa.geom.Transform3;
import org.fresa.io.OutputFolder;
import org.fresa.kin.IkOptions;
import org.fresa.kin.Robots;
import org.fresa.model.CamInputException;
import org.fresa.post.RapidWriter;
import org.fresa.post.RobotProgram;
import org.fresa.robot.RobotPrograms;
import org.fresa.testing.SpecKinematics;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fresa ik}'s acceptance: 2000 random IRB-140 poses made by the spec's own forward
 * kinematics are all solved, to 1e-6 mm and 1e-8 rad by that same forward kinematics, and in the
 * configuration asked.
 */
class IkServiceTest {

    static final double[] MIN = {-180, -90, -230, -200, -120, -400};
    static final double[] MAX = {180, 110, 50, 200, 120, 400};

    @TempDir
    Path dir;

    /** Random joints inside the limits and their poses by the spec's FK, as rows of a targets CSV. */
    static List<double[]> randomJoints(int count) {
        SplittableRandom rnd = new SplittableRandom(20261202L);
        List<double[]> out = new ArrayList<>();
        while (out.size() < count) {
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = MIN[i] + 0.01 * (MAX[i] - MIN[i]) + rnd.nextDouble() * 0.98 * (MAX[i] - MIN[i]);
            }
            // keep away from the wrist singularity (q5 = 0), where the branches merge
            if (Math.abs(q[4]) > 1) {
                out.add(q);
            }
        }
        return out;
    }

    static String row(double[][] t) {
        double roll = Math.toDegrees(Math.atan2(t[1][0], t[0][0]));
        double pitch = Math.toDegrees(Math.atan2(-t[2][0], Math.hypot(t[2][1], t[2][2])));
        double yaw = Math.toDegrees(Math.atan2(t[2][1], t[2][2]));
        return t[0][3] + "," + t[1][3] + "," + t[2][3] + "," + roll + "," + pitch + "," + yaw;
    }

    Path targets(List<double[]> joints, String name) throws IOException {
        StringBuilder sb = new StringBuilder("x,y,z,roll,pitch,yaw\n");
        for (double[] q : joints) {
            sb.append(row(SpecKinematics.irb140(q))).append('\n');
        }
        Path f = dir.resolve(name);
        Files.writeString(f, sb.toString());
        return f;
    }

    List<double[]> solve(Path targets, Map<String, Integer> configuration, String out) throws Exception {
        Path o = dir.resolve(out);
        TaskOutcome r = IkService.run(
                new IkService.Settings(
                        targets,
                        "irb140",
                        RobotTools.Choice.NONE,
                        IkOptions.Method.LEVENBERG_MARQUARDT,
                        1e-7,
                        configuration,
                        false),
                new OutputFolder(o),
                ProgressMonitor.NONE);
        assertEquals(0, r.exitStatus(), () -> String.join("; ", r.problems()));
        List<String> rows = Files.readAllLines(o.resolve("ik.csv"));
        List<String> h = List.of(rows.get(0).split(","));
        List<double[]> solved = new ArrayList<>();
        for (String line : rows.subList(1, rows.size())) {
            String[] c = line.split(",", -1);
            assertEquals("ok", c[h.indexOf("status")], line);
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = Double.parseDouble(c[h.indexOf("q1") + i]);
                assertTrue(q[i] >= MIN[i] && q[i] <= MAX[i], line);
            }
            double[][] asked = SpecKinematics.pose(
                    num(c, h, "x"),
                    num(c, h, "y"),
                    num(c, h, "z"),
                    num(c, h, "roll"),
                    num(c, h, "pitch"),
                    num(c, h, "yaw"));
            double[][] reached = SpecKinematics.irb140(q);
            assertTrue(SpecKinematics.positionError(asked, reached) <= 1e-6, line);
            assertTrue(SpecKinematics.rotationError(asked, reached) <= 1e-8, line);
            solved.add(q);
        }
        return solved;
    }

    @Test
    void everyRandomPoseIsSolvedToTheSpecsForwardKinematics() throws Exception {
        List<double[]> joints = randomJoints(2000);
        assertEquals(2000, solve(targets(joints, "random.csv"), Map.of(), "all").size());
    }

    @Test
    void theConfigurationAskedIsTheConfigurationGiven() throws Exception {
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(Robots.irb140());
        List<List<double[]>> byCfx = new ArrayList<>();
        for (int k = 0; k < 8; k++) {
            byCfx.add(new ArrayList<>());
        }
        for (double[] q : randomJoints(2000)) {
            byCfx.get(cfx(q, arm)).add(q);
        }
        int checked = 0;
        for (int k = 0; k < 8; k++) {
            if (byCfx.get(k).isEmpty()) {
                continue;
            }
            List<double[]> solved = solve(targets(byCfx.get(k), "cfx" + k + ".csv"), Map.of("cfx", k), "cfx" + k);
            assertEquals(byCfx.get(k).size(), solved.size());
            for (double[] q : solved) {
                assertEquals(k, cfx(q, arm));
                checked++;
            }
        }
        assertEquals(2000, checked);
    }

    @Test
    void aBadCellIsNamedWithItsFileAndLine() throws IOException {
        Path f = dir.resolve("bad.csv");
        Files.writeString(f, "x,y,z,roll,pitch,yaw\n1,2,3,0,0,0\n1,2,three,0,0,0\n");
        CamInputException e =
                org.junit.jupiter.api.Assertions.assertThrows(CamInputException.class, () -> IkService.read(f, 6));
        assertEquals(3, e.line().getAsInt());
        assertTrue(
                e.getMessage().contains("bad.csv") && e.getMessage().contains("z: expected a number"), e.getMessage());
    }

    @Test
    void aHeaderWithoutThePoseColumnsIsRefused() throws IOException {
        Path f = dir.resolve("bad.csv");
        Files.writeString(f, "a,b,c\n1,2,3\n");
        CamInputException e =
                org.junit.jupiter.api.Assertions.assertThrows(CamInputException.class, () -> IkService.read(f, 6));
        assertEquals(1, e.line().getAsInt());
        assertTrue(e.getMessage().contains("expected the header x,y,z,roll,pitch,yaw"), e.getMessage());
    }

    @Test
    void anUnknownConfigurationKeyIsRefused() {
        CamInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                CamInputException.class, () -> IkService.parseConfiguration("elbow=up"));
        assertTrue(e.getMessage().contains("--configuration"), e.getMessage());
    }

    static int cfx(double[] q, RapidWriter.ArmGeometry arm) {
        List<Double> v = new ArrayList<>();
        for (double d : q) {
            v.add(d);
        }
        return RapidWriter.confdata(
                        new RobotProgram.Motion(
                                0,
                                "",
                                RobotProgram.MotionType.LINEAR,
                                RobotProgram.PointRole.PART,
                                v,
                                Transform3.IDENTITY,
                                1,
                                0,
                                0,
                                0),
                        arm)
                .cfx();
    }

    private static double num(String[] c, List<String> h, String column) {
        return Double.parseDouble(c[h.indexOf(column)]);
    }
}
