package org.fresa.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.TestTag;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Counts the interpreter and corpus checks of one test JVM ({@link InterpreterCheck},
 * {@link CorpusCheck}): how many ran, failed, and were skipped with which reason. Registered with
 * the JUnit Platform through {@code META-INF/services}; when Maven names a folder
 * ({@value #FOLDER}) it writes the counts there at the end of the JVM's tests, and
 * {@link CheckCountLine} sums the files of the build into one line at the end of
 * {@code mvn verify}.
 */
public final class CheckCounter implements TestExecutionListener {

    public static final String INTERPRETER = "interpreter";
    public static final String CORPUS = "corpus";

    /** System property: the folder for the counts (Maven sets it for surefire). */
    static final String FOLDER = "fresa.checkCounts";

    /** System property: the build's start time, so that a build sums only its own files. */
    static final String BUILD = "fresa.build";

    static final String RAN = "ran";
    static final String FAILED = "failed";
    static final String SKIPPED = "skipped";

    /** kind, outcome, reason (empty unless skipped) to count. */
    record Key(String kind, String outcome, String reason) implements Comparable<Key> {
        @Override
        public int compareTo(Key o) {
            return (kind + '\t' + outcome + '\t' + reason).compareTo(o.kind + '\t' + o.outcome + '\t' + o.reason);
        }
    }

    private final Map<Key, Integer> counts = new TreeMap<>();
    private TestPlan plan;

    @Override
    public void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
    }

    @Override
    public void executionSkipped(TestIdentifier id, String reason) {
        for (TestIdentifier t : checksUnder(id)) {
            count(t, SKIPPED, reason);
        }
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        if (id.isTest()) {
            switch (result.getStatus()) {
                case SUCCESSFUL -> count(id, RAN, "");
                case FAILED -> count(id, FAILED, "");
                default -> count(id, SKIPPED, reason(result));
            }
        } else if (result.getStatus() == TestExecutionResult.Status.ABORTED) {
            // an assumption before any of its tests (a parameter source, @BeforeAll): they never start
            for (TestIdentifier t : checksUnder(id)) {
                count(t, SKIPPED, reason(result));
            }
        }
    }

    @Override
    public void testPlanExecutionFinished(TestPlan testPlan) {
        String folder = System.getProperty(FOLDER);
        if (folder == null || counts.isEmpty()) {
            return;
        }
        StringBuilder sb = new StringBuilder();
        counts.forEach((k, n) -> sb.append(k.kind())
                .append('\t')
                .append(k.outcome())
                .append('\t')
                .append(n)
                .append('\t')
                .append(k.reason())
                .append('\n'));
        try {
            Path dir = Files.createDirectories(Path.of(folder));
            Path tmp = Files.createTempFile(dir, ".counts", ".part");
            Files.writeString(tmp, sb, StandardCharsets.UTF_8);
            Files.move(
                    tmp,
                    dir.resolve(fileName(System.getProperty(BUILD, ""))
                            + ProcessHandle.current().pid() + "-" + System.nanoTime() + ".tsv"));
        } catch (IOException e) {
            throw new UncheckedIOException("the check counts could not be written into " + folder, e);
        }
    }

    /** The start of the counts files of one build. */
    static String fileName(String build) {
        return "build-" + build.replaceAll("[^A-Za-z0-9]", "_") + "-";
    }

    /** The tagged tests at or under a node; the node itself when it is a tagged container with none yet. */
    private List<TestIdentifier> checksUnder(TestIdentifier id) {
        if (id.isTest() || plan == null) {
            return List.of(id);
        }
        List<TestIdentifier> tests =
                plan.getDescendants(id).stream().filter(TestIdentifier::isTest).toList();
        return tests.isEmpty() ? List.of(id) : tests;
    }

    private void count(TestIdentifier id, String outcome, String reason) {
        for (TestTag tag : id.getTags()) {
            if (tag.getName().equals(INTERPRETER) || tag.getName().equals(CORPUS)) {
                counts.merge(new Key(tag.getName(), outcome, oneLine(reason)), 1, Integer::sum);
            }
        }
    }

    private static String reason(TestExecutionResult result) {
        Optional<Throwable> t = result.getThrowable();
        String m = t.map(Throwable::getMessage).orElse("");
        return m == null
                ? t.map(x -> x.getClass().getSimpleName()).orElse("")
                : m.replaceFirst("^Assumption failed: ", "");
    }

    private static String oneLine(String reason) {
        String r = reason == null ? "" : reason.strip().replaceAll("\\s+", " ");
        return r.length() > 200 ? r.substring(0, 197) + "..." : r;
    }
}
