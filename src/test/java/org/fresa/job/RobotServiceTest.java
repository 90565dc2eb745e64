package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.io.OutputFolder;
import org.fresa.model.Placement;
import org.fresa.post.RobotProgram;
import org.fresa.robot.RobotProgramXml;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The robot programs' acceptance: example 2 on the IRB-140, every format, the same joints everywhere. */
class RobotServiceTest {

    @TempDir
    static Path dir;

    static TaskOutcome outcome;
    static List<double[]> okJoints = new ArrayList<>();
    static int okRows;

    @BeforeAll
    static void runExample2() throws Exception {
        outcome = RobotService.run(
                new RobotService.Settings(
                        Path.of("samples/stepnc/example2.stp"),
                        "irb140",
                        new Placement(450, 0, 350, 0, 0, 0),
                        new Placement(0, 10, 0, 0, 0, 0),
                        List.of("csv", "xml", "rapid", "krl", "png")),
                new OutputFolder(dir),
                ProgressMonitor.NONE);
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
        for (String f : List.of(
                "toolpath.csv",
                "trajectory.csv",
                "summary.json",
                "program.xml",
                "program.mod",
                "program.src",
                "joints.png",
                "error.png")) {
            assertTrue(Files.isRegularFile(dir.resolve(f)), f);
        }
        assertTrue(okRows > 1000, "rows: " + okRows);
    }

    @Test
    void example2OnTheIrb140IsReachedExactlyWithoutJointJumps() throws Exception {
        // the trajectory's acceptance: every point reached within the limits, 1e-6 mm, 1e-8 rad, and no
        // jump over 20 deg between neighbouring ok points (relinks happen off the part)
        List<String> rows = Files.readAllLines(dir.resolve("trajectory.csv"));
        List<String> h = List.of(rows.get(0).split(","));
        int q1 = h.indexOf("q1");
        double[] min = {-180, -90, -230, -200, -120, -400};
        double[] max = {180, 110, 50, 200, 120, 400};
        double[] prev = null;
        double worstStep = 0;
        for (String r : rows.subList(1, rows.size())) {
            String[] c = r.split(",", -1);
            String status = c[h.indexOf("status")];
            assertTrue(!status.equals("unreachable"), r);
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = Double.parseDouble(c[q1 + i]);
                assertTrue(q[i] >= min[i] - 1e-9 && q[i] <= max[i] + 1e-9, "joint " + (i + 1) + " in " + r);
            }
            assertTrue(Double.parseDouble(c[h.indexOf("pos_err_mm")]) <= 1e-6, r);
            assertTrue(Double.parseDouble(c[h.indexOf("rot_err_rad")]) <= 1e-8, r);
            if (status.equals("ok")) {
                if (prev != null) {
                    for (int i = 0; i < 6; i++) {
                        worstStep = Math.max(worstStep, Math.abs(q[i] - prev[i]));
                    }
                }
                prev = q;
            } else {
                prev = null;
            }
        }
        assertTrue(worstStep <= 20, "largest joint step between ok points: " + worstStep);
        assertEquals(0, outcome.exitStatus(), String.valueOf(outcome.problems()));
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
            List<double[]> moves =
                    org.fresa.post.RobotProgramWritersTestAccess.jointsIn(Files.readString(dir.resolve(f)));
            assertEquals(okRows, moves.size(), f);
            for (int i = 0; i < okRows; i++) {
                for (int j = 0; j < 6; j++) {
                    assertEquals(okJoints.get(i)[j], moves.get(i)[j], 1e-6, f + " move " + i);
                }
            }
        }
    }

    /** One RAPID move: its workingstep, instruction, zone, confdata and joints (from its comment). */
    record RapidMove(String workingstep, String instruction, String zone, String confdata, double[] joints) {}

    static List<RapidMove> rapidMoves() throws Exception {
        List<RapidMove> out = new ArrayList<>();
        String ws = null;
        java.util.regex.Pattern cf = java.util.regex.Pattern.compile("\\],\\[(-?\\d+,-?\\d+,-?\\d+,-?\\d+)\\],\\[9E");
        java.util.regex.Pattern joints = java.util.regex.Pattern.compile("j=\\[([^\\]]*)\\]");
        for (String line : Files.readAllLines(dir.resolve("program.mod"))) {
            String l = line.trim();
            if (l.startsWith("! workingstep ")) {
                ws = l.substring("! workingstep ".length());
            } else if (l.startsWith("Move")) {
                String[] parts = l.split(",");
                String zone = l.contains(",fine,") ? "fine" : l.contains(",z1,") ? "z1" : "other";
                java.util.regex.Matcher c = cf.matcher(l);
                java.util.regex.Matcher j = joints.matcher(l);
                double[] q = null;
                if (j.find()) {
                    q = java.util.Arrays.stream(j.group(1).split(","))
                            .mapToDouble(Double::parseDouble)
                            .toArray();
                }
                out.add(new RapidMove(ws, l.substring(0, l.indexOf(' ')), zone, c.find() ? c.group(1) : null, q));
                assertTrue(parts.length > 1);
            }
        }
        return out;
    }

    @Test
    void rapidStopsOnlyAtTheEndsOfWorkingstepsAndAtRelinks() throws Exception {
        List<RapidMove> moves = rapidMoves();
        int blended = 0;
        for (int i = 0; i + 1 < moves.size(); i++) {
            RapidMove a = moves.get(i);
            RapidMove b = moves.get(i + 1);
            boolean insideAWorkingstep = a.instruction().equals("MoveL")
                    && b.instruction().equals("MoveL")
                    && a.workingstep().equals(b.workingstep());
            if (insideAWorkingstep) {
                assertEquals("z1", a.zone(), "move " + i + " of " + a.workingstep());
                blended++;
            }
        }
        assertTrue(blended > 4000, "blended moves: " + blended);
    }

    @Test
    void theConfdataNeverFlipsBetweenNeighbouringMovesWithinADegree() throws Exception {
        List<RapidMove> moves = rapidMoves();
        int compared = 0;
        for (int i = 0; i + 1 < moves.size(); i++) {
            RapidMove a = moves.get(i);
            RapidMove b = moves.get(i + 1);
            if (a.confdata() == null || b.confdata() == null) {
                continue;
            }
            double d = 0;
            for (int j = 0; j < 6; j++) {
                d = Math.max(d, Math.abs(a.joints()[j] - b.joints()[j]));
            }
            if (d < 1) {
                assertEquals(a.confdata(), b.confdata(), "moves " + i + " and " + (i + 1));
                compared++;
            }
        }
        assertTrue(compared > 3000, "neighbours within a degree: " + compared);
    }
}
