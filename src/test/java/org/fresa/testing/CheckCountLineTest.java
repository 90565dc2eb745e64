package org.fresa.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CheckCountLineTest {

    @Test
    void theTestJvmsOfOneBuildAreSummedIntoOneLineWithTheReasonsOfTheSkips(@TempDir Path dir) throws Exception {
        String build = CheckCounter.fileName("2026-12-02T07:00:00Z");
        Files.writeString(
                dir.resolve(build + "1-1.tsv"),
                "interpreter\tran\t40\t\ncorpus\tran\t100\t\n"
                        + "corpus\tskipped\t2\t../shared/corpus/stepnc is not beside the checkout\n");
        Files.writeString(
                dir.resolve(build + "2-1.tsv"),
                "interpreter\tran\t2\t\ninterpreter\tfailed\t1\t\n"
                        + "corpus\tskipped\t1\t../shared/corpus/stepnc is not beside the checkout\n");
        Files.writeString(dir.resolve(CheckCounter.fileName("an earlier build") + "3-1.tsv"), "corpus\tran\t999\t\n");
        assertEquals(
                "[fresa] Interpreter checks (LinuxCNC's rs274): 43 ran (1 failed), 0 skipped; corpus checks (files"
                        + " written by other programs): 100 ran, 3 skipped (3: ../shared/corpus/stepnc is not beside the"
                        + " checkout).",
                CheckCountLine.line(CheckCountLine.read(dir, build)));
    }

    @Test
    void aBuildWithoutChecksSaysNoneRan(@TempDir Path dir) throws Exception {
        assertEquals(
                "[fresa] Interpreter checks (LinuxCNC's rs274): 0 ran, 0 skipped; corpus checks (files written by"
                        + " other programs): 0 ran, 0 skipped.",
                CheckCountLine.line(CheckCountLine.read(dir.resolve("none"), "x")));
    }
}
