package org.fresa.sole;

import static org.fresa.sole.TreadFigureTest.assertArc;
import static org.fresa.sole.TreadFigureTest.assertLine;
import static org.fresa.sole.TreadFigureTest.assertPoint;
import static org.fresa.sole.TreadFigureTest.call;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;

/**
 * The DESCOM test programs 03, 04 and 05 of Ahrens (1986, App. E, figures 5.4 to 5.6; seed
 * 004-listings.md), each section built as the listing builds it: the same CALLs with the same
 * parameters, the INDEX blocks' COPYs as the copies of a tread item, in the listing's order. The
 * expected tool-centre coordinates are derived by hand from the listing's macros and stated in
 * each test (CTM = 0, so no factor).
 *
 * <p>How the listings are read:
 * <ul>
 * <li>An INDEX block is only defined; what is cut is what the COPYs emit (every listing follows a
 * block with {@code COPY/n,SAME,1}). A block that holds COPYs of other blocks holds those copies.
 * <li>{@code MIRROR,YPAR,v} reflects in the line x = v, {@code MIRROR,XPAR,v} in y = v; a COPY's
 * transforms apply in the order written ({@code TRANSL} then {@code MIRROR}). The order only
 * matters in test 05's last COPY, where it puts the mirrored parallelograms on the test field
 * (x 10 to 40) and the other order would put them at x 90 to 120.
 * <li>{@code GOTO/PP} with a point of the {@code ZSURF} plane lifts the tool. A continuous macro
 * (B types) begins with the cut from where the tool is to its start line ({@code GO/ON,YPAR}),
 * so copies that begin where the previous one ended chain into one groove; {@code NOVO} lifts
 * and plunges elsewhere, which a copy starting elsewhere does here without its first rapid point.
 * </ul>
 */
class DescomTestProgramsTest {

    private static final Tolerance TOL = Tolerance.DEFAULT;

    /** {@code TRANSL,dx,dy,0}. */
    private static Similarity2 transl(double dx, double dy) {
        return Similarity2.translation(dx, dy);
    }

    /** {@code MIRROR,YPAR,x}. */
    private static Similarity2 ypar(double x) {
        return Similarity2.mirrorX(x);
    }

    /** {@code MIRROR,XPAR,y}. */
    private static Similarity2 xpar(double y) {
        return Similarity2.mirrorY(y);
    }

    private static List<Stroke> cut(List<TreadFigure> lead, TreadFigure block, List<Similarity2> copies) {
        return new TreadItem(
                        "test", lead, List.of(block), new TreadPattern.Copies(copies), SizeRule.HELD, false, "bit3")
                .strokes(TOL);
    }

    /** The stroke is the polyline through the points (x0, y0), (x1, y1), ... */
    private static void assertPolyline(Stroke s, double... xy) {
        assertPoint(xy[0], xy[1], s.start());
        assertEquals(xy.length / 2 - 1, s.curves().size(), "segments of " + s.start());
        for (int i = 0; i < s.curves().size(); i++) {
            assertLine(
                    xy[2 * i],
                    xy[2 * i + 1],
                    xy[2 * i + 2],
                    xy[2 * i + 3],
                    s.curves().get(i));
        }
    }

    /** The copies {@code COPY/b,TRANSL,dx,dy,0,n} of a block b that is itself {@code t}. */
    private static List<Similarity2> row(Similarity2 t, double dx, double dy, int n) {
        List<Similarity2> out = new ArrayList<>();
        for (int k = 1; k <= n; k++) {
            out.add(t.then(transl(k * dx, k * dy)));
        }
        return out;
    }

