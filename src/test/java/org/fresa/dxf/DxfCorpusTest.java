package org.fresa.dxf;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

class DxfCorpusTest {

    static final Path CORPUS = TestInputs.DXF_CORPUS;

    static List<Path> corpusFiles() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(CORPUS), "corpus absent");
        try (Stream<Path> s = Files.walk(CORPUS)) {
            return s.filter(p -> p.toString().toLowerCase().endsWith(".dxf"))
                    .sorted()
                    .toList();
        }
    }

    @Test
    @CorpusCheck
    void everyCorpusDrawingIsReadWithoutACrash() throws Exception {
        StringBuilder report = new StringBuilder();
        for (Path p : corpusFiles()) {
            DxfDrawing d = DxfReader.read(p);
            {
                report.append(p.getFileName() + " units=" + d.units() + " curves=" + d.curveCount() + " layers="
                                + d.layers().size() + " ignored=" + d.ignored() + " warnings="
                                + d.warnings().size()
                                + (d.warnings().isEmpty()
                                        ? ""
                                        : " first: " + d.warnings().get(0)))
                        .append('\n');
            }
        }
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target/dxf-corpus.txt"), report);
    }

    @Test
    @CorpusCheck
    void malformedSplineFileIsNamedAndStillRead() throws Exception {
        Path p = CORPUS.resolve("dxf2gcode/Spline_Problem.dxf");
        Assumptions.assumeTrue(Files.exists(p));
        DxfDrawing d = DxfReader.read(p);
        assertFalse(d.curves().isEmpty());
        assertTrue(
                d.warnings().stream().anyMatch(w -> w.contains("SPLINE") && w.contains("line 6")),
                d.warnings().toString());
    }

    @Test
    @CorpusCheck
    void circlesWithRadiusZeroOrLessAreNamedByHandleAndTheRestIsKept() throws Exception {
        Path p = CORPUS.resolve("ezdxf/examples_dxf_circle_radius_le_0.dxf");
        Assumptions.assumeTrue(Files.exists(p));
        DxfDrawing d = DxfReader.read(p);
        assertTrue(
                d.warnings().stream().anyMatch(w -> w.contains("CIRCLE 2D") && w.contains("line 2002")),
                d.warnings().toString());
        assertTrue(
                d.warnings().stream().anyMatch(w -> w.contains("CIRCLE 2E")),
                d.warnings().toString());
    }

    /** Every DXF version in the corpus (R12 AC1009 to R2018 AC1032, and older) gives curves from some file. */
    @Test
    @CorpusCheck
    void everyDxfVersionOfTheCorpusIsRead() throws Exception {
        java.util.Map<String, Integer> curvesByVersion = new java.util.TreeMap<>();
        for (Path p : corpusFiles()) {
            String text = new String(Files.readAllBytes(p), java.nio.charset.StandardCharsets.ISO_8859_1);
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\$ACADVER\\s+1\\s+(AC\\d{4})")
                    .matcher(text);
            String v = m.find() ? m.group(1) : text.startsWith("AutoCAD Binary DXF") ? "binary" : "none";
            curvesByVersion.merge(v, DxfReader.read(p).curveCount(), Integer::sum);
        }
        for (String v : List.of("AC1009", "AC1015", "AC1018", "AC1021", "AC1024", "AC1027", "AC1032")) {
            if (curvesByVersion.containsKey(v)) {
                assertTrue(curvesByVersion.get(v) > 0, v + ": " + curvesByVersion);
            }
        }
        assertTrue(
                curvesByVersion.keySet().stream()
                                .filter(k -> k.startsWith("AC"))
                                .count()
                        >= 3,
                curvesByVersion.toString());
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target/dxf-versions.txt"), curvesByVersion.toString());
    }
}
