package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.cell.RobotTools;
import org.fresa.io.OutputFolder;
import org.fresa.model.Placement;
import org.fresa.robot.RobotProgramXml;
import org.fresa.testing.SpecKinematics;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Example 2 on the IRB-140 with a spindle 150 mm beyond the flange and a 50 mm tool: every row's
 * joints put the 200 mm tool's tip on the target by the spec's own forward kinematics.
 */
class RobotToolFramesTest {

    @TempDir
    static Path dir;

    static TaskOutcome outcome;

    @BeforeAll
    static void runExample2() throws Exception {
        outcome = RobotService.run(
                new RobotService.Settings(
                        Path.of("samples/stepnc/example2.stp"),
                        "irb140",
                        new Placement(450, 0, 350, 0, 0, 0),
                        new Placement(0, 10, 0, 0, 0, 0),
                        List.of("csv", "rapid", "krl", "xml"),
                        new RobotTools.Choice(Optional.of(new Placement(0, 0, 150, 0, 0, 0)), OptionalDouble.of(50))),
                new OutputFolder(dir),
                ProgressMonitor.NONE);
    }

    @Test
    void theSpecsForwardKinematicsPlusTheToolLandsOnEveryTarget() throws Exception {
        List<String> rows = Files.readAllLines(dir.resolve("trajectory.csv"));
        List<String> h = List.of(rows.get(0).split(","));
        int solved = 0;
        double worst = 0;
        for (String r : rows.subList(1, rows.size())) {
            String[] c = r.split(",", -1);
            if (c[h.indexOf("status")].equals("unreachable")) {
                continue;
            }
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = Double.parseDouble(c[h.indexOf("q1") + i]);
            }
            double[][] flange = SpecKinematics.irb140(q);
            double[][] tip = SpecKinematics.times(flange, SpecKinematics.tz(200));
            double[][] target = SpecKinematics.pose(
                    num(c, h, "x"),
                    num(c, h, "y"),
                    num(c, h, "z"),
                    num(c, h, "roll"),
                    num(c, h, "pitch"),
                    num(c, h, "yaw"));
            worst = Math.max(worst, SpecKinematics.positionError(tip, target));
            assertTrue(SpecKinematics.rotationError(tip, target) <= 1e-8, r);
            assertEquals(flange[0][3], num(c, h, "flange_x"), 1e-6, r);
            assertEquals(flange[1][3], num(c, h, "flange_y"), 1e-6, r);
            assertEquals(flange[2][3], num(c, h, "flange_z"), 1e-6, r);
            solved++;
        }
        assertTrue(solved > 4000, "rows with joints: " + solved);
        assertTrue(worst <= 1e-6, "largest tip error " + worst + " mm");
    }

    @Test
    void theRapidToolDataHoldTheSpindleAndTheTool() throws Exception {
        String mod = Files.readString(dir.resolve("program.mod"));
        assertTrue(
                mod.contains("PERS tooldata tFresa1 := [TRUE,[[0.000,0.000,200.000],[1.00000000,"),
                mod.substring(0, 400));
        assertTrue(mod.contains(",tFresa1\\WObj:=wFresa;"));
        String src = Files.readString(dir.resolve("program.src"));
        assertTrue(src.contains("TOOL_DATA[1] = {X 0.000,Y 0.000,Z 200.000,A 0.000000,B 0.000000,C 0.000000}"));
        assertTrue(src.contains("$TOOL = TOOL_DATA[1]"));
    }

    @Test
    void theOfflineProgramNamesEachMotionsTool() throws Exception {
        org.fresa.post.RobotProgram p = RobotProgramXml.read(dir.resolve("program.xml"));
        assertEquals(200, p.toolOf(p.motions().get(0).workingstep()).tcp().tz(), 0);
    }

    @Test
    void noSpindleIsSaidOnce() {
        assertTrue(outcome.problems().stream().noneMatch(s -> s.equals(RobotTools.NO_SPINDLE)));
    }

    private static double num(String[] c, List<String> h, String column) {
        return Double.parseDouble(c[h.indexOf(column)]);
    }

    @Test
    void theSummaryGivesTheErrorPerAxisAsTheThesisTable() {
        @SuppressWarnings("unchecked")
        java.util.Map<String, Object> axes =
                (java.util.Map<String, Object>) outcome.summary().get("error_per_axis");
        assertEquals(List.of("x_mm", "y_mm", "z_mm", "rx_rad", "ry_rad", "rz_rad"), List.copyOf(axes.keySet()));
        for (String a : axes.keySet()) {
            @SuppressWarnings("unchecked")
            java.util.Map<String, Double> m = (java.util.Map<String, Double>) axes.get(a);
            assertTrue(m.get("min") <= m.get("mean") && m.get("mean") <= m.get("max"), a + " " + m);
            double bound = a.endsWith("_mm") ? 1e-6 : 1e-8;
            assertTrue(Math.abs(m.get("min")) <= bound && Math.abs(m.get("max")) <= bound, a + " " + m);
        }
    }
}