    /**
     * Test 03, SUB5E: {@code CALL/SUB5E,XC1=-35,YC1=-45,XA5=-40,XB5=-20,XC2=-25,YC2=-35,XT=-30,
     * YT=-40,AFAS=20,N=3}; INDEX/2 {@code COPY/1,MIRROR,YPAR,0,MIRROR,XPAR,-37.5,1}; INDEX/3 holds
     * COPY/1 and COPY/2; {@code COPY/3,SAME,1}, {@code COPY/3,TRANSL,0,10,0,1}.
     *
     * <p>By hand: the circles of radius sqrt(50) centred (-35,-45) and (-25,-35) touch at
     * (-30,-40); x = -40 meets the first at (-40,-40) (and (-40,-50): the second intersection,
     * "ON,2", on the way there from SP (-38,-44) is the upper one). GORGT turns right: the first
     * quarter arc runs clockwise over the top to (-30,-40), GOFWD on the second circle under it to
     * (-20,-40), and the N = 3 copies every AFAS = 20 end at x = XB5 + 3 AFAS = 40: eight quarter
     * arcs ending at x = -30 + 10 i, y = -40, centres alternately 5 below and 5 above. The double
     * mirror (x, y) -> (-x, -75 - y) is a half turn about (0, -37.5): the wave from (40,-35) to
     * (-40,-35), senses kept. Then both 10 higher: four waves at y = -40, -35, -30, -25.
     */
    @Test
    void test03Sub5eWavesTwoRowsAndTheirMirrorImages() throws Exception {
        TreadFigure sub5e = call("SUB5E", "XC1=-35,YC1=-45,XA5=-40,XB5=-20,XC2=-25,YC2=-35,XT=-30,YT=-40,AFAS=20,N=3");
        Similarity2 m = ypar(0).then(xpar(-37.5));
        List<Stroke> s = cut(List.of(), sub5e, List.of(Similarity2.IDENTITY, m, transl(0, 10), m.then(transl(0, 10))));
        assertEquals(4, s.size(), "four waves, each plunged and lifted (SUB5E is discontinuous)");
        double[] baseY = {-40, -35, -30, -25};
        for (int w = 0; w < 4; w++) {
            boolean back = w % 2 == 1;
            double y = baseY[w];
            List<Curve2> c = s.get(w).curves();
            assertEquals(8, c.size());
            assertPoint(back ? 40 : -40, y, s.get(w).start());
            for (int i = 0; i < 8; i++) {
                double x0 = back ? 40 - 10 * i : -40 + 10 * i;
                double x1 = back ? x0 - 10 : x0 + 10;
                // centres of the forward wave: (-35,-45), (-25,-35), ... 5 below, then 5 above the line
                double cy = back ? y + (i % 2 == 0 ? 5 : -5) : y + (i % 2 == 0 ? -5 : 5);
                assertArc(x0, y, x1, y, (x0 + x1) / 2, cy, i % 2 == 1, c.get(i));
                assertEquals(Math.sqrt(50), ((Arc2) c.get(i)).radius(), 1e-9);
            }
        }
    }

    /**
     * Test 03, SUB8B: {@code CALL/NOVO,XF1=-40,YF1=-25,XF2=-40,YF2=-15}; INDEX/4
     * {@code CALL/SUB8B,XB8=5,YB8=5,XC8=10,YC8=0,XD8=5,YD8=-5}; INDEX/5 {@code COPY/4,TRANSL,20,0,0,3};
     * INDEX/6 NOVO to (40,-10); INDEX/7 {@code COPY/4,TRANSL,0,5,0,MIRROR,YPAR,0,1}; INDEX/8
     * {@code COPY/7,TRANSL,-20,0,0,3}; INDEX/9 holds 4 to 8; {@code COPY/9,SAME,1}, NOVO to
     * (-40,-5), {@code COPY/9,TRANSL,0,10,0,1}.
     *
     * <p>By hand: GODLTA 5,5 / 10,0 / 5,-5 from the plunge at (-40,-15) is the trapezoid
     * (-40,-15) (-35,-10) (-25,-10) (-20,-15), four of them to (40,-15); the mirrored row starts at
     * (40,-10) (where NOVO I=2 plunged) and runs back to (-40,-10) with its tops at y = -5; both
     * rows again 10 higher from (-40,-5) (NOVO I=3) and (40,0).
     */
    @Test
    void test03Sub8bTrapezoidWavesFourRowsBackAndForth() throws Exception {
        TreadFigure novo = call("NOVO", "XF1=-40,YF1=-25,XF2=-40,YF2=-15");
        TreadFigure sub8b = call("SUB8B", "XB8=5,YB8=5,XC8=10,YC8=0,XD8=5,YD8=-5");
        List<Similarity2> block9 = new ArrayList<>();
        block9.add(Similarity2.IDENTITY);
        block9.addAll(row(Similarity2.IDENTITY, 20, 0, 3));
        Similarity2 seven = transl(0, 5).then(ypar(0));
        block9.add(seven);
        block9.addAll(row(seven, -20, 0, 3));
        List<Similarity2> copies = new ArrayList<>(block9);
        block9.forEach(t -> copies.add(t.then(transl(0, 10))));
        List<Stroke> s = cut(List.of(novo), sub8b, copies);
        assertEquals(4, s.size(), "one groove a row, NOVO between rows");
        assertEquals(List.of(Vec2.of(-40, -25)), s.get(0).via(), "NOVO I=1 passes over its first point");
        double[][] rows = {{-40, -15, 1}, {40, -10, -1}, {-40, -5, 1}, {40, 0, -1}};
        for (int r = 0; r < 4; r++) {
            double x = rows[r][0];
            double y = rows[r][1];
            double d = rows[r][2];
            double[] xy = new double[26];
            xy[0] = x;
            xy[1] = y;
            for (int k = 0; k < 4; k++) {
                double x0 = x + d * 20 * k;
                double[] p = {x0 + d * 5, y + 5, x0 + d * 15, y + 5, x0 + d * 20, y};
                System.arraycopy(p, 0, xy, 2 + 6 * k, 6);
            }
            assertPolyline(s.get(r), xy);
        }
    }

