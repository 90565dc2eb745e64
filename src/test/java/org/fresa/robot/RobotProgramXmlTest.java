package org.fresa.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.io.SafeXml;
import org.fresa.model.CamInputException;
import org.fresa.post.RobotProgram;
import org.fresa.post.RobotProgramsForTest;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RobotProgramXmlTest {

    @TempDir
    Path dir;

    Path writeSample() throws Exception {
        Path f = dir.resolve("program.xml");
        try (OutputStream out = Files.newOutputStream(f)) {
            RobotProgramXml.write(RobotProgramsForTest.sample(), RobotProgramsForTest.FRONT_UPPER, out);
        }
        return f;
    }

    @Test
    void readingTheFileBackGivesTheSameTrajectory() throws Exception {
        RobotProgram p = RobotProgramsForTest.sample();
        RobotProgram back = RobotProgramXml.read(writeSample());
        assertEquals(p.joints(), back.joints());
        assertEquals(p.motions().size(), back.motions().size());
        for (int i = 0; i < p.motions().size(); i++) {
            RobotProgram.Motion a = p.motions().get(i);
            RobotProgram.Motion b = back.motions().get(i);
            assertEquals(a.jointValues(), b.jointValues(), "joints are exact");
            assertEquals(a.target().translationPart(), b.target().translationPart(), "positions are exact");
            assertTrue(a.target().rotationAngleTo(b.target()) < 1e-15);
            assertEquals(a.workingstep(), b.workingstep());
            assertEquals(a.type(), b.type());
            assertEquals(a.role(), b.role());
            assertEquals(a.speedMmPerS(), b.speedMmPerS());
            assertEquals(a.zoneMm(), b.zoneMm());
        }
    }

    /** A drilling's bottom: a wait there and the spindle running, both read back as written. */
    @Test
    void aDwellAndTheSpindleSpeedOfAMotionAreReadBack() throws Exception {
        RobotProgram p = RobotProgramsForTest.sample();
        java.util.List<RobotProgram.Motion> motions = new java.util.ArrayList<>(p.motions());
        for (int i = 0; i < motions.size(); i++) {
            RobotProgram.Motion m = motions.get(i);
            motions.set(
                    i,
                    new RobotProgram.Motion(
                            m.index(),
                            m.workingstep(),
                            m.type(),
                            m.role(),
                            m.jointValues(),
                            m.target(),
                            m.speedMmPerS(),
                            i == 1 ? 0 : m.zoneMm(),
                            i == 1 ? 1.5 : 0,
                            3000));
        }
        RobotProgram q = new RobotProgram(p.programName(), p.robotName(), p.joints(), motions);
        Path f = dir.resolve("dwell.xml");
        try (OutputStream out = Files.newOutputStream(f)) {
            RobotProgramXml.write(q, RobotProgramsForTest.FRONT_UPPER, out);
        }
        RobotProgram back = RobotProgramXml.read(f);
        for (int i = 0; i < motions.size(); i++) {
            assertEquals(motions.get(i).dwellS(), back.motions().get(i).dwellS());
            assertEquals(3000, back.motions().get(i).spindleRpm());
        }
        assertEquals(1.5, back.motions().get(1).dwellS());
    }

    @Test
    void theFileValidatesWithXmllint() throws Exception {
        Path xmllint = Path.of("/usr/bin/xmllint");
        Assumptions.assumeTrue(Files.isExecutable(xmllint), "xmllint not installed");
        Process p = new ProcessBuilder(
                        xmllint.toString(),
                        "--noout",
                        "--schema",
                        "schemas/robot-program.xsd",
                        writeSample().toString())
                .redirectErrorStream(true)
                .start();
        String out = new String(p.getInputStream().readAllBytes());
        assertEquals(0, p.waitFor(), out);
        assertTrue(out.contains("validates"), out);
    }

    @Test
    void anInvalidFileIsRefusedWithItsLine() throws Exception {
        Path f = writeSample();
        String xml = Files.readString(f)
                .replaceFirst("<MotionType>Linear</MotionType>", "<MotionType>Circular</MotionType>");
        Files.writeString(f, xml);
        CamInputException e = assertThrows(CamInputException.class, () -> RobotProgramXml.read(f));
        assertTrue(e.line().isPresent(), e.getMessage());
    }

    @Test
    void aSchemaValidFileWithMoreJointValuesThanJointsIsRefused() throws Exception {
        // found by the CI fuzzer: the schema cannot tie the joint count to the values per motion
        Path f = Path.of(
                "src/test/resources/org/fresa/fuzz/ReaderFuzzTestInputs/robotProgramXmlReaderAcceptsOrRefuses/two-joints-six-values.xml");
        CamInputException e = assertThrows(CamInputException.class, () -> RobotProgramXml.read(f));
        assertTrue(e.getMessage().contains("6 joint values for 2 joints"), e.getMessage());
        assertTrue(e.getMessage().contains("two-joints-six-values.xml"), e.getMessage());
    }

    @Test
    void theWrittenFileIsValidAgainstTheSchema() throws Exception {
        // write() no longer validates as it goes: the file must still be valid
        javax.xml.validation.Validator v =
                SafeXml.schema("/schemas/robot-program.xsd").newValidator();
        v.validate(new javax.xml.transform.stream.StreamSource(writeSample().toFile()));
    }

    @Test
    void aNumberOutsideTheSchemaIsRefusedBeforeAnythingIsWritten() {
        RobotProgram p = RobotProgramsForTest.sample();
        java.util.List<RobotProgram.Motion> motions = new java.util.ArrayList<>(p.motions());
        RobotProgram.Motion m = motions.get(1);
        java.util.List<Double> joints = new java.util.ArrayList<>(m.jointValues());
        joints.set(2, Double.NaN);
        motions.set(
                1,
                new RobotProgram.Motion(
                        m.index(),
                        m.workingstep(),
                        m.type(),
                        m.role(),
                        joints,
                        m.target(),
                        m.speedMmPerS(),
                        m.zoneMm(),
                        0,
                        0));
        RobotProgram bad = new RobotProgram(p.programName(), p.robotName(), p.joints(), motions);
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        java.io.IOException e = assertThrows(
                java.io.IOException.class, () -> RobotProgramXml.write(bad, RobotProgramsForTest.FRONT_UPPER, out));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
        assertEquals(0, out.size());
    }

    @Test
    void theDirectWriterWritesTheBindingsBytes() throws Exception {
        RobotProgram p = RobotProgramsForTest.sample();
        for (RobotProgram q :
                java.util.List.of(p, new RobotProgram("empty", p.robotName(), p.joints(), java.util.List.of()))) {
            var x = RobotProgramXml.toXml(q, RobotProgramsForTest.FRONT_UPPER);
            assertTrue(RobotProgramXml.plainStrings(x));
            java.io.ByteArrayOutputStream byBinding = new java.io.ByteArrayOutputStream();
            RobotProgramXml.marshal(x, byBinding);
            java.io.ByteArrayOutputStream direct = new java.io.ByteArrayOutputStream();
            RobotProgramXml.write(q, RobotProgramsForTest.FRONT_UPPER, direct);
            assertEquals(
                    byBinding.toString(java.nio.charset.StandardCharsets.UTF_8),
                    direct.toString(java.nio.charset.StandardCharsets.UTF_8));
        }
    }

    @Test
    void namesThatNeedEscapingGoThroughTheBinding() throws Exception {
        RobotProgram p = RobotProgramsForTest.sample();
        RobotProgram odd = new RobotProgram("a<b & \"c\" \u00e9", p.robotName(), p.joints(), p.motions());
        assertTrue(!RobotProgramXml.plainStrings(RobotProgramXml.toXml(odd, RobotProgramsForTest.FRONT_UPPER)));
        Path f = dir.resolve("odd.xml");
        try (OutputStream out = Files.newOutputStream(f)) {
            RobotProgramXml.write(odd, RobotProgramsForTest.FRONT_UPPER, out);
        }
        assertEquals(odd.programName(), RobotProgramXml.read(f).programName());
    }
}
