package org.fresa.dxf;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Test;

class DxfReaderTest {

    static String dxf(String header, String blocks, String entities) {
        StringBuilder sb = new StringBuilder();
        if (!header.isEmpty()) {
            sb.append("0\nSECTION\n2\nHEADER\n").append(header).append("0\nENDSEC\n");
        }
        if (!blocks.isEmpty()) {
            sb.append("0\nSECTION\n2\nBLOCKS\n").append(blocks).append("0\nENDSEC\n");
        }
        sb.append("0\nSECTION\n2\nENTITIES\n").append(entities).append("0\nENDSEC\n0\nEOF\n");
        return sb.toString();
    }

    static DxfDrawing read(String text) throws DxfException {
        return DxfReader.read(text.getBytes(StandardCharsets.UTF_8), "t.dxf", DxfReadOptions.DEFAULT);
    }

    static void near(Vec2 want, Vec2 got) {
        assertEquals(0, want.distance(got), 1e-9, () -> "want " + want + " got " + got);
    }

    @Test
    void thePapersFigureOneFragmentGivesALineAnArcAndACircle() throws Exception {
        String e = "0\nLINE\n100\nAcDbLine\n10\n-40.0\n20\n50.0\n30\n0.0\n11\n40.0\n21\n50.0\n31\n0.0\n"
                + "0\nARC\n100\nAcDbCircle\n10\n-50.0\n20\n50.0\n30\n0.0\n40\n10.00000000000001\n100\nAcDbArc\n50\n0.0\n51\n270.0\n"
                + "0\nCIRCLE\n100\nAcDbCircle\n10\n0.0\n20\n0.0\n30\n0.0\n40\n15.0\n";
        List<Curve2> c = read(dxf("", "", e)).curves();
        assertEquals(3, c.size());
        near(Vec2.of(-40, 50), c.get(0).start());
        Arc2 arc = (Arc2) c.get(1);
        assertTrue(arc.ccw());
        near(Vec2.of(-40, 50), arc.start());
        near(Vec2.of(-50, 40), arc.end());
        assertEquals(1.5 * Math.PI, arc.sweepRad(), 1e-12);
        Arc2 circle = (Arc2) c.get(2);
        assertTrue(circle.isFullCircle());
        assertEquals(15, circle.radius(), 1e-12);
    }

    @Test
    void theBulgeAtVertexIBelongsToTheSegmentFromIToIPlusOne() throws Exception {
        // square 0,0 -> 10,0 (straight) -> 10,10 (bulge 1: semicircle CCW bulging right) -> 0,10 -> close
        String e = "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n10\n20\n0\n42\n1\n10\n10\n20\n10\n10\n0\n20\n10\n";
        List<Curve2> c = read(dxf("", "", e)).curves();
        assertEquals(4, c.size());
        assertTrue(c.get(0) instanceof Segment2);
        Arc2 arc = (Arc2) c.get(1);
        assertTrue(arc.ccw());
        near(Vec2.of(10, 5), arc.center());
        near(Vec2.of(10, 0), arc.start());
        near(Vec2.of(10, 10), arc.end());
        // CCW from (10,0) to (10,10) about (10,5) passes through (15,5): outside the square
        near(Vec2.of(15, 5), arc.pointAt(0.5));
        assertTrue(c.get(2) instanceof Segment2);
        near(Vec2.of(0, 0), c.get(3).end());
    }

    @Test
    void aNegativeBulgeIsClockwiseAndAQuarterBulgeSweepsNinetyDegrees() {
        double b = Math.tan(Math.toRadians(90) / 4);
        Arc2 arc = (Arc2) DxfReader.bulged(Vec2.of(1, 0), Vec2.of(0, 1), b);
        near(Vec2.ZERO, arc.center());
        assertEquals(Math.PI / 2, arc.sweepRad(), 1e-12);
        Arc2 cw = (Arc2) DxfReader.bulged(Vec2.of(0, 1), Vec2.of(1, 0), -b);
        assertFalse(cw.ccw());
        near(Vec2.ZERO, cw.center());
    }

    @Test
    void anArcWithExtrusionMinusZIsMirroredInXAndRunsClockwise() throws Exception {
        String e = "0\nARC\n10\n10\n20\n5\n40\n2\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n";
        Arc2 arc = (Arc2) read(dxf("", "", e)).curves().get(0);
        near(Vec2.of(-10, 5), arc.center());
        near(Vec2.of(-12, 5), arc.start());
        near(Vec2.of(-10, 7), arc.end());
        assertFalse(arc.ccw());
    }