    /**
     * Test 03, SUB8A: INDEX/10 {@code CALL/SUB8A,XA8=-39,YA8=20,XB8=4,YB8=0,XC8=5,YC8=-10,XD8=4,YD8=0};
     * INDEX/11 {@code COPY/10,TRANSL,17,0,0,4}; INDEX/12 {@code COPY/10,MIRROR,XPAR,20,MIRROR,YPAR,1.5,1};
     * INDEX/13 {@code COPY/12,TRANSL,-17,0,0,4}; INDEX/14 holds 10 and 11; {@code COPY/14,SAME,1},
     * {@code COPY/12,SAME,1}, {@code COPY/13,SAME,1}, {@code COPY/14,TRANSL,0,20,0,1}.
     *
     * <p>By hand: the stepped Z (-39,20) (-35,20) (-30,10) (-26,10), five of them 17 apart; the
     * double mirror (x, y) -> (3 - x, 40 - y) gives (42,20) (38,20) (33,30) (29,30), five of them
     * 17 apart to the left; then the first five again 20 higher: fifteen Z's, each plunged and
     * lifted.
     */
    @Test
    void test03Sub8aSteppedZsInThreeRows() throws Exception {
        TreadFigure sub8a = call("SUB8A", "XA8=-39,YA8=20,XB8=4,YB8=0,XC8=5,YC8=-10,XD8=4,YD8=0");
        List<Similarity2> block14 = new ArrayList<>();
        block14.add(Similarity2.IDENTITY);
        block14.addAll(row(Similarity2.IDENTITY, 17, 0, 4));
        Similarity2 twelve = xpar(20).then(ypar(1.5));
        List<Similarity2> copies = new ArrayList<>(block14);
        copies.add(twelve);
        copies.addAll(row(twelve, -17, 0, 4));
        block14.forEach(t -> copies.add(t.then(transl(0, 20))));
        List<Stroke> s = cut(List.of(), sub8a, copies);
        assertEquals(15, s.size());
        for (int k = 0; k < 5; k++) {
            double x = -39 + 17 * k;
            assertPolyline(s.get(k), x, 20, x + 4, 20, x + 9, 10, x + 13, 10);
            double xm = 42 - 17 * k;
            assertPolyline(s.get(5 + k), xm, 20, xm - 4, 20, xm - 9, 30, xm - 13, 30);
            assertPolyline(s.get(10 + k), x, 40, x + 4, 40, x + 9, 30, x + 13, 30);
        }
    }

