package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.model.Placement;
import org.fresa.post.RobotProgram;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 6's acceptance: example 2 on the IRB-140, every format, the same joints everywhere. */
class RobotServiceTest {

    @TempDir
    static Path dir;

    static TaskOutcome outcome;
    static List<double[]> okJoints = new ArrayList<>();
    static int okRows;

    @BeforeAll
    static void runExample2() throws Exception {
        outcome = RobotService.run(new RobotService.Settings(Path.of("samples/stepnc/example2.stp"), "irb140",
                new Placement(450, 0, 350, 0, 0, 0), new Placement(0, 10, 0, 0, 0, 0),
                List.of("csv", "xml", "rapid", "krl", "png")), new OutputFolder(dir), ProgressMonitor.NONE);
        List<String> rows = Files.readAllLines(dir.resolve("trajectory.csv"));
        String[] header = rows.get(0).split(",");
        int q1 = List.of(header).indexOf("q1");
        int status = List.of(header).indexOf("status");
        for (String r : rows.subList(1, rows.size())) {
            String[] c = r.split(",", -1);
            if (!c[status].equals("unreachable")) {
                double[] q = new double[6];
                for (int i = 0; i < 6; i++) {
                    q[i] = Double.parseDouble(c[q1 + i]);
                }
                okJoints.add(q);
                okRows++;
            }
        }
    }

    @Test
    void everyFileIsWritten() {
        for (String f : List.of("toolpath.csv", "trajectory.csv", "summary.json", "program.xml", "program.mod",
                "program.src", "joints.png", "error.png")) {
            assertTrue(Files.isRegularFile(dir.resolve(f)), f);
        }
        assertTrue(okRows > 1000, "rows: " + okRows);
    }

    @Test
    void theXmlHoldsEveryReachablePointsJointsExactly() throws Exception {
        RobotProgram p = RobotProgramXml.read(dir.resolve("program.xml"));
        assertEquals(okRows, p.motions().size());
        for (int i = 0; i < okRows; i++) {
            for (int j = 0; j < 6; j++) {
                assertEquals(okJoints.get(i)[j], p.motions().get(i).joint(j), 0.0, "row " + i);
            }
        }
    }

    @Test
    void rapidAndKrlHaveOneMovePerPointWithTheTrajectoryJoints() throws Exception {
        for (String f : List.of("program.mod", "program.src")) {
            List<double[]> moves = org.fresa.post.RobotProgramWritersTestAccess.jointsIn(Files.readString(dir.resolve(f)));
            assertEquals(okRows, moves.size(), f);
            for (int i = 0; i < okRows; i++) {
                for (int j = 0; j < 6; j++) {
                    assertEquals(okJoints.get(i)[j], moves.get(i)[j], 1e-6, f + " move " + i);
                }
            }
        }
    }
}