    @Test
    void insertAppliesBaseScaleRotationAndMirrorAndNestedBlocks() throws Exception {
        String blocks = "0\nBLOCK\n2\nINNER\n10\n0\n20\n0\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDBLK\n"
                + "0\nBLOCK\n2\nOUTER\n10\n1\n20\n0\n0\nINSERT\n2\nINNER\n10\n1\n20\n0\n"
                + "0\nARC\n10\n1\n20\n0\n40\n1\n50\n0\n51\n90\n0\nENDBLK\n";
        String e = "0\nINSERT\n8\nCUT\n2\nOUTER\n10\n100\n20\n0\n41\n-2\n42\n2\n50\n90\n";
        DxfDrawing d = read(dxf("", blocks, e));
        assertEquals(List.of("CUT"), List.copyOf(d.layers().keySet()));
        List<Curve2> c = d.curves();
        // inner line (0,0)-(1,0) in OUTER at (1,0): (1,0)-(2,0); minus base (1,0): (0,0)-(1,0);
        // scale (-2,2): (0,0)-(-2,0); rotate 90: (0,0)-(0,-2); move to (100,0)
        near(Vec2.of(100, 0), c.get(0).start());
        near(Vec2.of(100, -2), c.get(0).end());
        Arc2 arc = (Arc2) c.get(1);
        // arc centre (1,0) -> (0,0) -> (0,0) -> (100,0); start (2,0)->(1,0)->(-2,0)->(0,-2)
        near(Vec2.of(100, 0), arc.center());
        near(Vec2.of(100, -2), arc.start());
        assertFalse(arc.ccw(), "a mirrored insert reverses the arc sense");
        near(Vec2.of(98, 0), arc.end());
    }

    @Test
    void aBlockThatInsertsItselfIsReportedAndDoesNotLoop() throws Exception {
        String blocks =
                "0\nBLOCK\n2\nB\n10\n0\n20\n0\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nINSERT\n5\nAB\n2\nB\n10\n5\n20\n0\n0\nENDBLK\n";
        DxfDrawing d = read(dxf("", blocks, "0\nINSERT\n2\nB\n10\n0\n20\n0\n"));
        assertEquals(1, d.curveCount());
        assertTrue(
                d.warnings().stream().anyMatch(w -> w.contains("inserts itself")),
                d.warnings().toString());
    }

    @Test
    void inchDrawingsAreScaledAndUnitlessUseTheChosenUnit() throws Exception {
        String line = "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n";
        DxfDrawing inch = read(dxf("9\n$INSUNITS\n70\n1\n", "", line));
        assertEquals(DxfUnits.INCH, inch.units());
        assertEquals(25.4, inch.curves().get(0).length(), 1e-12);
        DxfDrawing cm = read(dxf("9\n$INSUNITS\n70\n5\n", "", line));
        assertEquals(10, cm.curves().get(0).length(), 1e-12);
        DxfDrawing none = DxfReader.read(
                dxf("", "", line).getBytes(StandardCharsets.UTF_8),
                "t",
                new DxfReadOptions(Optional.empty(), DxfUnits.INCH, 0.001, 16, 1000));
        assertEquals(25.4, none.curves().get(0).length(), 1e-12);
        assertFalse(none.warnings().isEmpty());
        DxfDrawing forced = DxfReader.read(
                dxf("9\n$INSUNITS\n70\n1\n", "", line).getBytes(StandardCharsets.UTF_8),
                "t",
                DxfReadOptions.DEFAULT.withUnits(Optional.of(DxfUnits.MM)));
        assertEquals(1, forced.curves().get(0).length(), 1e-12);
    }

    @Test
    void anEllipseIsReplacedByArcsWithinTheTolerance() throws Exception {
        String e = "0\nELLIPSE\n10\n0\n20\n0\n11\n20\n21\n0\n40\n0.5\n41\n0\n42\n6.283185307179586\n";
        List<Curve2> c = read(dxf("", "", e)).curves();
        assertTrue(c.size() > 4);
        for (Curve2 cv : c) {
            for (int k = 0; k <= 10; k++) {
                Vec2 p = cv.pointAt(k / 10.0);
                double f = Math.pow(p.x() / 20, 2) + Math.pow(p.y() / 10, 2);
                // distance to the ellipse ~ |f - 1| * b / 2 for a flat ellipse: bound loosely
                assertEquals(1, f, 0.001);
            }
        }
        for (int i = 0; i < c.size(); i++) {
            assertEquals(c.get(i).end(), c.get((i + 1) % c.size()).start());
        }
    }

