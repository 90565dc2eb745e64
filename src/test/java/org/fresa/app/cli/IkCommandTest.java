package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class IkCommandTest {

    @TempDir
    Path dir;

    @Test
    void aBadRowExitsWithTheFileAndLineAndWritesNothing() throws Exception {
        Path f = dir.resolve("targets.csv");
        Files.writeString(f, "x,y,z,roll,pitch,yaw\n500,0,500,0,180,0\n500,0,500,0,180\n");
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter()),
                new PrintWriter(err),
                "ik",
                f.toString(),
                "--robot",
                "irb140",
                "--out",
                dir.resolve("out").toString());
        assertEquals(2, status, err::toString);
        assertTrue(err.toString().contains("targets.csv") && err.toString().contains("3"), err::toString);
        assertTrue(err.toString().contains("expected 6 comma-separated numbers"), err::toString);
        assertFalse(Files.exists(dir.resolve("out").resolve("ik.csv")));
    }

    @Test
    void everyBranchOfAPoseIsWrittenWithAll() throws Exception {
        Path f = dir.resolve("targets.csv");
        Files.writeString(f, "x,y,z,roll,pitch,yaw\n500,100,500,0,180,0\n");
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter()),
                new PrintWriter(err),
                "ik",
                f.toString(),
                "--robot",
                "irb140",
                "--out",
                dir.resolve("out").toString(),
                "--all",
                "--tool-length",
                "20",
                "--spindle",
                "0,0,100");
        assertEquals(0, status, err::toString);
        var rows = Files.readAllLines(dir.resolve("out").resolve("ik.csv"));
        assertTrue(rows.get(0).endsWith(",branch"), rows.get(0));
        // an IRB-140 reaches this pose with shoulder, elbow and wrist each either way
        assertTrue(rows.size() - 1 >= 4, String.join("\n", rows));
        assertTrue(rows.get(rows.size() - 1).endsWith("," + (rows.size() - 1)), rows.get(rows.size() - 1));
    }

    @Test
    void anUnknownMethodIsBadUsage() throws Exception {
        Path f = dir.resolve("targets.csv");
        Files.writeString(f, "x,y,z,roll,pitch,yaw\n500,100,500,0,180,0\n");
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter()),
                new PrintWriter(err),
                "ik",
                f.toString(),
                "--robot",
                "irb140",
                "--out",
                dir.resolve("out").toString(),
                "--method",
                "newton");
        assertEquals(2, status, err::toString);
        assertTrue(err.toString().contains("--method"), err::toString);
    }
}