    /**
     * Test 04, SUB3A: INDEX/1 {@code CALL/SUB3A,XC=-30,YC=-35,RA=5,XA3=-35,XB3=-25}; INDEX/2
     * {@code COPY/1,TRANSL,15,0,0,4}; INDEX/3 {@code COPY/1,TRANSL,0,10,0,MIRROR,YPAR,0,1};
     * INDEX/4 {@code COPY/3,TRANSL,-15,0,0,4}; COPY/1 to COPY/4 SAME; INDEX/5
     * {@code COPY/1,TRANSL,7.5,0,0,MIRROR,XPAR,-35,1} (the OCR prints "7, 5, 0, 0"); INDEX/6
     * {@code COPY/5,TRANSL,15,0,0,3}; INDEX/7 {@code COPY/1,MIRROR,YPAR,-3.75,MIRROR,XPAR,-30,1};
     * INDEX/8 {@code COPY/7,TRANSL,-15,0,0,3}; COPY/5 to COPY/8 SAME.
     *
     * <p>By hand: x = -35 touches the circle of radius 5 about (-30,-35) at (-35,-35); GORGT turns
     * right, clockwise over the top to x = -25. Five such scallops centred x = -30 .. 30 on
     * y = -35; their mirror 10 higher runs back from (35,-25), counter-clockwise, still over the
     * top, centres 30 .. -30. Block 5 is the first scallop moved 7.5 and turned under y = -35:
     * from (-27.5,-35) to (-17.5,-35) under it, counter-clockwise, four of them centred -22.5 ..
     * 22.5. Block 7 is the half turn (x, y) -> (-7.5 - x, -60 - y): from (27.5,-25) to (17.5,-25)
     * clockwise under y = -25, four of them centred 22.5 .. -22.5.
     */
    @Test
    void test04Sub3aScallopsOverAndUnderInFourRows() throws Exception {
        TreadFigure sub3a = call("SUB3A", "XC=-30,YC=-35,RA=5,XA3=-35,XB3=-25");
        List<Similarity2> copies = new ArrayList<>();
        copies.add(Similarity2.IDENTITY);
        copies.addAll(row(Similarity2.IDENTITY, 15, 0, 4));
        Similarity2 three = transl(0, 10).then(ypar(0));
        copies.add(three);
        copies.addAll(row(three, -15, 0, 4));
        Similarity2 five = transl(7.5, 0).then(xpar(-35));
        copies.add(five);
        copies.addAll(row(five, 15, 0, 3));
        Similarity2 seven = ypar(-3.75).then(xpar(-30));
        copies.add(seven);
        copies.addAll(row(seven, -15, 0, 3));
        List<Stroke> s = cut(List.of(), sub3a, copies);
        assertEquals(18, s.size());
        for (int k = 0; k < 5; k++) {
            double c = -30 + 15 * k;
            assertArc(c - 5, -35, c + 5, -35, c, -35, false, only(s.get(k)));
            double cm = 30 - 15 * k;
            assertArc(cm + 5, -25, cm - 5, -25, cm, -25, true, only(s.get(5 + k)));
        }
        for (int k = 0; k < 4; k++) {
            double c = -22.5 + 15 * k;
            assertArc(c - 5, -35, c + 5, -35, c, -35, true, only(s.get(10 + k)));
            double cm = 22.5 - 15 * k;
            assertArc(cm + 5, -25, cm - 5, -25, cm, -25, false, only(s.get(14 + k)));
        }
        // over the top and under: the middle of each arc
        assertPoint(-30, -30, only(s.get(0)).pointAt(0.5));
        assertPoint(30, -20, only(s.get(5)).pointAt(0.5));
        assertPoint(-22.5, -40, only(s.get(10)).pointAt(0.5));
        assertPoint(22.5, -30, only(s.get(14)).pointAt(0.5));
    }

    private static Curve2 only(Stroke s) {
        assertEquals(1, s.curves().size());
        return s.curves().get(0);
    }

