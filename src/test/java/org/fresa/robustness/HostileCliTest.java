package org.fresa.robustness;

import static org.fresa.robustness.HostileFiles.contour;
import static org.fresa.robustness.HostileFiles.dxf;
import static org.fresa.robustness.HostileFiles.example2With;
import static org.fresa.robustness.HostileFiles.fanOut;
import static org.fresa.robustness.HostileFiles.insert;
import static org.fresa.robustness.HostileFiles.nested;
import static org.fresa.robustness.HostileFiles.part21;
import static org.fresa.robustness.HostileFiles.polygon;
import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fresa.io.AtomicFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.api.io.TempDir;

/**
 * Hostile inputs (absurd counts, nesting, cycles, numeric hazards) through the command line in a
 * JVM with a 160 MB heap and a 512 KiB stack: every command ends within 30 s with
 * exit 0, 1 or 2, one message and no stack trace; a refused input writes nothing; no temporary
 * file is left; no output file holds NaN or Infinity. Some cases also pin the outcome.
 */
class HostileCliTest {

    static final String HEAP = "-Xmx160m";
    static final String STACK = "-Xss512k";
    static final Pattern NON_FINITE = Pattern.compile("(?i)\\b(nan|infinity)\\b");

    @TempDir
    Path dir;

    /** One command: the file it reads, its arguments (IN, OUT replaced), the status wanted (-1: any) and words. */
    record Case(String name, String fileName, String content, List<String> args, int status, String words) {}

    static List<String> pocket() {
        return List.of("pocket", "IN", "--out", "OUT/p.ngc", "--tool-diameter", "6");
    }

    static List<String> cut() {
        return List.of("cut", "IN", "--out", "OUT/c.ngc");
    }

    static List<String> grade() {
        return List.of("grade", "IN", "--out", "OUT", "--base-size", "40", "--sizes", "39-40", "--system", "br");
    }

    static List<String> toolpath() {
        return List.of("toolpath", "IN", "--out", "OUT");
    }

    static List<String> stepnc() {
        return List.of("stepnc", "IN", "--json");
    }

