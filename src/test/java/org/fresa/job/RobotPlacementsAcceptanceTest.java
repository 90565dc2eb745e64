package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.cell.RobotTools;
import org.fresa.io.OutputFolder;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The thesis's placements (its table 5.1) through the whole robot pipeline. */
class RobotPlacementsAcceptanceTest {

    @TempDir
    Path dir;

    /** The thesis placed its parts for a TCP at the flange: a tool length of 0 mm does the same. */
    static List<String[]> run(Path dir, String part, String robot, double x, double y, double z) throws Exception {
        RobotService.run(
                new RobotService.Settings(
                        Path.of("samples/stepnc/" + part),
                        robot,
                        new Placement(x, y, z, 0, 0, 0),
                        new Placement(0, 10, 0, 0, 0, 0),
                        List.of("csv"),
                        new RobotTools.Choice(java.util.Optional.empty(), java.util.OptionalDouble.of(0))),
                new OutputFolder(dir),
                ProgressMonitor.NONE);
        return Files.readAllLines(dir.resolve("trajectory.csv")).stream()
                .skip(1)
                .map(r -> r.split(",", -1))
                .toList();
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            iso14649-11-example1.stp, irb140,     400, -200,   500
            iso14649-11-example1.stp, tricept806,  50,   50, -1900
            example2.stp,             tricept806, 200,  300, -1900
            iso14649-11-example1.stp, adept-one,  300,  300,   745
            """)
    void everyPointIsReachedExactlyWithoutJointJumps(String part, String robot, double x, double y, double z)
            throws Exception {
        List<String[]> rows = run(dir, part, robot, x, y, z);
        String[] header =
                Files.readAllLines(dir.resolve("trajectory.csv")).get(0).split(",");
        List<String> h = List.of(header);
        int n = h.indexOf("reached_x") - h.indexOf("q1");
        double worst = 0;
        double[] prev = null;
        for (String[] c : rows) {
            String status = c[h.indexOf("status")];
            assertTrue(!status.equals("unreachable"), String.join(",", c));
            assertTrue(Double.parseDouble(c[h.indexOf("pos_err_mm")]) <= 1e-6);
            assertTrue(Double.parseDouble(c[h.indexOf("rot_err_rad")]) <= 1e-8);
            double[] q = new double[n];
            for (int i = 0; i < n; i++) {
                q[i] = Double.parseDouble(c[h.indexOf("q1") + i]);
            }
            if (status.equals("ok") && prev != null && !robot.equals("tricept806")) {
                for (int i = 0; i < n; i++) {
                    worst = Math.max(worst, Math.abs(q[i] - prev[i]));
                }
            }
            prev = status.equals("ok") ? q : null;
        }
        assertTrue(worst <= 20, part + " " + robot + ": largest joint step " + worst);
    }

    @Test
    void theAdeptOneReachesTheTopOfExample2AndNotItsSideFaces() throws Exception {
        // the thesis's part-2 top placement (300, 300, 650); the tool axis of a SCARA stays vertical
        List<String[]> rows = run(dir, "example2.stp", "adept-one", 300, 300, 650);
        List<String> h =
                List.of(Files.readAllLines(dir.resolve("trajectory.csv")).get(0).split(","));
        int top = 0;
        int side = 0;
        for (String[] c : rows) {
            double a = Math.toRadians(Double.parseDouble(c[h.indexOf("roll")]));
            double b = Math.toRadians(Double.parseDouble(c[h.indexOf("pitch")]));
            double g = Math.toRadians(Double.parseDouble(c[h.indexOf("yaw")]));
            double zz = Math.cos(b) * Math.cos(g);
            boolean isTop = zz < -0.99;
            String status = c[h.indexOf("status")];
            if (isTop) {
                assertEquals("ok", status);
                top++;
            } else {
                assertEquals("unreachable", status);
                side++;
            }
        }
        assertTrue(top > 100 && side > 100, top + " top, " + side + " side");
    }
}