    @Test
    void anEllipseWithTheLongerAxisWrittenAsMinorIsReadWithItsAxesSwapped() throws Exception {
        // QCAD: major axis (0, 5), ratio 3.5, so the "minor" axis (-17.5, 0) is the longer one
        String e = "0\nELLIPSE\n5\n2F\n10\n0\n20\n0\n11\n0\n21\n5\n40\n3.5\n41\n0\n42\n6.283185307179586\n";
        DxfDrawing d = read(dxf("", "", e));
        List<Curve2> c = d.curves();
        assertTrue(c.size() > 4, d.warnings().toString());
        for (Curve2 cv : c) {
            for (int k = 0; k <= 10; k++) {
                Vec2 p = cv.pointAt(k / 10.0);
                assertEquals(1, Math.pow(p.x() / 17.5, 2) + Math.pow(p.y() / 5, 2), 0.001, p::toString);
            }
        }
        assertEquals(c.get(c.size() - 1).end(), c.get(0).start());
    }

    @Test
    void anEllipticArcWithARatioAboveOneKeepsItsEndPoints() throws Exception {
        // u from 0 to pi/2 on centre + major cos u + (N x major) ratio sin u: from (0, 5) to (-10, 0)
        String e = "0\nELLIPSE\n10\n0\n20\n0\n11\n0\n21\n5\n40\n2\n41\n0\n42\n1.5707963267948966\n";
        List<Curve2> c = read(dxf("", "", e)).curves();
        near(Vec2.of(0, 5), c.get(0).start());
        near(Vec2.of(-10, 0), c.get(c.size() - 1).end());
        Vec2 mid = c.get(c.size() / 2).start();
        assertTrue(mid.x() < 0 && mid.y() > 0, mid::toString);
        assertEquals(1, Math.pow(mid.x() / 10, 2) + Math.pow(mid.y() / 5, 2), 0.001);
    }

    @Test
    void aDegenerateEllipseIsNamedWithItsNumbersNotARecord() throws Exception {
        String e = "0\nELLIPSE\n5\n2F\n10\n0\n20\n0\n11\n0\n21\n5\n40\n0\n";
        DxfDrawing d = read(dxf("", "", e));
        String w = d.warnings().stream()
                .filter(x -> x.startsWith("ELLIPSE 2F"))
                .findFirst()
                .orElseThrow();
        assertAll(
                () -> assertTrue(w.contains("major axis (0, 5) and axis ratio 0"), w),
                () -> assertFalse(w.contains("Vec2"), w));
    }

    @Test
    void everyKindOfEntityLeftOutIsNamedWithItsFirstPlace() throws Exception {
        String e = "0\nTEXT\n5\n1A\n1\nhi\n0\nTEXT\n5\n1B\n1\nho\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n";
        DxfDrawing d = read(dxf("", "", e));
        assertTrue(
                d.warnings()
                        .contains("2 TEXT entities left out (not a line, arc or curve to cut), the first: TEXT 1A"
                                + " at line 6"),
                d.warnings().toString());
    }

    @Test
    void unusableEntitiesAreNamedAndTheRestIsKept() throws Exception {
        String e = "0\nCIRCLE\n5\nA1\n10\n0\n20\n0\n40\n0\n0\nCIRCLE\n5\nA2\n10\n0\n20\n0\n40\n5\n0\nTEXT\n1\nhi\n";
        DxfDrawing d = read(dxf("", "", e));
        assertEquals(1, d.curveCount());
        assertEquals(1, d.ignored().get("TEXT"));
        assertTrue(
                d.warnings().contains("CIRCLE A1 at line 6: radius 0.0 is not > 0; the circle is left out"),
                d.warnings().toString());
    }

