package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.app.cli.CutCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --post apt} on the command line: listed by {@code fresa posts}, taken by {@code fresa pocket}. */
class AptCommandTest {

    @TempDir
    Path dir;

    @Test
    void postsListsTheAptPost() {
        Run r = CutCommandTest.fresa("posts");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("apt ") && l.contains("CL data")), r.out());
    }

    @Test
    void pocketWritesAptClData() throws Exception {
        Path out = dir.resolve("examplepart.apt");
        Run r = CutCommandTest.fresa(
                "pocket",
                "samples/pocket/examplepart.dad",
                "--out",
                out.toString(),
                "--tool-diameter",
                "4",
                "--cut",
                "0.62",
                "--finish",
                "0.18",
                "--z-top",
                "8",
                "--z-bottom",
                "6",
                "--max-depth",
                "2",
                "--rpm",
                "3250",
                "--feed",
                "278",
                "--finish-feed",
                "115",
                "--post",
                "apt");
        assertEquals(0, r.status(), r.err());
        String text = Files.readString(out);
        assertTrue(text.startsWith("PARTNO examplepart.dad\nUNITS/MM\n"), text);
        assertTrue(
                text.contains("\nSPINDL/3250,CLW\n")
                        && text.contains("\nFEDRAT/278.0,MMPM\n")
                        && text.contains("\nCIRCLE/")
                        && text.endsWith("\nFINI\n"),
                text);
    }

    @Test
    void anUnknownPostIsBadUsageNamingApt() {
        Run r = CutCommandTest.fresa(
                "pocket",
                "samples/pocket/examplepart.dad",
                "--out",
                dir.resolve("x").toString(),
                "--tool-diameter",
                "4",
                "--post",
                "aptx");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("apt"), r.err());
    }
}
