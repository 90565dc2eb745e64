package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.DadContour;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.PocketPost;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A pocket contour held in the job ({@code <pocket><elements>}): kept, bounded, and run as its file is. */
class PocketElementsJobTest {

    @TempDir
    Path dir;

    private static DadContour contourOf(String name) throws Exception {
        return DadReader.contour(Files.readString(Path.of("samples/pocket", name), StandardCharsets.ISO_8859_1), name);
    }

    private static PocketSettings cavity05(Path contour) {
        return new PocketSettings(
                contour,
                4,
                0.65,
                0.1,
                0,
                -3,
                3,
                3000,
                300,
                100,
                PocketPost.LINUXCNC,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);
    }

    @Test
    void theElementsAreWrittenAndReadBackExactly() throws Exception {
        for (String name : List.of("cavity02.dad", "cavity05.dad", "cavity07.dad", "examplepart.dad")) {
            Job job = Job.empty(JobTask.POCKET)
                    .withPocket(cavity05(dir.resolve(name)).withElements(dir.resolve(name), contourOf(name)));
            Path file = dir.resolve("job.xml");
            JobXml.write(job, file);
            assertEquals(job, JobXml.read(file), name);
            String xml = Files.readString(file);
            assertTrue(xml.contains("<elements>") && xml.contains("<line ") && xml.contains("<arc "), xml);
        }
    }

    @Test
    void aJobWithElementsNeedsNoContourFile() throws Exception {
        Path file = dir.resolve("typed.xml");
        Files.writeString(file, """
                <?xml version="1.0"?>
                <job xmlns="urn:fresa:job:1" version="1" task="pocket">
                  <pocket toolDiameterMm="6">
                    <elements>
                      <line a="0" b="1" dMm="30"/>
                      <arc xMm="20" yMm="15" radiusMm="25" selector="L" sense="convex"/>
                      <line a="0" b="1" dMm="0" selector="L"/>
                      <line a="1" b="0" dMm="0"/>
                    </elements>
                  </pocket>
                </job>
                """);
        PocketSettings p = JobXml.read(file).pocket().orElseThrow();
        assertEquals(dir.resolve("contour.dad"), p.contour());
        assertEquals(4, p.elements().orElseThrow().elements().size());
        assertEquals(' ', p.elements().get().elements().get(0).selector());
        assertEquals('L', p.elements().get().elements().get(1).selector());
        assertEquals('F', p.elements().get().elements().get(1).sense());
    }

    @Test
    void aBadElementIsRefusedWithItsLine() throws Exception {
        String[][] cases = {
            {"<arc xMm=\"20\" yMm=\"15\" radiusMm=\"-25\" sense=\"convex\"/>", "-25"},
            {"<arc xMm=\"2e6\" yMm=\"15\" radiusMm=\"25\" sense=\"convex\"/>", "2e6"},
            {"<arc xMm=\"20\" yMm=\"15\" radiusMm=\"25\" sense=\"inward\"/>", "inward"},
            {"<line a=\"0\" b=\"0\" dMm=\"3\"/>", "a and b are both zero"},
            {"<line a=\"0\" b=\"1\" dMm=\"3\" selector=\"X\"/>", "'X'"},
        };
        for (String[] c : cases) {
            Path file = dir.resolve("bad.xml");
            Files.writeString(
                    file,
                    "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\">\n"
                            + "  <pocket toolDiameterMm=\"6\">\n    <elements>\n      <line a=\"1\" b=\"0\" dMm=\"0\"/>\n      "
                            + c[0] + "\n    </elements>\n  </pocket>\n</job>\n");
            CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(file), c[0]);
            assertEquals(6, e.line().orElse(0), e.getMessage());
            assertTrue(e.getMessage().contains(c[1]), e.getMessage());
        }
    }

    @Test
    void aPocketWithNeitherFileNorElementsIsRefused() throws Exception {
        Path file = dir.resolve("none.xml");
        Files.writeString(
                file,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\">"
                        + "<pocket toolDiameterMm=\"6\"/></job>\n");
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(file));
        assertTrue(e.getMessage().contains("needs a contour file"), e.getMessage());
    }

    @Test
    void aContourThatCrossesItselfIsRefusedWithTheElementNamed() throws Exception {
        Path file = dir.resolve("crossing.xml");
        // a bow tie (0, 0), (40, 30), (40, 0), (0, 30)
        Files.writeString(file, """
                <?xml version="1.0"?>
                <job xmlns="urn:fresa:job:1" version="1" task="pocket">
                  <pocket toolDiameterMm="6">
                    <elements>
                      <line a="3" b="-4" dMm="0"/>
                      <line a="1" b="0" dMm="40"/>
                      <line a="3" b="4" dMm="120"/>
                      <line a="1" b="0" dMm="0"/>
                    </elements>
                  </pocket>
                </job>
                """);
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> JobRunner.run(JobXml.read(file), new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE));
        assertTrue(
                e.getMessage()
                        .endsWith("the job's <elements>: Element 3 crosses element 1: the contour intersects itself."),
                e.getMessage());
        assertTrue(Files.notExists(dir.resolve("out").resolve("pocket.ngc")));
    }

    /** Every thesis contour run from the job's elements writes what its .dad file writes, file for file. */
    @Test
    void runningTheElementsWritesWhatTheFileWrites() throws Exception {
        for (String name : List.of("cavity01.dad", "cavity05.dad", "examplepart.dad")) {
            Path dad = Path.of("samples/pocket", name).toAbsolutePath();
            // the typed contour goes by the file's name, which is not there: only the elements are read
            Job typed = Job.empty(JobTask.POCKET)
                    .withPocket(cavity05(dir.resolve(name))
                            .withElements(dir.resolve("absent").resolve(name), contourOf(name)));
            Path typedJob = dir.resolve("typed-" + name + ".xml");
            JobXml.write(typed, typedJob);
            TaskOutcome a = JobRunner.run(
                    JobXml.read(typedJob), new OutputFolder(dir.resolve("typed-" + name)), ProgressMonitor.NONE);
            TaskOutcome b = JobRunner.run(
                    Job.empty(JobTask.POCKET).withPocket(cavity05(dad)),
                    new OutputFolder(dir.resolve("file-" + name)),
                    ProgressMonitor.NONE);
            assertEquals(0, a.exitStatus(), a.problems().toString());
            assertEquals(b.exitStatus(), a.exitStatus());
            assertEquals(b.files().size(), a.files().size());
            List<String> differ = new ArrayList<>();
            for (int i = 0; i < a.files().size(); i++) {
                assertEquals(b.files().get(i).getFileName(), a.files().get(i).getFileName());
                if (!Files.readString(a.files().get(i))
                        .replace(dir.resolve("absent").toString(), "")
                        .equals(Files.readString(b.files().get(i))
                                .replace(dad.getParent().toString(), ""))) {
                    differ.add(a.files().get(i).getFileName().toString());
                }
            }
            assertEquals(List.of(), differ, name);
        }
    }
}