    List<Case> cases() throws IOException {
        List<Case> c = new ArrayList<>();
        // ---- Part 21 / ISO 14649: counts, nesting, cycles
        c.add(new Case("p21-20-digit-name", "a.stp", part21("#12345678901234567890=X(1);\n"), stepnc(), 2, "line 8"));
        c.add(new Case(
                "p21-100000-parens",
                "a.stp",
                part21("#1=X(" + nested("(", "", ")", 100_000) + ");\n"),
                toolpath(),
                2,
                "nested more than"));
        c.add(new Case(
                "p21-100000-typed",
                "a.stp",
                part21("#1=X(" + nested("A(", "1", ")", 100_000) + ");\n"),
                stepnc(),
                2,
                "nested more than"));
        c.add(new Case(
                "p21-254-lists", "a.stp", part21("#1=X(" + nested("(", "", ")", 254) + ");\n"), stepnc(), 0, ""));
        c.add(new Case("p21-self-ref", "a.stp", part21("#1=X(#1);\n"), toolpath(), -1, ""));
        c.add(new Case(
                "p21-workplan-self",
                "a.stp",
                part21("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#2),$,$,$);\n"),
                toolpath(),
                2,
                "contains itself"));
        c.add(new Case(
                "p21-workplan-cycle",
                "a.stp",
                part21("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#3),$,$,$);\n"
                        + "#3=WORKPLAN('v',(#2),$,$,$);\n"),
                stepnc(),
                2,
                "contains itself"));
        c.add(new Case("p21-workplans-5000-deep", "a.stp", HostileFiles.workplanChain(5000), toolpath(), 2, "nested"));
        c.add(new Case("p21-workplans-99-deep", "a.stp", HostileFiles.workplanChain(99), stepnc(), 0, ""));
        // ---- STEP-NC numeric hazards into the toolpath
        String point = "#4=CARTESIAN_POINT('',(0.0,0.0,0.0));";
        String tool = "#29=MILLING_TOOL_DIMENSION(10.0,";
        String pocketWidth = "#40=TOLERANCED_LENGTH_MEASURE(20.0,";
        for (String v : List.of("1.E308", "-1.E308", "1.E15")) {
            c.add(new Case(
                    "stepnc-point-" + v,
                    "a.stp",
                    example2With(point, "#4=CARTESIAN_POINT('',(" + v + ",0.0,0.0));"),
                    toolpath(),
                    2,
                    "out of range"));
        }
        for (String v : List.of("0.", "-5.", "1.E-320", "1.E15", "1.E308")) {
            c.add(new Case(
                    "stepnc-tool-" + v,
                    "a.stp",
                    example2With(tool, "#29=MILLING_TOOL_DIMENSION(" + v + ","),
                    toolpath(),
                    -1,
                    ""));
            c.add(new Case(
                    "stepnc-width-" + v,
                    "a.stp",
                    example2With(pocketWidth, "#40=TOLERANCED_LENGTH_MEASURE(" + v + ","),
                    toolpath(),
                    -1,
                    ""));
        }
        // ---- DXF: counts, nesting, cycles, numbers, through cut, pocket and grade
        String square = HostileFiles.lwpolyline("", new double[][] {{0, 0}, {100, 0}, {100, 100}, {0, 100}}, null);
        Map<String, String> drawings = new LinkedHashMap<>();
        drawings.put(
                "lwpolyline-90-1e9",
                HostileFiles.lwpolyline(
                        "90\n1000000000\n", new double[][] {{0, 0}, {100, 0}, {100, 100}, {0, 100}}, null));
        drawings.put(
                "insert-self", dxf(List.<String[]>of(new String[] {"A", square + insert("A", 0)}), insert("A", 0)));
        drawings.put(
                "insert-cycle",
                dxf(
                        List.of(new String[] {"A", square + insert("B", 0)}, new String[] {"B", insert("A", 0)}),
                        insert("A", 0)));
        drawings.put("blocks-20000-deep", dxf(fanOut(20_000, 1, square), insert("B0", 0)));
        drawings.put("inserts-10-pow-15", dxf(fanOut(15, 10, ""), insert("B0", 0)));
        drawings.put("inserts-undefined-10-pow-4", dxf(fanOut(4, 10, null), insert("B0", 0)));
        drawings.put(
                "ellipse-u0-1e300",
                dxf(List.of(), "0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0.5\n41\n1e300\n42\n0\n"));
        drawings.put(
                "huge-lines",
                dxf(
                        List.of(),
                        HostileFiles.line("-1e308", "0", "1e308", "0")
                                + HostileFiles.line("1e308", "0", "1e308", "1e308")
                                + HostileFiles.line("1e308", "1e308", "-1e308", "0")));
        drawings.put(
                "degenerate-arcs",
                dxf(
                        List.of(),
                        "0\nARC\n8\n0\n10\n0\n20\n0\n40\n0\n50\n0\n51\n90\n"
                                + "0\nARC\n8\n0\n10\n0\n20\n0\n40\n-5\n50\n0\n51\n90\n"
                                + HostileFiles.line("0", "0", "0", "0")
                                + "0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n1e-300\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\nNaN\n"
                                + "0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\nInfinity\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n40\n"));
        drawings.put(
                "bulges",
                dxf(
                        List.of(),
                        HostileFiles.lwpolyline(
                                "",
                                new double[][] {{0, 0}, {100, 0}, {100, 100}, {0, 100}},
                                new double[] {1e308, 1e-300, -1e200, 0})));
        drawings.put(
                "near-parallel",
                dxf(
                        List.of(),
                        HostileFiles.lwpolyline("", new double[][] {{0, 0}, {100, 0}, {100, 1e-9}, {0, 2e-9}}, null)));
        drawings.put(
                "coincident-points",
                dxf(
                        List.of(),
                        HostileFiles.lwpolyline(
                                "",
                                new double[][] {{0, 0}, {0, 0}, {100, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 100}},
                                null)));
        drawings.put("polygon-30000", dxf(List.of(), HostileFiles.lwpolyline("", polygon(30_000, 100), null)));
        for (var d : drawings.entrySet()) {
            String text = d.getValue().startsWith("0\nSECTION") ? d.getValue() : dxf(List.of(), d.getValue());
            c.add(new Case("cut-" + d.getKey(), "a.dxf", text, cut(), -1, ""));
            if (!d.getKey().startsWith("inserts-") && !d.getKey().startsWith("blocks-")) {
                // the expansion limits are the reader's, already met through cut: only the geometry here
                c.add(new Case("pocket-" + d.getKey(), "a.dxf", text, pocket(), -1, ""));
            }
        }
        c.add(new Case(
                "grade-dxf-polygon-30000",
                "a.dxf",
                dxf(List.of(), HostileFiles.lwpolyline("", polygon(30_000, 100), null)),
                grade(),
                2,
                "at most 20000"));
        // ---- contours: huge, tiny, slivers, near-parallel, many elements
        Map<String, double[][]> contours = new LinkedHashMap<>();
        contours.put("square-2e9", new double[][] {{-1e9, -1e9}, {-1e9, 1e9}, {1e9, 1e9}, {1e9, -1e9}});
        contours.put("square-1e-5", new double[][] {{0, 0}, {0, 1e-5}, {1e-5, 1e-5}, {1e-5, 0}});
        contours.put("sliver", new double[][] {{0, 0}, {50, 1e-5}, {100, 0}});
        contours.put("near-parallel", new double[][] {{0, 0}, {0, 2e-7}, {100, 1e-7}, {100, 0}});
        contours.put(
                "spike", new double[][] {{0, 0}, {0, 10}, {5, 10}, {5.000001, 1e6}, {5, 10.000001}, {10, 10}, {10, 0}});
        contours.put("bow-tie", new double[][] {{0, 0}, {10, 10}, {10, 0}, {0, 10}});
        contours.put("polygon-20000", polygon(20_000, 100));
        for (var k : contours.entrySet()) {
            c.add(new Case("pocket-contour-" + k.getKey(), "a.contour", contour(k.getValue()), pocket(), -1, ""));
            c.add(new Case("grade-contour-" + k.getKey(), "a.contour", contour(k.getValue()), grade(), -1, ""));
        }
        c.add(new Case(
                "pocket-contour-NaN",
                "a.contour",
                "contour\nmove 0 0\nline NaN 0\nline 0 10\nline 0 0\n",
                pocket(),
                2,
                "out of range"));
        c.add(new Case(
                "pocket-contour-1e308",
                "a.contour",
                "contour\nmove 0 0\nline 1e308 0\nline 0 10\nline 0 0\n",
                pocket(),
                2,
                "out of range"));
        c.add(new Case(
                "pocket-arc-zero-radius", "a.contour", "contour\nmove 0 0\narc 0 0 0 0 ccw\n", pocket(), 2, "zero"));
        c.add(new Case(
                "pocket-zero-length-line",
                "a.contour",
                "contour\nmove 0 0\nline 0 0\nline 10 0\nline 0 0\n",
                pocket(),
                2,
                "zero-length"));
        c.add(new Case(
                "pocket-square-2e9-pass-budget",
                "a.contour",
                contour(contours.get("square-2e9")),
                pocket(),
                1,
                "more than 1000000 pass elements"));
        c.add(new Case(
                "grade-square-2e9", "a.contour", contour(contours.get("square-2e9")), grade(), 2, "at most 5000 mm"));
        return c;
    }

