package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class FresaCommandTest {

    @TempDir
    Path dir;

    record Run(int status, String out, String err) {}

    static Run fresa(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    @ParameterizedTest
    @ValueSource(
            strings = {
                "gui",
                "run",
                "stepnc",
                "toolpath",
                "robot",
                "pocket",
                "cut",
                "grade",
                "sole",
                "robots",
                "posts",
                "bench"
            })
    void helpListsEveryCommandOfTheSpec(String command) {
        Run r = fresa("--help");
        assertEquals(0, r.status());
        assertTrue(r.out().contains("\n  " + command + " "), command + " missing from:\n" + r.out());
    }

    @ParameterizedTest
    @ValueSource(
            strings = {
                "gui",
                "run",
                "stepnc",
                "toolpath",
                "robot",
                "pocket",
                "cut",
                "grade",
                "sole",
                "robots",
                "posts",
                "bench"
            })
    void aNamedCommandAloneStillHasItsFullUsage(String command) {
        // only the named command is built (start-up time); its usage names it under fresa
        Run r = fresa(command, "--help");
        assertEquals(0, r.status());
        assertTrue(r.out().startsWith("Usage: fresa " + command + " "), r.out());
    }

    @Test
    void helpListsTheCommandsInTheirOrder() {
        String out = fresa("--help").out();
        int last = -1;
        for (Class<?> c : FresaCommand.COMMANDS) {
            int at = out.indexOf(
                    "\n  " + c.getAnnotation(picocli.CommandLine.Command.class).name() + " ");
            assertTrue(at > last, c + " out of order in:\n" + out);
            last = at;
        }
    }

    @Test
    void anUnknownCommandIsAUsageError() {
        Run r = fresa("weld");
        assertAll(
                () -> assertEquals(2, r.status()),
                () -> assertTrue(r.err().contains("weld")),
                () -> assertFalse(r.err().contains("\tat ")));
    }

    @Test
    void aMissingRequiredOptionIsAUsageError() {
        Run r = fresa("run", "job.xml");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--out"), r.err());
    }

    @Test
    void aJobWithAnExternalEntityIsRefusedWithStatus2() throws Exception {
        Path job = dir.resolve("xxe.xml");
        Files.writeString(
                job,
                "<?xml version=\"1.0\"?><!DOCTYPE job [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>"
                        + "<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\"><name>&x;</name></job>");
        Run r = fresa("run", job.toString(), "--out", dir.resolve("out").toString());
        assertAll(
                () -> assertEquals(2, r.status()),
                () -> assertTrue(r.err().startsWith("fresa: " + job), r.err()),
                () -> assertFalse(r.err().contains("root:"), "the entity must not be read"),
                () -> assertFalse(Files.exists(dir.resolve("out")), "nothing is written for bad input"));
    }

    @Test
    void aMissingJobFileIsBadInput() {
        Run r = fresa("run", dir.resolve("nope.xml").toString(), "--out", dir.toString());
        assertEquals(2, r.status());
        assertTrue(r.err().contains("nope.xml"), r.err());
    }

    @Test
    void pocketTakesTheMillingDirection() throws Exception {
        String c = "samples/pocket/examplepart.dad";
        Run climb = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "10",
                "--out",
                dir.resolve("a.ngc").toString(),
                "--json");
        Run conv = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "10",
                "--out",
                dir.resolve("b.ngc").toString(),
                "--json",
                "--direction",
                "conventional");
        Run bad = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "10",
                "--out",
                dir.resolve("c.ngc").toString(),
                "--direction",
                "sideways");
        assertAll(
                () -> assertEquals(0, climb.status(), climb.err()),
                () -> assertTrue(climb.out().contains("\"direction\":\"climb\""), climb.out()),
                () -> assertEquals(0, conv.status(), conv.err()),
                () -> assertTrue(conv.out().contains("\"direction\":\"conventional\""), conv.out()),
                () -> assertFalse(
                        Files.readString(dir.resolve("a.ngc")).equals(Files.readString(dir.resolve("b.ngc")))),
                () -> assertEquals(2, bad.status()),
                () -> assertTrue(bad.err().contains("sideways"), bad.err()),
                () -> assertFalse(Files.exists(dir.resolve("c.ngc"))));
    }

    @Test
    void pocketTakesTheMillingDirectionOnTheCorrected7mPost() throws Exception {
        String c = "samples/pocket/examplepart.dad";
        Run climb = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "4",
                "--post",
                "7m",
                "--out",
                dir.resolve("a.nc").toString(),
                "--json");
        Run conv = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "4",
                "--post",
                "7m",
                "--out",
                dir.resolve("b.nc").toString(),
                "--json",
                "--direction",
                "conventional");
        Run compat = fresa(
                "pocket",
                c,
                "--tool-diameter",
                "4",
                "--post",
                "7m-compat",
                "--out",
                dir.resolve("c.nc").toString(),
                "--json");
        assertAll(
                () -> assertEquals(0, climb.status(), climb.err()),
                () -> assertTrue(climb.out().contains("\"direction\":\"climb\""), climb.out()),
                () -> assertEquals(0, conv.status(), conv.err()),
                () -> assertTrue(conv.out().contains("\"direction\":\"conventional\""), conv.out()),
                // convex arcs: clockwise in the thesis's conventional passes, counter-clockwise climbing
                () -> assertTrue(Files.readString(dir.resolve("a.nc")).contains("G03"), "climb"),
                () -> assertFalse(Files.readString(dir.resolve("b.nc")).contains("G03"), "conventional"),
                () -> assertTrue(compat.out().contains("\"direction\":\"conventional\""), compat.out()),
                () -> assertFalse(Files.readString(dir.resolve("c.nc")).contains("G03"), "7m-compat"));
    }
}
