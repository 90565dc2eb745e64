package org.fresa.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

/**
 * The line at the end of {@code mvn verify} (the exec plugin runs it in the verify phase): how
 * many interpreter and corpus checks ran in this build, summed over the test JVMs' files that
 * {@link CheckCounter} wrote, and how many were skipped and why.
 *
 * <pre>
 * CheckCountLine FOLDER BUILD
 * </pre>
 */
public final class CheckCountLine {

    private static final Map<String, String> TITLES = Map.of(
            CheckCounter.INTERPRETER, "Interpreter checks (LinuxCNC's rs274)",
            CheckCounter.CORPUS, "corpus checks (files written by other programs)");

    private CheckCountLine() {}

    public static void main(String[] args) throws IOException {
        Path folder = Path.of(args[0]);
        String build = args.length > 1 ? args[1] : "";
        System.out.println(line(read(folder, CheckCounter.fileName(build))));
    }

    /** kind to outcome to reason to count, from the files of one build. */
    static Map<String, Map<String, Map<String, Integer>>> read(Path folder, String prefix) throws IOException {
        Map<String, Map<String, Map<String, Integer>>> sums = new LinkedHashMap<>();
        for (String kind : List.of(CheckCounter.INTERPRETER, CheckCounter.CORPUS)) {
            sums.put(kind, new TreeMap<>());
        }
        if (!Files.isDirectory(folder)) {
            return sums;
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(folder)) {
            files = s.filter(p -> p.getFileName().toString().startsWith(prefix))
                    .sorted()
                    .toList();
        }
        for (Path f : files) {
            for (String l : Files.readAllLines(f, StandardCharsets.UTF_8)) {
                String[] c = l.split("\t", 4);
                if (c.length == 4) {
                    sums.computeIfAbsent(c[0], k -> new TreeMap<>())
                            .computeIfAbsent(c[1], k -> new LinkedHashMap<>())
                            .merge(c[3], Integer.parseInt(c[2]), Integer::sum);
                }
            }
        }
        return sums;
    }

    /** One line: for each kind, ran (failed), skipped, and each reason of a skip with its count. */
    static String line(Map<String, Map<String, Map<String, Integer>>> sums) {
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, Map<String, Map<String, Integer>>> k : sums.entrySet()) {
            Map<String, Map<String, Integer>> byOutcome = k.getValue();
            int ran = total(byOutcome.get(CheckCounter.RAN));
            int failed = total(byOutcome.get(CheckCounter.FAILED));
            Map<String, Integer> skipped = byOutcome.getOrDefault(CheckCounter.SKIPPED, Map.of());
            StringBuilder sb = new StringBuilder(TITLES.getOrDefault(k.getKey(), k.getKey() + " checks"))
                    .append(": ")
                    .append(ran + failed)
                    .append(" ran");
            if (failed > 0) {
                sb.append(" (").append(failed).append(" failed)");
            }
            sb.append(", ").append(total(skipped)).append(" skipped");
            if (!skipped.isEmpty()) {
                List<String> why = new ArrayList<>();
                skipped.forEach((reason, n) -> why.add(n + ": " + (reason.isEmpty() ? "no reason given" : reason)));
                sb.append(" (").append(String.join("; ", why)).append(')');
            }
            parts.add(sb.toString());
        }
        return "[fresa] " + String.join("; ", parts) + ".";
    }

    private static int total(Map<String, Integer> m) {
        return m == null ? 0 : m.values().stream().mapToInt(Integer::intValue).sum();
    }
}
