package org.fresa.robustness;

import static org.fresa.robustness.HostileFiles.LINE;
import static org.fresa.robustness.HostileFiles.dxf;
import static org.fresa.robustness.HostileFiles.fanOut;
import static org.fresa.robustness.HostileFiles.insert;
import static org.fresa.robustness.HostileFiles.nested;
import static org.fresa.robustness.HostileFiles.part21;
import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
import org.fresa.model.CamInputException;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * Absurd counts, deep nesting and cycles straight into the readers: each gives one
 * CamInputException naming the line and what was expected, or a drawing read with a warning;
 * never an OutOfMemoryError, a StackOverflowError or a hang. The same files also go through the
 * command line with a small heap in {@link HostileCliTest}.
 */
class HostileReadersTest {

    private static final Duration HANG_GUARD = Duration.ofSeconds(20);

    static StepNcProgram read(String text) throws Exception {
        return StepNcReader.read(new ByteArrayInputStream(text.getBytes(StandardCharsets.ISO_8859_1)), "h.stp");
    }

    static CamInputException refused(String text) {
        return assertTimeoutPreemptively(HANG_GUARD, () -> assertThrows(CamInputException.class, () -> read(text)));
    }

    static void assertAt(CamInputException e, int line, String words) {
        assertAll(
                e.getMessage(),
                () -> assertEquals(line, e.line().orElse(0)),
                () -> assertTrue(e.getMessage().contains(words)),
                () -> assertTrue(e.getMessage().length() < 300, "one short message"));
    }

    @Test
    void aTwentyDigitInstanceNameIsRefusedAtItsLine() {
        assertAt(refused(part21("#12345678901234567890=X(1);\n")), 8, "larger than 64 bits");
        assertAt(refused(part21("#1=X(#99999999999999999999);\n")), 8, "larger than 64 bits");
    }

    @Test
    void a100000DeepListIsRefusedNotOverflowingTheStack() {
        assertAt(refused(part21("#1=X(" + nested("(", "", ")", 100_000) + ");\n")), 8, "nested more than 256 deep");
        assertAt(refused(part21("#1=X(" + nested("A(", "1", ")", 100_000) + ");\n")), 8, "nested more than 256 deep");
        assertAt(refused(part21("#1=(" + nested("(", "", ")", 100_000) + ");\n")), 8, "complex instance");
        assertAt(
                refused(part21("#1=(" + "A()".repeat(100_000) + nested("B(", "1", ")", 100_000) + ");\n")),
                8,
                "nested more than 256 deep");
    }

    @Test
    void nestingJustUnderTheLimitsIsReadOnASmallStack() throws Exception {
        // the limits leave room: read and bound on a 512 KiB stack (the default is 1 MiB or more)
        AtomicReference<Throwable> failure = new AtomicReference<>();
        AtomicReference<StepNcProgram> deep = new AtomicReference<>();
        Thread t = new Thread(
                null,
                () -> {
                    try {
                        read(part21("#1=X(" + nested("(", "", ")", 254) + ");\n#2=Y(" + nested("A(", "1", ")", 254)
                                + ");\n"));
                        deep.set(read(HostileFiles.workplanChain(99)));
                    } catch (Throwable e) {
                        failure.set(e);
                    }
                },
                "small-stack",
                512 * 1024);
        t.start();
        t.join(HANG_GUARD.toMillis());
        assertAll(
                () -> assertEquals(null, failure.get()),
                () -> assertTrue(deep.get() != null && deep.get().mainWorkplan().isPresent()));
    }

    @Test
    void aWorkplanContainingItselfIsRefusedDirectlyAndThroughOthers() {
        assertAt(
                refused(part21("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#2),$,$,$);\n")),
                9,
                "workplan contains itself");
        assertAt(
                refused(part21("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#3),$,$,$);\n"
                        + "#3=WORKPLAN('v',(#4),$,$,$);\n#4=WORKPLAN('u',(#2),$,$,$);\n")),
                9,
                "workplan contains itself");
        assertAt(refused(HostileFiles.workplanChain(5000)), 9 + 100, "nested more than 100 deep");
    }

    @Test
    void selfReferencesOutsideTheWorkplansAreReadInBoundedTime() throws Exception {
        StepNcProgram p = assertTimeoutPreemptively(
                HANG_GUARD,
                () -> read(part21("#1=X(#1);\n#2=Y(#3);\n#3=Y(#2);\n"
                        + "#4=NUMERIC_PARAMETER('a',#4,'mm');\n#5=TOLERANCED_LENGTH_MEASURE(#6,$);\n"
                        + "#6=TOLERANCED_LENGTH_MEASURE(#5,$);\n")));
        assertEquals(6, p.instanceCount());
    }

    @Test
    void aPointFarOutIsRefusedAtItsLine() throws Exception {
        String s = HostileFiles.example2With(
                "#4=CARTESIAN_POINT('',(0.0,0.0,0.0));", "#4=CARTESIAN_POINT('',(1.E308,0.0,0.0));");
        CamInputException e = refused(s);
        assertTrue(e.getMessage().contains("#4") && e.getMessage().contains("out of range"), e.getMessage());
    }

    // ---------------------------------------------------------------- DXF

