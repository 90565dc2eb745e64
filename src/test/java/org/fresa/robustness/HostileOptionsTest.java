package org.fresa.robustness;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.fresa.app.cli.FresaCommand;
import org.fresa.io.AtomicFiles;
import org.fresa.io.FolderLock;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Every numeric option of every command with values a typo or a script produces: 0,
 * -1, NaN, inf, -inf, 1e308, 1e-9 and the limits of the option's type. The options are found by
 * walking the command line's own model, so an option added later is tested too; a command with
 * numeric options needs a base command line here, which the test asks for.
 *
 * <p>Each case runs in a JVM with a small heap (as {@link HostileCliTest}) and must end within
 * 10 s of CPU time (the machine may be shared: a case is also stopped after a minute of wall
 * time) with exit 0, 1 or 2 and no trace; a value that no physical range holds (NaN, the
 * infinities, 1e308, the type's extremes) is refused with exit 2 by a message naming the
 * option, and a refused command writes nothing, not even its folder's lock.
 */
class HostileOptionsTest {

    static final long LIMIT_CPU_MS = 10_000;
    static final long DEADLINE_MS = 60_000;
    static final String HEAP = "-Xmx256m";

    static final List<String> DOUBLES = List.of(
            "0",
            "-1",
            "NaN",
            "inf",
            "-inf",
            "Infinity",
            "-Infinity",
            "1e308",
            "-1e308",
            "1e-9",
            "4.9E-324",
            "1.7976931348623157E308",
            "-1.7976931348623157E308");
    static final List<String> INTS =
            List.of("0", "-1", "NaN", "inf", "-inf", "1e308", "1e-9", "2147483647", "-2147483648");
    static final List<String> LONGS =
            List.of("0", "-1", "NaN", "inf", "-inf", "1e308", "1e-9", "9223372036854775807", "-9223372036854775808");
    /** Values beyond any physical range: refused with exit 2 naming the option. */
    static final Set<String> ABSURD = Set.of(
            "NaN",
            "inf",
            "-inf",
            "Infinity",
            "-Infinity",
            "1e308",
            "-1e308",
            "1.7976931348623157E308",
            "-1.7976931348623157E308",
            "2147483647",
            "-2147483648",
            "9223372036854775807",
            "-9223372036854775808");

    @TempDir
    Path dir;

    /** A command's base line: IN files, OUT its output path (a folder, or a file in it). */
    Map<String, List<String>> bases() throws Exception {
        Path one = dir.resolve("one-hole.stp");
        // ISO 14649-11 example 1 with its drilling only: seven points, so that every robot case is short
        Files.writeString(
                one,
                Files.readString(Path.of("samples/stepnc/iso14649-11-example1.stp"))
                        .replace("(#10,#11,#12,#13,#14)", "(#11)"));
        Path targets = dir.resolve("targets.csv");
        Files.writeString(targets, "x,y,z,roll,pitch,yaw\n500,0,400,0,90,0\n");
        Map<String, List<String>> m = new LinkedHashMap<>();
        m.put("pocket", List.of("pocket", "samples/pocket/cavity01.dad", "--out", "OUT/p.ngc", "--tool-diameter", "6"));
        m.put("cut", List.of("cut", "samples/cutting/plate.dxf", "--out", "OUT/c.ngc"));
        m.put(
                "grade",
                List.of(
                        "grade",
                        "samples/grading/sole-40.contour",
                        "--out",
                        "OUT",
                        "--base-size",
                        "40",
                        "--sizes",
                        "40-41",
                        "--system",
                        "br"));
        m.put(
                "robot",
                List.of(
                        "robot",
                        one.toString(),
                        "--robot",
                        "irb140",
                        "--out",
                        "OUT",
                        "--robot-table",
                        "450,0,350",
                        "--table-piece",
                        "0,10,0",
                        "--formats",
                        "csv"));
        m.put("toolpath", List.of("toolpath", one.toString(), "--out", "OUT"));
        m.put("ik", List.of("ik", targets.toString(), "--robot", "irb140", "--out", "OUT"));
        m.put("toolpath", List.of("toolpath", one.toString(), "--out", "OUT"));
        return m;
    }

    /** One command line: which option it varies, with which value. */
    record Case(String name, String option, String value, boolean absurd, List<String> args) {}

    /** The values an option is given: a number type's list, or per slot of a comma list (X,Y,Z). */
    static List<String[]> values(OptionSpec o) {
        List<String[]> out = new ArrayList<>();
        Class<?> t = o.type();
        List<String> list = t == double.class || t == Double.class || t == float.class || t == Float.class
                ? DOUBLES
                : t == int.class || t == Integer.class ? INTS : t == long.class || t == Long.class ? LONGS : null;
        if (list != null) {
            list.forEach(v -> out.add(new String[] {v, v}));
            return out;
        }
        String label = o.paramLabel();
        if (t == String.class && label.equals("A-B")) {
            for (String v : DOUBLES) {
                out.add(new String[] {v + "-41", v});
                out.add(new String[] {"40-" + v, v});
            }
        } else if (t == String.class && label.contains(",")) {
            int slots = label.replaceAll("[\\[\\]]", "").split(",").length;
            for (int k = 0; k < slots; k++) {
                for (String v : DOUBLES) {
                    String[] parts = new String[slots];
                    java.util.Arrays.fill(parts, "0");
                    parts[k] = v;
                    out.add(new String[] {String.join(",", parts), v});
                }
            }
        }
        return out;
    }

    List<Case> cases(List<String> missingBases) throws Exception {
        Map<String, List<String>> bases = bases();
        List<Case> cases = new ArrayList<>();
        CommandLine all = FresaCommand.withAllCommands();
        for (Map.Entry<String, CommandLine> c : all.getSubcommands().entrySet()) {
            List<OptionSpec> numeric = c.getValue().getCommandSpec().options().stream()
                    .filter(o -> !values(o).isEmpty())
                    .toList();
            if (numeric.isEmpty()) {
                continue;
            }
            List<String> base = bases.get(c.getKey());
            if (base == null) {
                missingBases.add(c.getKey());
                continue;
            }
            for (OptionSpec o : numeric) {
                for (String[] v : values(o)) {
                    List<String> args = new ArrayList<>(base);
                    int at = args.indexOf(o.longestName());
                    if (at >= 0) {
                        args.set(at + 1, v[0]);
                    } else {
                        args.add(o.longestName());
                        args.add(v[0]);
                    }
                    String name = c.getKey() + " " + o.longestName() + " " + v[0];
                    cases.add(new Case(name, o.longestName(), v[0], ABSURD.contains(v[1]), args));
                }
            }
        }
        return cases;
    }

    @Test
    void everyNumericOptionEndsWithinTenSecondsWithAStatusAndNoTrace() throws Exception {
        List<String> missing = new ArrayList<>();
        List<Case> cases = cases(missing);
        StringBuilder plan = new StringBuilder();
        for (int i = 0; i < cases.size(); i++) {
            Path out = Files.createDirectories(dir.resolve("case-" + i));
            plan.append(cases.get(i).name().replace('\t', ' '));
            for (String a : cases.get(i).args()) {
                plan.append('\t').append(a.replace("OUT", out.toString()));
            }
            plan.append('\n');
        }
        Path planFile = dir.resolve("plan.txt");
        Files.writeString(planFile, plan);
        List<String[]> results = runAll(planFile, cases.size());

        long worst = 0;
        long worstWall = 0;
        String slowest = "";
        Map<String, Integer> statuses = new TreeMap<>();
        List<Executable> checks = new ArrayList<>();
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            String[] r = results.get(i);
            String status = r[1];
            long ms = Long.parseLong(r[2]);
            long cpuMs = Long.parseLong(r[3]);
            String err = r[4];
            statuses.merge(status, 1, Integer::sum);
            if (cpuMs > worst) {
                worst = cpuMs;
                slowest = c.name() + " (" + ms + " ms wall)";
            }
            worstWall = Math.max(worstWall, ms);
            List<String> left = names(dir.resolve("case-" + i));
            checks.add(() -> assertAll(
                    c.name() + ": status " + status + ", " + cpuMs + " ms CPU, " + ms + " ms, " + err,
                    () -> assertTrue(Set.of("0", "1", "2").contains(status), "exit 0, 1 or 2"),
                    () -> assertTrue(cpuMs < LIMIT_CPU_MS, "within 10 s of CPU time"),
                    () -> assertFalse(
                            err.contains("internal error")
                                    || err.contains("\tat ")
                                    || err.contains("Exception")
                                    || err.contains("must be finite"),
                            "no trace, no internal error"),
                    () -> assertTrue(!c.absurd() || status.equals("2"), "a value beyond any range is refused (exit 2)"),
                    () -> assertTrue(
                            !c.absurd()
                                    || err.contains(c.option())
                                    || c.option().equals("--sizes") && err.contains("size"),
                            "the message names " + c.option()),
                    () -> assertTrue(!status.equals("2") || left.isEmpty(), "nothing written when refused: " + left),
                    () -> assertTrue(
                            left.stream()
                                    .noneMatch(n ->
                                            n.startsWith(AtomicFiles.TEMP_PREFIX) || n.equals(FolderLock.FILE_NAME)),
                            "no temporary or lock file: " + left)));
        }
        System.out.println("HostileOptionsTest: " + cases.size() + " cases, " + HEAP + ", exit statuses " + statuses
                + ", most CPU " + worst + " ms: " + slowest + "; longest wall time " + worstWall + " ms");
        assertEquals(List.of(), missing, "commands with numeric options need a base command line in this test");
        assertAll(checks.stream());
    }

    /** Every case's {name, status, ms, CPU ms, stderr}, in plan order, starting a new JVM after a case past its deadline. */
    List<String[]> runAll(Path plan, int n) throws Exception {
        List<String[]> results = new ArrayList<>();
        int fork = 0;
        while (results.size() < n) {
            Path log = dir.resolve("fork-" + fork++ + ".log");
            String java =
                    Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process p = new ProcessBuilder(
                            java,
                            HEAP,
                            HostileCliTest.STACK,
                            "-Djava.awt.headless=true",
                            "-XX:+UseSerialGC",
                            "-cp",
                            System.getProperty("java.class.path"),
                            HostileOptionsMain.class.getName(),
                            plan.toString(),
                            Integer.toString(results.size()),
                            Long.toString(DEADLINE_MS))
                    .redirectErrorStream(true)
                    .redirectOutput(log.toFile())
                    .start();
            if (!p.waitFor(20, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                throw new AssertionError("the hostile options hang beyond their deadlines: " + Files.readString(log));
            }
            int before = results.size();
            for (String line : Files.readAllLines(log, StandardCharsets.UTF_8)) {
                String[] f = line.split("\t", 5);
                if (f.length == 5 && f[2].matches("\\d+")) {
                    results.add(f);
                }
            }
            if (results.size() == before) {
                throw new AssertionError("the runner JVM ended without a result: " + Files.readString(log));
            }
        }
        return results;
    }

    static List<String> names(Path d) throws Exception {
        try (Stream<Path> s = Files.walk(d)) {
            return s.filter(p -> !p.equals(d))
                    .map(p -> d.relativize(p).toString())
                    .sorted()
                    .toList();
        }
    }
}