    @Test
    void aCoordinateThatIsNotANumberRefusesTheDrawingAtItsLine() {
        String e = "0\nLINE\n5\nA1\n10\n0\n20\n0\n11\nabc\n21\n0\n";
        DxfException ex = assertThrows(DxfException.class, () -> read(dxf("", "", e)));
        assertEquals(
                "t.dxf: line 14: LINE A1 (from line 6): group 11 is 'abc': expected an x coordinate (a finite number)",
                ex.getMessage());
    }

    @Test
    void aDrawingPastTheCurveLimitIsRefusedNotCutShort() {
        String line = "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n";
        DxfReadOptions three = new DxfReadOptions(Optional.empty(), DxfUnits.MM, 0.001, 16, 3);
        DxfException ex = assertThrows(
                DxfException.class,
                () -> DxfReader.read(dxf("", "", line.repeat(4)).getBytes(StandardCharsets.UTF_8), "t.dxf", three));
        assertTrue(
                ex.getMessage().startsWith("t.dxf: the drawing expands to more than 3 lines and arcs"),
                ex.getMessage());
    }

    @Test
    void aFileThatIsNotDxfIsRejectedWithItsLine() {
        DxfException ex = assertThrows(
                DxfException.class,
                () -> DxfReader.read(
                        "hello\nworld\n".getBytes(StandardCharsets.UTF_8), "x.dxf", DxfReadOptions.DEFAULT));
        assertTrue(ex.getMessage().contains("x.dxf: line 1"), ex.getMessage());
    }

    @Test
    void absurdVertexCountsDoNotPreallocate() throws Exception {
        String e = "0\nLWPOLYLINE\n90\n2000000000\n70\n0\n10\n0\n20\n0\n10\n1\n20\n0\n";
        assertEquals(1, read(dxf("", "", e)).curveCount());
    }

    @Test
    void entitiesOnFrozenOrSwitchedOffLayersAndInPaperSpaceAreLeftOutAndCounted() throws Exception {
        String tables = "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n"
                + "0\nLAYER\n2\nCUT\n70\n0\n62\n7\n"
                + "0\nLAYER\n2\nFROZEN\n70\n1\n62\n7\n"
                + "0\nLAYER\n2\nOFF\n70\n0\n62\n-3\n0\nENDTAB\n0\nENDSEC\n";
        String line = "0\nLINE\n8\n%s\n10\n0\n20\n0\n11\n10\n21\n0\n";
        String entities = String.format(line, "CUT") + String.format(line, "FROZEN") + String.format(line, "OFF")
                + "0\nLINE\n8\nCUT\n67\n1\n10\n0\n20\n0\n11\n5\n21\n5\n"
                + "0\nHATCH\n8\nCUT\n0\nDIMENSION\n8\nCUT\n0\nMTEXT\n8\nCUT\n";
        String text = tables + dxf("", "", entities);
        DxfDrawing d = read(text);
        assertAll(
                () -> assertEquals(List.of("CUT"), List.copyOf(d.layers().keySet())),
                () -> assertEquals(1, d.curveCount()),
                () -> assertEquals(2, d.ignored().get("on frozen or off layers")),
                () -> assertEquals(1, d.ignored().get("paper space")),
                () -> assertEquals(1, d.ignored().get("HATCH")),
                () -> assertEquals(1, d.ignored().get("DIMENSION")),
                () -> assertEquals(1, d.ignored().get("MTEXT")));
    }

    @Test
    @CorpusCheck
    void binaryDrawingsOfTheCorpusReadLikeTheirContents() throws Exception {
        java.nio.file.Path dir = TestInputs.DXF_CORPUS.resolve("ezdxf");
        org.junit.jupiter.api.Assumptions.assumeTrue(java.nio.file.Files.isDirectory(dir), "corpus absent");
        // R12 binary: three LINEs; R2000 binary: one TEXT and nothing to cut
        DxfDrawing r12 = DxfReader.read(dir.resolve("integration_tests_data_bin_dxf_r12.dxf"));
        DxfDrawing r2000 = DxfReader.read(dir.resolve("integration_tests_data_bin_dxf_r2000.dxf"));
        assertAll(
                () -> assertEquals(3, r12.curveCount()),
                () -> assertTrue(r12.curves().stream().allMatch(c -> c instanceof org.fresa.geom.Segment2)),
                () -> assertEquals(0, r2000.curveCount()),
                () -> assertEquals(1, r2000.ignored().get("TEXT")),
                () -> assertEquals(DxfUnits.M, r2000.units()));
    }
}