    static DxfDrawing readDxf(String text) {
        return assertTimeoutPreemptively(
                HANG_GUARD,
                () -> DxfReader.read(text.getBytes(StandardCharsets.ISO_8859_1), "h.dxf", DxfReadOptions.DEFAULT));
    }

    static boolean warns(DxfDrawing d, String words) {
        return d.warnings().stream().anyMatch(w -> w.contains(words));
    }

    @Test
    void aPolylineClaimingABillionVerticesIsReadByItsVertices() {
        double[][] tri = {{0, 0}, {10, 0}, {10, 10}};
        DxfDrawing lw = readDxf(dxf(List.of(), HostileFiles.lwpolyline("90\n1000000000\n", tri, null)));
        DxfDrawing old = readDxf(dxf(
                List.of(),
                "0\nPOLYLINE\n8\n0\n66\n1\n70\n1\n71\n1000000000\n72\n1000000000\n"
                        + "0\nVERTEX\n8\n0\n10\n0\n20\n0\n0\nVERTEX\n8\n0\n10\n10\n20\n0\n0\nVERTEX\n8\n0\n10\n10\n20\n10\n"
                        + "0\nSEQEND\n"));
        assertAll(
                () -> assertEquals(3, lw.curves().size()),
                () -> assertEquals(3, old.curves().size()));
    }

    @Test
    void aBlockInsertingItselfIsExpandedOnce() {
        DxfDrawing self = readDxf(dxf(List.<String[]>of(new String[] {"A", LINE + insert("A", 0)}), insert("A", 0)));
        DxfDrawing cycle = readDxf(dxf(
                List.of(new String[] {"A", LINE + insert("B", 0)}, new String[] {"B", LINE + insert("A", 0)}),
                insert("A", 0)));
        assertAll(
                () -> assertEquals(1, self.curves().size()),
                () -> assertTrue(warns(self, "inserts itself")),
                () -> assertEquals(2, cycle.curves().size()),
                () -> assertTrue(
                        warns(cycle, "cycle: A -> B -> A"), cycle.warnings().toString()));
    }

    @Test
    void blocksNested100000DeepStopAtTheDepthLimit() {
        List<String[]> chain = fanOut(100_000, 1, LINE);
        DxfDrawing d = readDxf(dxf(chain, insert("B0", 0)));
        assertAll(() -> assertEquals(0, d.curves().size()), () -> assertTrue(warns(d, "nested deeper than 16")));
    }

    @Test
    void exponentiallyNestedInsertsOfEmptyBlocksStopAtTheExpansionBudget() {
        // 10^15 inserts and not one curve: formerly a hang; now cut after a bounded number of entities
        // refused past the budget (exit 2), not cut short
        byte[] fan = dxf(fanOut(15, 10, ""), insert("B0", 0)).getBytes(StandardCharsets.ISO_8859_1);
        String refused = assertTimeoutPreemptively(
                        HANG_GUARD,
                        () -> org.junit.jupiter.api.Assertions.assertThrows(
                                org.fresa.dxf.DxfException.class,
                                () -> DxfReader.read(fan, "h.dxf", DxfReadOptions.DEFAULT)))
                .getMessage();
        DxfDrawing undefined = readDxf(dxf(fanOut(4, 10, null), insert("B0", 0)));
        assertAll(
                () -> assertTrue(refused.contains("expand to more than"), refused),
                () -> assertTrue(warns(undefined, "is not defined")),
                () -> assertTrue(
                        undefined.warnings().size() <= 1002,
                        "warnings bounded: " + undefined.warnings().size()),
                () -> assertTrue(warns(undefined, "more warnings like the ones above")));
    }

    @Test
    void aBillionByBillionInsertArrayIsCut() {
        DxfDrawing d = readDxf(dxf(
                List.<String[]>of(new String[] {"A", LINE}),
                "0\nINSERT\n8\n0\n2\nA\n10\n0\n20\n0\n70\n1000000000\n71\n1000000000\n44\n20\n45\n20\n"));
        assertAll(() -> assertEquals(10_000, d.curves().size()), () -> assertTrue(warns(d, "cut to the first 10000")));
    }

    @Test
    void anEllipseWithHugeParametersEnds() {
        // u0 = 1e300, u1 = 0: adding 2 pi until the sweep is positive never ended
        String normal = "0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0.5\n41\n0\n42\n6.283185307179586\n";
        DxfDrawing d = readDxf(dxf(
                List.of(),
                "0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0.5\n41\n1e300\n42\n0\n"
                        + "0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0.5\n41\n1e17\n42\n-1e17\n" + normal));
        // at 1e300 the sweep is below the parameter's resolution: those ellipses add nothing
        assertEquals(readDxf(dxf(List.of(), normal)).curves().size(), d.curves().size());
    }

    @Test
    void coordinatesBeyondAThousandKilometresAreLeftOutWithAWarning() {
        DxfDrawing d = readDxf(dxf(
                List.of(),
                HostileFiles.line("-1e308", "0", "1e308", "0")
                        + "0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n1e308\n" + HostileFiles.line("0", "0", "1e10", "0")
                        + "0\nINSERT\n8\n0\n2\nA\n10\n0\n20\n0\n41\n1e300\n42\n1e300\n" + LINE));
        assertAll(() -> assertEquals(1, d.curves().size()), () -> assertTrue(warns(d, "coordinates beyond")));
    }
}
