package org.fresa.fuzz;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.job.JobXml;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;

/**
 * Coverage-guided fuzz tests of the readers (Jazzer). A reader may accept an input or refuse it
 * with a {@link CamInputException}; any other exception, a hang or an out-of-memory is a finding.
 *
 * <p>{@code mvn test} replays the seed corpus in src/test/resources/org/fresa/fuzz/ReaderFuzzTestInputs;
 * {@code JAZZER_FUZZ=1 mvn test -Dtest=ReaderFuzzTest#NAME} fuzzes one target for its maxDuration
 * (CI does this for a bounded time; docs/robustness.md says how to run longer).
 */
class ReaderFuzzTest {

    @FuzzTest(maxDuration = "10s")
    void jobXmlReaderAcceptsOrRefuses(byte[] data) throws IOException {
        Path f = Files.createTempFile("fuzz-job", ".xml");
        try {
            Files.write(f, data);
            JobXml.read(f);
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        } finally {
            Files.deleteIfExists(f);
        }
    }

    @FuzzTest(maxDuration = "10s")
    void contourReaderAcceptsOrRefuses(byte[] data) {
        try {
            ContourFile.read(new StringReader(new String(data, StandardCharsets.UTF_8)), "fuzz.contour");
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        }
    }

    @FuzzTest(maxDuration = "10s")
    void part21AndIso14649BindingAcceptOrRefuse(byte[] data) throws IOException {
        try {
            org.fresa.stepnc.StepNcReader.read(new java.io.ByteArrayInputStream(data), "fuzz.stp");
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        }
    }

    @FuzzTest(maxDuration = "10s")
    void dxfReaderAcceptsOrRefuses(byte[] data) {
        try {
            org.fresa.dxf.DxfReader.read(data, "fuzz.dxf", org.fresa.dxf.DxfReadOptions.DEFAULT);
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        }
    }

    @FuzzTest(maxDuration = "10s")
    void dadReaderAcceptsOrRefuses(byte[] data) {
        try {
            org.fresa.pocket.DadReader.read(new String(data, StandardCharsets.ISO_8859_1), "fuzz.dad");
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        }
    }

    @FuzzTest(maxDuration = "10s")
    void robotProgramXmlReaderAcceptsOrRefuses(byte[] data) throws IOException {
        Path f = Files.createTempFile("fuzz-program", ".xml");
        try {
            Files.write(f, data);
            org.fresa.robot.RobotProgramXml.read(f);
        } catch (CamInputException expected) {
            // refusing bad input with a message is the wanted outcome
        } finally {
            Files.deleteIfExists(f);
        }
    }
}