    /**
     * Test 04, SUB5B: {@code CALL/NOVO,XF1=-27.5,YF1=-25,XF2=-40,YF2=-10}; INDEX/9
     * {@code CALL/SUB5B,XC1=-30,YC1=-10,XC2=-20,YC2=-10,XT=-25,YT=-10,XA5=-35,XB5=-15}; INDEX/10
     * {@code COPY/9,TRANSL,25,0,0,2}; INDEX/11 holds 9 and 10; {@code COPY/11,SAME,1}; NOVO over
     * (35,-10) to (40,0); {@code COPY/11,MIRROR,YPAR,0,MIRROR,XPAR,-5,1}; {@code GOTO/PP} lifts.
     *
     * <p>By hand: from the plunge at (-40,-10) GO/ON,YPAR,-35 cuts to (-35,-10); GOLFT turns left
     * from +x, upwards, clockwise over the circle about (-30,-10) to (-25,-10), then GOFWD
     * counter-clockwise under the one about (-20,-10) to (-15,-10). The copies 25 and 50 to the
     * right begin with the cut to x = -10 and 15: one groove to (35,-10). The half turn
     * (x, y) -> (-x, -10 - y) gives the groove from (40,0) back to (-35,0), under then over.
     */
    @Test
    void test04Sub5bWavesChainIntoTwoGrooves() throws Exception {
        TreadFigure novo = call("NOVO", "XF1=-27.5,YF1=-25,XF2=-40,YF2=-10");
        TreadFigure sub5b = call("SUB5B", "XC1=-30,YC1=-10,XC2=-20,YC2=-10,XT=-25,YT=-10,XA5=-35,XB5=-15");
        List<Similarity2> block11 = new ArrayList<>();
        block11.add(Similarity2.IDENTITY);
        block11.addAll(row(Similarity2.IDENTITY, 25, 0, 2));
        List<Similarity2> copies = new ArrayList<>(block11);
        Similarity2 half = ypar(0).then(xpar(-5));
        block11.forEach(t -> copies.add(t.then(half)));
        List<Stroke> s = cut(List.of(novo), sub5b, copies);
        assertEquals(2, s.size());
        for (int r = 0; r < 2; r++) {
            double d = r == 0 ? 1 : -1;
            double y = r == 0 ? -10 : 0;
            List<Curve2> c = s.get(r).curves();
            assertEquals(9, c.size(), "per copy: the cut to its start line and two arcs");
            for (int k = 0; k < 3; k++) {
                double x0 = d * (-40 + 25 * k);
                assertLine(x0, y, x0 + d * 5, y, c.get(3 * k));
                assertArc(x0 + d * 5, y, x0 + d * 15, y, x0 + d * 10, y, false, c.get(3 * k + 1));
                assertArc(x0 + d * 15, y, x0 + d * 25, y, x0 + d * 20, y, true, c.get(3 * k + 2));
            }
        }
        assertPoint(-30, -5, s.get(0).curves().get(1).pointAt(0.5));
        assertPoint(-20, -15, s.get(0).curves().get(2).pointAt(0.5));
        assertPoint(30, -5, s.get(1).curves().get(1).pointAt(0.5));
        assertPoint(-35, 0, s.get(1).end());
    }

    /**
     * Test 04, SUB7A: INDEX/12 {@code CALL/SUB7A,XA7=-40,YA7=20,XB7=10,YB7=5,XC7=10,YC7=-5};
     * INDEX/13 {@code COPY/12,TRANSL,30,0,0,2}; INDEX/14 {@code COPY/12,TRANSL,0,10,0,MIRROR,YPAR,0,1};
     * INDEX/15 {@code COPY/14,TRANSL,-30,0,0,2}; INDEX/16 {@code COPY/12,TRANSL,15,0,0,MIRROR,XPAR,19,1};
     * INDEX/17 {@code COPY/16,TRANSL,30,0,0,1}; INDEX/18 {@code COPY/16,TRANSL,0,10,0,MIRROR,YPAR,0,1};
     * INDEX/19 {@code COPY/18,TRANSL,-30,0,0,1}; COPY/12 to COPY/19 SAME.
     *
     * <p>By hand: the V (-40,20) (-30,25) (-20,20), three of them 30 apart; (x, y+10) mirrored in
     * x = 0: (40,30) (30,35) (20,30), three to the left; block 16, (x + 15, 38 - y): the inverted
     * V (-25,18) (-15,13) (-5,18) and 30 to the right; block 18 its (x, y + 10) mirror in x = 0:
     * (25,28) (15,23) (5,28) and 30 to the left: ten V's.
     */
    @Test
    void test04Sub7aVsAndInvertedVs() throws Exception {
        TreadFigure sub7a = call("SUB7A", "XA7=-40,YA7=20,XB7=10,YB7=5,XC7=10,YC7=-5");
        List<Similarity2> copies = new ArrayList<>();
        copies.add(Similarity2.IDENTITY);
        copies.addAll(row(Similarity2.IDENTITY, 30, 0, 2));
        Similarity2 fourteen = transl(0, 10).then(ypar(0));
        copies.add(fourteen);
        copies.addAll(row(fourteen, -30, 0, 2));
        Similarity2 sixteen = transl(15, 0).then(xpar(19));
        copies.add(sixteen);
        copies.addAll(row(sixteen, 30, 0, 1));
        Similarity2 eighteen = sixteen.then(transl(0, 10)).then(ypar(0));
        copies.add(eighteen);
        copies.addAll(row(eighteen, -30, 0, 1));
        List<Stroke> s = cut(List.of(), sub7a, copies);
        assertEquals(10, s.size());
        for (int k = 0; k < 3; k++) {
            double x = -40 + 30 * k;
            assertPolyline(s.get(k), x, 20, x + 10, 25, x + 20, 20);
            double xm = 40 - 30 * k;
            assertPolyline(s.get(3 + k), xm, 30, xm - 10, 35, xm - 20, 30);
        }
        assertPolyline(s.get(6), -25, 18, -15, 13, -5, 18);
        assertPolyline(s.get(7), 5, 18, 15, 13, 25, 18);
        assertPolyline(s.get(8), 25, 28, 15, 23, 5, 28);
        assertPolyline(s.get(9), -5, 28, -15, 23, -25, 28);
    }

