package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

class RobotProgramWritersTest {

    static String golden(String name) throws IOException {
        try (InputStream in = RobotProgramWritersTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    static String write(RobotProgramWriter w) throws IOException {
        StringWriter out = new StringWriter();
        w.write(RobotProgramsForTest.sample(), out);
        return out.toString();
    }

    @Test
    void rapidModuleMatchesTheGoldenFile() throws IOException {
        assertEquals(golden("sample.mod"), write(new RapidWriter(RobotProgramsForTest.FRONT_UPPER)));
    }

    @Test
    void krlProgramMatchesTheGoldenFile() throws IOException {
        assertEquals(golden("sample.src"), write(new KrlWriter(RobotProgramsForTest.FRONT_UPPER)));
    }

    @Test
    void everyFormatCarriesTheTrajectoryJointsToAMillionthOfADegree() throws IOException {
        RobotProgram p = RobotProgramsForTest.sample();
        for (String text : List.of(
                write(new RapidWriter(RobotProgramsForTest.FRONT_UPPER)),
                write(new KrlWriter(RobotProgramsForTest.FRONT_UPPER)))) {
            List<double[]> joints = jointsIn(text);
            assertEquals(p.motions().size(), joints.size());
            for (int i = 0; i < joints.size(); i++) {
                for (int j = 0; j < 6; j++) {
                    assertEquals(p.motions().get(i).joint(j), joints.get(i)[j], 1e-6);
                }
            }
        }
    }

    @Test
    void confdataCountsQuarterRevolutions() {
        assertAll(
                () -> assertEquals(0, RapidWriter.quarter(0)),
                () -> assertEquals(0, RapidWriter.quarter(89.999)),
                () -> assertEquals(1, RapidWriter.quarter(90)),
                () -> assertEquals(-1, RapidWriter.quarter(-0.001)),
                () -> assertEquals(-2, RapidWriter.quarter(-91)),
                () -> assertEquals(3, RapidWriter.quarter(359.9)));
    }

    @Test
    void statusAndTurnFollowTheJointSigns() {
        RobotProgram.Motion m = RobotProgramsForTest.sample().motions().get(1);
        KrlWriter w = new KrlWriter(RobotProgramsForTest.FRONT_UPPER);
        assertAll(
                () -> assertEquals(0b110, w.status(m), "upper arm and A5 <= 0"),
                () -> assertEquals(0b110101, KrlWriter.turn(m), "A1, A3, A5 and A6 negative"));
    }

    @Test
    void aJointAtPlusOrMinusRoundingNoiseKeepsTheConfiguration() {
        RobotProgram.Motion plus = linear(List.of(1e-16, 10.0, -20.0, 1e-16, 1e-16, 1e-16), 1, 0);
        RobotProgram.Motion minus = linear(List.of(-1e-16, 10.0, -20.0, -1e-16, -1e-16, -1e-16), 1, 0);
        assertAll(
                () -> assertEquals(
                        RapidWriter.confdata(plus, RobotProgramsForTest.FRONT_UPPER),
                        RapidWriter.confdata(minus, RobotProgramsForTest.FRONT_UPPER)),
                () -> assertEquals(KrlWriter.turn(plus), KrlWriter.turn(minus)),
                () -> assertEquals(
                        KrlWriter.status(plus, RobotProgramsForTest.FRONT_UPPER),
                        KrlWriter.status(minus, RobotProgramsForTest.FRONT_UPPER)),
                () -> assertEquals(-1, RapidWriter.quarter(-1e-6)));
    }

    @Test
    void aDwellIsAWaitAtAFinePoint() throws IOException {
        RobotProgram sample = RobotProgramsForTest.sample();
        List<RobotProgram.Motion> motions = new ArrayList<>(sample.motions());
        motions.add(linear(List.of(3.0, 13.5, -20.5, -0.5, 31.0, 359.9), 0, 0.5));
        motions.add(linear(List.of(3.0, 13.5, -20.5, -0.5, 31.0, 359.9), 1, 0));
        RobotProgram p = new RobotProgram(sample.programName(), sample.robotName(), sample.joints(), motions);
        StringWriter rapid = new StringWriter();
        new RapidWriter(RobotProgramsForTest.FRONT_UPPER).write(p, rapid);
        StringWriter krl = new StringWriter();
        new KrlWriter(RobotProgramsForTest.FRONT_UPPER).write(p, krl);
        assertAll(
                () -> assertTrue(
                        rapid.toString()
                                .contains(
                                        ",fine,tFresa1\\WObj:=wFresa; ! j=[3.000000,13.500000,"
                                                + "-20.500000,-0.500000,31.000000,359.900000] ! 4\n    WaitTime \\InPos, 0.500;\n"),
                        rapid::toString),
                () -> assertTrue(
                        rapid.toString()
                                .contains(",z1,tFresa1\\WObj:=wFresa; ! j=[3.000000,13.500000,"
                                        + "-20.500000,-0.500000,31.000000,359.900000] ! 5\n"),
                        rapid::toString),
                () -> assertTrue(krl.toString().contains(" ; 4\nWAIT SEC 0.500\n"), krl::toString),
                () -> assertTrue(krl.toString().contains("$APO.CDIS = 1.000\n"), krl::toString));
    }

    private static RobotProgram.Motion linear(List<Double> q, double zoneMm, double dwellS) {
        int index = dwellS > 0 ? 4 : 5;
        return new RobotProgram.Motion(
                index,
                "WS 2",
                RobotProgram.MotionType.LINEAR,
                RobotProgram.PointRole.PART,
                q,
                Transform3.rotY(180),
                5,
                zoneMm,
                dwellS,
                0);
    }

    /** The joint values of every move: MoveAbsJ/PTP axis values, or the j=[...] of linear moves. */
    static List<double[]> jointsIn(String program) {
        List<double[]> out = new ArrayList<>();
        Pattern abs = Pattern.compile("MoveAbsJ \\[\\[([^\\]]*)\\]");
        Pattern ptp = Pattern.compile("PTP \\{AXIS: ([^}]*)\\}");
        Pattern lin = Pattern.compile("j=\\[([^\\]]*)\\]");
        for (String line : program.split("\n")) {
            for (Pattern p : List.of(abs, ptp, lin)) {
                Matcher m = p.matcher(line);
                if (m.find()) {
                    String[] parts = m.group(1).replaceAll("A\\d ", "").split(",");
                    double[] v = new double[parts.length];
                    for (int i = 0; i < parts.length; i++) {
                        v[i] = Double.parseDouble(parts[i].trim());
                    }
                    out.add(v);
                    break;
                }
            }
        }
        return out;
    }
}
