package org.fresa;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The "Dependencies: ..." sentence of each package-info and the per-package rules of
 * {@link ArchitectureTest} say the same, so that the words a newcomer reads are the ones checked.
 */
class PackageStatementsTest {

    static final Path SOURCES = Path.of("src/main/java/org/fresa");

    /** The top layers, whose arrows the layered rule states (docs/architecture.md). */
    static final Set<String> LAYERED_ONLY = Set.of("app", "app.cli", "ui");

    private static final Pattern DEPENDENCIES =
            Pattern.compile("Dependencies:(.*?)(?:\\.\\s*(?:\\n|\\*/|<p>)|\\bnever\\b)", Pattern.DOTALL);
    private static final Pattern CODE = Pattern.compile("\\{@code ([a-z.]+)\\}");

    @Test
    void everyPackageBelowTheUiStatesItsDependenciesAsTheRulesDo() throws IOException {
        List<String> differences = new ArrayList<>();
        for (String pkg : packages()) {
            if (LAYERED_ONLY.contains(pkg)) {
                continue;
            }
            Set<String> rule =
                    new TreeSet<>(ArchitectureTest.STATED_DEPENDENCIES.getOrDefault(pkg, List.of("(no rule)")));
            Set<String> said = stated(pkg);
            if (!rule.equals(said)) {
                differences.add(pkg + ": package-info says " + said + ", ArchitectureTest has " + rule);
            }
        }
        assertEquals(List.of(), differences);
    }

    /** The list of arrows in docs/architecture.md names, per package, the packages of its rule. */
    @Test
    void theArchitectureDocumentListsTheArrowsOfTheRules() throws IOException {
        Pattern arrow = Pattern.compile("^- `([a-z.]+)` -> (.*)$", Pattern.MULTILINE);
        Matcher m = arrow.matcher(Files.readString(Path.of("docs/architecture.md")));
        java.util.Map<String, Set<String>> listed = new java.util.TreeMap<>();
        while (m.find()) {
            Set<String> to = new TreeSet<>();
            Matcher c = Pattern.compile("`([a-z.]+)`").matcher(m.group(2));
            while (c.find()) {
                to.add(c.group(1));
            }
            listed.put(m.group(1), to);
        }
        java.util.Map<String, Set<String>> rules = new java.util.TreeMap<>();
        ArchitectureTest.STATED_DEPENDENCIES.forEach((pkg, deps) -> rules.put(pkg, new TreeSet<>(deps)));
        assertEquals(rules, listed);
    }

    @Test
    void everyRuleHasItsPackage() throws IOException {
        assertTrue(
                packages().containsAll(ArchitectureTest.STATED_DEPENDENCIES.keySet()),
                ArchitectureTest.STATED_DEPENDENCIES.keySet() + " vs " + packages());
    }

    /** The Fresa packages named in the package's "Dependencies:" sentence, up to a "never". */
    static Set<String> stated(String pkg) throws IOException {
        Path info = SOURCES.resolve(pkg.replace('.', '/')).resolve("package-info.java");
        String text = Files.exists(info) ? Files.readString(info) : "";
        Matcher m = DEPENDENCIES.matcher(text);
        Set<String> names = new TreeSet<>();
        if (!m.find()) {
            names.add("(no Dependencies: sentence in " + info + ")");
            return names;
        }
        Set<String> known = packages();
        Matcher c = CODE.matcher(m.group(1));
        while (c.find()) {
            if (known.contains(c.group(1))) {
                names.add(c.group(1));
            }
        }
        return names;
    }

    /** Every package of the main sources that holds classes, relative to org.fresa. */
    static Set<String> packages() throws IOException {
        try (Stream<Path> s = Files.walk(SOURCES)) {
            return s.filter(p -> p.toString().endsWith(".java"))
                    .map(Path::getParent)
                    .distinct()
                    .map(d -> SOURCES.relativize(d).toString().replace('/', '.'))
                    .filter(n -> !n.isEmpty())
                    .collect(java.util.stream.Collectors.toCollection(TreeSet::new));
        }
    }
}