    @Test
    void hostileInputsEndCleanlyWithABoundedHeap() throws Exception {
        List<Case> cases = cases();
        StringBuilder plan = new StringBuilder();
        Map<String, Case> byName = new LinkedHashMap<>();
        for (Case c : cases) {
            Path caseDir = Files.createDirectories(dir.resolve(c.name()));
            Path in = caseDir.resolve(c.fileName());
            HostileFiles.write(in, c.content());
            Path out = Files.createDirectories(caseDir.resolve("out"));
            plan.append(c.name());
            for (String a : c.args()) {
                plan.append('\t').append(a.replace("IN", in.toString()).replace("OUT", out.toString()));
            }
            plan.append('\n');
            byName.put(c.name(), c);
        }
        Path planFile = dir.resolve("plan.txt");
        Files.writeString(planFile, plan);
        List<String> result = fork(planFile, 20 * 60);
        assertEquals("END", result.get(result.size() - 1), "the forked JVM ended early: " + String.join("\n", result));
        long maxMs = 0;
        String slowest = "";
        List<Executable> checks = new ArrayList<>();
        for (String line : result.subList(0, result.size() - 1)) {
            String[] f = line.split("\t", 4);
            Case c = byName.get(f[0]);
            int status = Integer.parseInt(f[1]);
            long ms = Long.parseLong(f[2]);
            String messages = f[3];
            if (ms > maxMs) {
                maxMs = ms;
                slowest = c.name();
            }
            Path out = dir.resolve(c.name()).resolve("out");
            List<Path> files;
            try (Stream<Path> s = Files.list(out)) {
                files = s.toList();
            }
            String what = c.name() + ": status " + status + ", " + ms + " ms, " + messages;
            checks.add(() -> assertAll(
                    what,
                    () -> assertTrue(status == 0 || status == 1 || status == 2),
                    () -> assertTrue(c.status() < 0 || c.status() == status, "status " + c.status() + " wanted"),
                    () -> assertTrue(messages.contains(c.words()), "says '" + c.words() + "'"),
                    () -> assertFalse(
                            messages.contains("internal error")
                                    || messages.contains("\tat ")
                                    || messages.contains("Exception"),
                            "no internal error"),
                    () -> assertTrue(ms < 30_000, "under 30 s"),
                    () -> assertTrue(status != 2 || files.isEmpty(), "nothing written for refused input: " + files),
                    () -> assertTrue(
                            files.stream()
                                    .noneMatch(p -> p.getFileName().toString().startsWith(AtomicFiles.TEMP_PREFIX)),
                            "no temporary file"),
                    () -> assertEquals(
                            List.of(),
                            nonFinite(files, messages.substring(messages.indexOf(" | ") + 3)),
                            "no NaN or Infinity in outputs")));
        }
        assertEquals(cases.size(), result.size() - 1);
        System.out.println("HostileCliTest: " + cases.size() + " commands, " + HEAP + " " + STACK + ", slowest "
                + slowest + " " + maxMs + " ms");
        assertAll(checks.stream());
    }