    /**
     * Test 05, SUB3B: {@code CALL/PRIM,XI=-40,YI=-40,XA1=0,YA1=0}; INDEX/1
     * {@code CALL/SUB3B,XC=-30,YC=-40,RA=5,XA3=-35,XB3=-25}; INDEX/2 {@code COPY/1,TRANSL,15,0,0,4};
     * INDEX/3 holds 1 and 2; {@code COPY/3,SAME,1}; NOVO over (35,-40) to (40,-30);
     * {@code COPY/3,TRANSL,0,10,0,MIRROR,YPAR,0,1}.
     *
     * <p>By hand: from PRIM's plunge at (-40,-40) the cut to (-35,-40), GOLFT clockwise over the
     * circle about (-30,-40) to (-25,-40); the copies 15 .. 60 to the right chain on: one groove
     * to (35,-40), five cuts of 5 and five half circles. Then (x, y + 10) mirrored in x = 0: from
     * (40,-30) back to (-35,-30), counter-clockwise, still over the top.
     */
    @Test
    void test05Sub3bArcsChainedInTwoRows() throws Exception {
        TreadFigure prim = call("PRIM", "XI=-40,YI=-40,XA1=0,YA1=0");
        TreadFigure sub3b = call("SUB3B", "XC=-30,YC=-40,RA=5,XA3=-35,XB3=-25");
        List<Similarity2> block3 = new ArrayList<>();
        block3.add(Similarity2.IDENTITY);
        block3.addAll(row(Similarity2.IDENTITY, 15, 0, 4));
        List<Similarity2> copies = new ArrayList<>(block3);
        Similarity2 back = transl(0, 10).then(ypar(0));
        block3.forEach(t -> copies.add(t.then(back)));
        List<Stroke> s = cut(List.of(prim), sub3b, copies);
        assertEquals(2, s.size());
        for (int r = 0; r < 2; r++) {
            double d = r == 0 ? 1 : -1;
            double y = r == 0 ? -40 : -30;
            List<Curve2> c = s.get(r).curves();
            assertEquals(10, c.size());
            for (int k = 0; k < 5; k++) {
                double x0 = d * (-40 + 15 * k);
                assertLine(x0, y, x0 + d * 5, y, c.get(2 * k));
                assertArc(x0 + d * 5, y, x0 + d * 15, y, x0 + d * 10, y, r == 1, c.get(2 * k + 1));
                assertPoint(x0 + d * 10, y + 5, c.get(2 * k + 1).pointAt(0.5));
            }
        }
    }

