package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.model.CamInputException;
import org.fresa.post.PocketPost;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An enumerated setting is typed when the job is read: a word that is no value is refused with
 * the file, the line and the allowed values, before anything runs.
 */
class JobFileChoicesTest {

    @TempDir
    Path dir;

    private Path sampleWith(String sample, String from, String to) throws Exception {
        String xml = Files.readString(Path.of("samples/jobs", sample));
        assertTrue(xml.contains(from), from);
        Path job = dir.resolve(sample);
        Files.writeString(job, xml.replace(from, to));
        return job;
    }

    @Test
    void aMistypedPocketPostIsRefusedWhenTheJobIsRead() throws Exception {
        Path job = sampleWith("pocket-cavity01.xml", "post=\"7m-compat\"", "post=\"7m-compta\"");
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(job));
        assertAll(
                e.getMessage(),
                () -> assertEquals(job.toString(), e.source()),
                () -> assertEquals(7, e.line().getAsInt()),
                () -> assertEquals(
                        "post: unknown value '7m-compta': expected one of 7m-compat, 7m, linuxcnc, iso, "
                                + "fanuc, 840d, apt",
                        e.problem()));
    }

    @Test
    void theWordsAreWrittenAsTheyAreRead() throws Exception {
        Job job = JobXml.read(Path.of("samples/jobs/pocket-cavity01.xml"));
        assertEquals(PocketPost.SINUMERIK_7M_COMPAT, job.pocket().orElseThrow().post());
        Path saved = dir.resolve("saved.xml");
        JobXml.write(job, saved);
        assertTrue(Files.readString(saved).contains("post=\"7m-compat\""), Files.readString(saved));
        assertEquals(job, JobXml.read(saved));
    }

    @Test
    void aMistypedCuttingPostIsRefusedWhenTheJobIsRead() throws Exception {
        Path job = sampleWith("cut-plate.xml", "post=\"linuxcnc\"", "post=\"fanuk\"");
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(job));
        assertAll(
                e.getMessage(),
                () -> assertEquals(5, e.line().getAsInt()),
                () -> assertEquals(
                        "post: unknown value 'fanuk': expected one of linuxcnc, iso, fanuc, 840d", e.problem()));
    }

    @Test
    void aMistypedRobotFormatIsRefusedWhenTheJobIsRead() throws Exception {
        Path job = sampleWith("example2-irb140.xml", "formats=\"", "formats=\"rapdi,");
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(job));
        assertAll(
                e.getMessage(),
                () -> assertTrue(e.line().isPresent()),
                () -> assertEquals(
                        "formats: unknown value 'rapdi': expected one of csv, xml, rapid, krl, png", e.problem()));
    }
}