    static List<String> nonFinite(List<Path> files, String stdout) throws IOException {
        List<String> bad = new ArrayList<>();
        if (NON_FINITE.matcher(stdout).find()) {
            bad.add("stdout");
        }
        for (Path f : files) {
            if (f.getFileName().toString().endsWith(".png")) {
                continue;
            }
            if (NON_FINITE
                    .matcher(Files.readString(f, StandardCharsets.ISO_8859_1))
                    .find()) {
                bad.add(f.getFileName().toString());
            }
        }
        return bad;
    }

    /** Runs {@link HostileCliMain} in a JVM with the small heap and stack; its stdout and stderr lines. */
    static List<String> fork(Path plan, int timeoutS) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        ProcessBuilder pb = new ProcessBuilder(
                java,
                HEAP,
                STACK,
                "-Djava.awt.headless=true",
                "-XX:+UseSerialGC",
                "-cp",
                System.getProperty("java.class.path"),
                HostileCliMain.class.getName(),
                plan.toString());
        pb.redirectErrorStream(true);
        Path log = plan.resolveSibling("fork.log");
        pb.redirectOutput(log.toFile());
        Process p = pb.start();
        if (!p.waitFor(timeoutS, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("hostile commands hang (more than " + timeoutS + " s): " + Files.readString(log));
        }
        return Files.readAllLines(log, StandardCharsets.UTF_8);
    }
}