    /**
     * Test 05, SUB9B: NOVO over (-35,-30) to (-40,-20); INDEX/4
     * {@code CALL/SUB9B,XB9=5,YB9=0,XC9=5,YC9=8,XD9=5,YD9=0,XE9=5,YE9=-8}; INDEX/5
     * {@code COPY/4,TRANSL,20,0,0,3}; INDEX/6 holds 4 and 5; {@code COPY/6,SAME,1}; NOVO over
     * (40,-20) to (40,-5); {@code COPY/6,TRANSL,0,15,0,MIRROR,YPAR,0,1}.
     *
     * <p>By hand: GODLTA 5,0 / 5,8 / 5,0 / 5,-8 from (-40,-20): (-35,-20) (-30,-12) (-25,-12)
     * (-20,-20), four periods of 20 to (40,-20); (x, y + 15) mirrored in x = 0 runs from (40,-5)
     * back to (-40,-5) with its tops at y = 3.
     */
    @Test
    void test05Sub9bTrapezoidWaveThereAndBack() throws Exception {
        TreadFigure novo = call("NOVO", "XF1=-35,YF1=-30,XF2=-40,YF2=-20");
        TreadFigure sub9b = call("SUB9B", "XB9=5,YB9=0,XC9=5,YC9=8,XD9=5,YD9=0,XE9=5,YE9=-8");
        List<Similarity2> block6 = new ArrayList<>();
        block6.add(Similarity2.IDENTITY);
        block6.addAll(row(Similarity2.IDENTITY, 20, 0, 3));
        List<Similarity2> copies = new ArrayList<>(block6);
        Similarity2 back = transl(0, 15).then(ypar(0));
        block6.forEach(t -> copies.add(t.then(back)));
        List<Stroke> s = cut(List.of(novo), sub9b, copies);
        assertEquals(2, s.size());
        double[][] rows = {{-40, -20, 1}, {40, -5, -1}};
        for (int r = 0; r < 2; r++) {
            double x = rows[r][0];
            double y = rows[r][1];
            double d = rows[r][2];
            double[] xy = new double[34];
            xy[0] = x;
            xy[1] = y;
            for (int k = 0; k < 4; k++) {
                double x0 = x + d * 20 * k;
                double[] p = {x0 + d * 5, y, x0 + d * 10, y + 8, x0 + d * 15, y + 8, x0 + d * 20, y};
                System.arraycopy(p, 0, xy, 2 + 8 * k, 8);
            }
            assertPolyline(s.get(r), xy);
        }
    }

    /**
     * Test 05, SUB9A: INDEX/7 {@code CALL/SUB9A,XA9=15,YA9=15,XB9=5,YB9=0,XC9=-5,YC9=10,XD9=-5,
     * YD9=0,XE9=5,YE9=-10}; INDEX/8 {@code COPY/7,TRANSL,10,0,0,2}; INDEX/9 holds 7 and 8;
     * {@code COPY/9,SAME,1}, {@code COPY/9,TRANSL,40,15,0,MIRROR,YPAR,45,1}.
     *
     * <p>By hand: the closed parallelogram (15,15) (20,15) (15,25) (10,25) (15,15), and at x + 10
     * and x + 20; moved (40,15) and mirrored in x = 45, (x, y) -> (50 - x, y + 15): (35,30)
     * (30,30) (35,40) (40,40) (35,30), and at x - 10 and x - 20.
     */
    @Test
    void test05Sub9aClosedParallelogramsAndTheirMirroredRow() throws Exception {
        TreadFigure sub9a = call("SUB9A", "XA9=15,YA9=15,XB9=5,YB9=0,XC9=-5,YC9=10,XD9=-5,YD9=0,XE9=5,YE9=-10");
        List<Similarity2> block9 = new ArrayList<>();
        block9.add(Similarity2.IDENTITY);
        block9.addAll(row(Similarity2.IDENTITY, 10, 0, 2));
        List<Similarity2> copies = new ArrayList<>(block9);
        Similarity2 mirrored = transl(40, 15).then(ypar(45));
        block9.forEach(t -> copies.add(t.then(mirrored)));
        List<Stroke> s = cut(List.of(), sub9a, copies);
        assertEquals(6, s.size());
        for (int k = 0; k < 3; k++) {
            double x = 15 + 10 * k;
            assertPolyline(s.get(k), x, 15, x + 5, 15, x, 25, x - 5, 25, x, 15);
            double xm = 35 - 10 * k;
            assertPolyline(s.get(3 + k), xm, 30, xm - 5, 30, xm, 40, xm + 5, 40, xm, 30);
        }
    }
}
