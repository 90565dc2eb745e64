package org.fresa.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Transform3;
import org.fresa.io.Json;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class RobotFilesTest {

    @TempDir
    Path dir;

    @Test
    void theIrb140FileHasTheForwardKinematicsOfTheBuiltIn() throws CamInputException {
        Robot file = RobotFiles.load("samples/robot/irb140.xml");
        assertInstanceOf(SerialRobot.class, file);
        assertEquals("irb140-file", file.name());
        double[] q = {12, -34, 56, -78, 90, -123};
        Transform3 a = file.forward(q);
        Transform3 b = Robots.irb140().forward(q);
        assertTrue(a.eq(b, new org.fresa.geom.Tolerance(1e-12, 1e-15)));
    }

    @Test
    void theTriceptFileHasTheForwardKinematicsOfTheBuiltIn() throws CamInputException {
        Robot file = RobotFiles.load("samples/robot/tricept806.xml");
        assertInstanceOf(TriceptRobot.class, file);
        double[] q = {1500, 1400, 1450, 10, 80, -20};
        assertTrue(file.forward(q).eq(Robots.tricept806().forward(q), new org.fresa.geom.Tolerance(1e-9, 1e-12)));
    }

    @Test
    void aBuiltInNameNeedsNoFile() throws CamInputException {
        assertEquals("adept-one", RobotFiles.load("adept-one").name());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            q1 + 90   | 90
            q1        | 0
            q1 - 12.5 | -12.5
            q1+1e1    | 10
            180/2 + q1 - 180 | -90
            """)
    void aVariableCellReadsAsItsOffset(String text, double offset) throws CamInputException {
        assertEquals(offset, RobotFiles.variableOffset("f", 1, "theta", text));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            q2 - 90
            2*q1
            90
            q1*q1
            """)
    void aVariableCellThatIsNotQPlusAConstantIsRefused(String text) {
        CamInputException e =
                assertThrows(CamInputException.class, () -> RobotFiles.variableOffset("f", 1, "theta", text));
        assertTrue(e.getMessage().contains("joint 1: theta must be q1 plus a constant"), e.getMessage());
    }

    @Test
    void aWrongCellIsReportedWithTheJoint() throws IOException {
        Path f = dir.resolve("bad.xml");
        Files.writeString(
                f, Files.readString(Path.of("samples/robot/irb140.xml")).replace("q2 - 90", "q3 - 90"));
        CamInputException e = assertThrows(CamInputException.class, () -> RobotFiles.load(f.toString()));
        assertTrue(e.getMessage().contains("joint 2"), e.getMessage());
    }

    @Test
    void aFileAgainstTheSchemaIsReportedWithItsLine() throws IOException {
        Path f = dir.resolve("bad.xml");
        Files.writeString(
                f, Files.readString(Path.of("samples/robot/irb140.xml")).replace("min=\"-90\"", "minimum=\"-90\""));
        CamInputException e = assertThrows(CamInputException.class, () -> RobotFiles.load(f.toString()));
        assertTrue(e.line().isPresent(), e.getMessage());
    }

    @Test
    void anUnknownNameIsBadInput() {
        assertThrows(CamInputException.class, () -> RobotFiles.load("puma560"));
    }

    @Test
    void theBuiltInsAreDescribedWithTheirLimits() {
        String json = Json.write(RobotFiles.describeBuiltIns());
        assertTrue(json.contains("\"name\":\"irb140\""));
        assertTrue(json.contains("\"base_radius_mm\":500"));
        assertTrue(json.contains("\"min\":-230"));
    }

    @ParameterizedTest
    @CsvSource({"irb140", "adept-one", "tricept806"})
    void aWrittenRobotReadsBackWithTheSameKinematicsAndLimits(String name) throws Exception {
        Robot r = Robots.byName(name).orElseThrow();
        Path f = dir.resolve(name + ".xml");
        RobotFiles.write(r, f);
        Robot back = RobotFiles.read(f);
        double[] q = new double[r.dof()];
        for (int i = 0; i < q.length; i++) {
            q[i] = (r.joints().get(i).min() + r.joints().get(i).max()) / 2 + 7 * (i + 1) % 11;
        }
        assertEquals(r.joints(), back.joints());
        assertEquals(r.name(), back.name());
        assertTrue(r.forward(q).eq(back.forward(q), new org.fresa.geom.Tolerance(1e-12, 1e-15)), f.toString());
    }

    @Test
    void aToolFrameWithRotationIsWrittenAndReadBack() throws Exception {
        Transform3 tool = Transform3.ofXyzRpyDeg(10, -20, 150.25, 30, -45, 60);
        SerialRobot r = Robots.irb140().withTool(tool);
        Path f = dir.resolve("tool.xml");
        RobotFiles.write(r, f);
        SerialRobot back = (SerialRobot) RobotFiles.read(f);
        assertTrue(
                back.chain().tool().eq(tool, new org.fresa.geom.Tolerance(1e-12, 1e-14)),
                back.chain().tool().toString());
        assertEquals(r.wristJoint(), back.wristJoint());
    }
}
