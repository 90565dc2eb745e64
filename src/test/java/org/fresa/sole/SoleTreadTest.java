package org.fresa.sole;

import static org.fresa.sole.TreadFigureTest.assertLine;
import static org.fresa.sole.TreadFigureTest.assertPoint;
import static org.fresa.sole.TreadFigureTest.call;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.ContourFile;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.post.NcPosts;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SoleTreadTest {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    private static final Vec2 ORIGIN = Vec2.of(0, 0.2);

    static Contour men40() throws Exception {
        try (var r = Files.newBufferedReader(Path.of("samples/sole/men40.contour"))) {
            return ContourFile.read(r, "men40.contour").get(0);
        }
    }

    @Test
    void copiesOfSub7bChainIntoTheZigZagRowOfTest02() throws Exception {
        TreadItem zig = new TreadItem(
                "zig-zag",
                List.of(call("PRIM", "XI=-40,YI=-10,XA1=0,YA1=0")),
                List.of(call("SUB7B", "XB7=10,YB7=8,XC7=10,YC7=-8")),
                TreadPattern.linear(20, 0, 4),
                SizeRule.HELD,
                false,
                "bit");
        List<Stroke> s = zig.strokes(TOL);
        assertEquals(1, s.size(), "one continuous groove");
        List<Curve2> c = s.get(0).curves();
        assertEquals(8, c.size());
        for (int i = 0; i < 8; i++) {
            double x = -40 + 10 * i;
            assertLine(x, i % 2 == 0 ? -10 : -2, x + 10, i % 2 == 0 ? -2 : -10, c.get(i));
        }
    }

    @Test
    void theBrickRowsOfTest01ComeFromALinearPatternAndAMirroredCopy() throws Exception {
        TreadFigure dash = call("SUB2", "XA2=-40,YA2=10,XB2=10,YB2=0");
        List<Similarity2> copies = List.of(
                Similarity2.IDENTITY,
                Similarity2.translation(15, 0),
                Similarity2.translation(30, 0),
                Similarity2.mirrorX(-23.75).then(Similarity2.translation(0, 5)),
                Similarity2.mirrorX(-23.75).then(Similarity2.translation(-15, 5)));
        List<Stroke> s = new TreadItem(
                        "bricks",
                        List.of(),
                        List.of(dash),
                        new TreadPattern.Copies(copies),
                        SizeRule.HELD,
                        false,
                        "bit")
                .strokes(TOL);
        assertEquals(5, s.size());
        assertLine(-10, 10, 0, 10, s.get(2).curves().get(0));
        assertLine(-7.5, 15, -17.5, 15, s.get(3).curves().get(0));
        assertLine(-22.5, 15, -32.5, 15, s.get(4).curves().get(0));
    }

    @Test
    void theLeftFootIsTheMirrorImageCutInTheSameSense() throws Exception {
        TreadItem ring = new TreadItem(
                "ring",
                List.of(),
                List.of(call("SUB4", "XC=-32,YC=161,RA=5,XA4=-37,YA4=161,XB4=-27,YB4=161")),
                TreadPattern.single(),
                SizeRule.HELD,
                false,
                "bit");
        SizeScale base = SizeScale.base("40", ORIGIN);
        List<Stroke> right = SoleTread.placed(ring, base, Foot.RIGHT, TOL);
        List<Stroke> left = SoleTread.placed(ring, base, Foot.LEFT, TOL);
        Arc2 r0 = (Arc2) right.get(0).curves().get(0);
        Arc2 l1 = (Arc2) left.get(0).curves().get(1);
        assertPoint(32, 161, l1.center());
        assertEquals(r0.ccw(), l1.ccw(), "climb stays climb");
        assertPoint(-r0.start().x(), r0.start().y(), l1.end());
        assertPoint(-r0.end().x(), r0.end().y(), l1.start());
    }

    @Test
    void textIsMovedToTheLeftFootButNotMirrored() throws Exception {
        TreadItem logo = new TreadItem(
                "logo",
                List.of(),
                List.of(call("SUB7A", "XA7=-20,YA7=100,XB7=5,YB7=10,XC7=5,YC7=-10")),
                TreadPattern.single(),
                SizeRule.HELD,
                true,
                "bit");
        List<Stroke> left = SoleTread.placed(logo, SizeScale.base("40", ORIGIN), Foot.LEFT, TOL);
        // the V's bounding box centre (-15, 105) goes to (15, 105); the V still opens downwards, left to right
        assertLine(10, 100, 15, 110, left.get(0).curves().get(0));
        assertLine(15, 110, 20, 100, left.get(0).curves().get(1));
    }

    @Test
    void sizeRulesHoldMoveOrScaleAFigure() throws Exception {
        TreadFigure dash = call("SUB2", "XA2=10,YA2=100,XB2=10,YB2=0");
        SizeScale s42 = new SizeScale("42", Vec2.ZERO, 1.05, 1.10, 1.02);
        List<Stroke> held = SoleTread.placed(item(dash, SizeRule.HELD), s42, Foot.RIGHT, TOL);
        assertLine(10.2, 102, 20.4, 102, held.get(0).curves().get(0));
        List<Stroke> moved = SoleTread.placed(item(dash, SizeRule.POSITION), s42, Foot.RIGHT, TOL);
        // anchor (15, 100) -> (15.75, 110); the dash keeps its length times the shrinkage
        assertLine(15.75 - 5.1, 110, 15.75 + 5.1, 110, moved.get(0).curves().get(0));
        List<Stroke> scaled = SoleTread.placed(item(dash, SizeRule.SCALED), s42, Foot.RIGHT, TOL);
        assertLine(10.5, 110, 21, 110, scaled.get(0).curves().get(0));
    }

    private static TreadItem item(TreadFigure f, SizeRule r) {
        return new TreadItem("x", List.of(), List.of(f), TreadPattern.single(), r, false, "bit");
    }

    @Test
    void aScaledArcPassesThroughTheGradedImagesOfItsEndsAndMiddle() {
        Arc2 a = new Arc2(Vec2.of(0, 50), Vec2.of(-10, 50), Vec2.of(10, 50), false);
        SizeScale s = new SizeScale("44", Vec2.ZERO, 1.07, 1.10, 1.02);
        Arc2 g = (Arc2) SoleTread.graded(a, s, TOL);
        assertPoint(-10.7, 55, g.start());
        assertPoint(10.7, 55, g.end());
        assertEquals(0, g.center().distance(s.graded(a.pointAt(0.5))) - g.radius(), 1e-9);
    }

    @Test
    void noGrooveOfTheZigZagFieldLeavesTheSoleShrunkByTheMargin() throws Exception {
        Contour outline = men40();
        TreadItem field = new TreadItem(
                "field",
                List.of(),
                List.of(call("SUB7A", "XA7=-70,YA7=130,XB7=15,YB7=11.7,XC7=15,YC7=-11.7")),
                TreadPattern.grid(30, 5.85, 5, 20, 0),
                SizeRule.SCALED,
                false,
                "bit");
        SoleTread tread = new SoleTread(List.of(field), 3);
        for (Foot foot : Foot.values()) {
            SizeScale s = new SizeScale("42", ORIGIN, 1.036889 + 0.02, 1.049333 + 0.02, 1.02);
            Contour graded = gradedOutline(outline, s);
            Contour sideOutline = foot == Foot.RIGHT ? graded : SoleTread.mirrored(graded, ORIGIN.x());
            List<SoleTread.ToolGrooves> g = tread.grooves(s, foot, graded, TOL);
            int n = 0;
            for (Stroke st : g.get(0).strokes()) {
                for (Curve2 c : st.curves()) {
                    for (int k = 0; k <= 8; k++) {
                        Vec2 p = c.pointAt(k / 8.0);
                        assertTrue(
                                sideOutline.contains(p, TOL) && sideOutline.distanceTo(p) >= 3 - 1e-6, foot + " " + p);
                        n++;
                    }
                }
            }
            assertTrue(n > 100, "the field is cut");
        }
    }

    /** The outline graded by the 3-point rebuild (the tread test needs an outline per size, not the grading module). */
    static Contour gradedOutline(Contour base, SizeScale s) {
        return Contour.of(
                base.curves().stream().map(c -> SoleTread.graded(c, s, TOL)).toList(), Tolerance.ofLinear(1e-6));
    }

    @Test
    void leftProgramsAreTheMirrorOfTheRightOnes() throws Exception {
        Contour outline = men40();
        SoleTread tread = sample();
        SizeScale s = SizeScale.base("40", ORIGIN);
        List<Stroke> right = tread.grooves(s, Foot.RIGHT, outline, TOL).get(0).strokes();
        List<Stroke> left = tread.grooves(s, Foot.LEFT, outline, TOL).get(0).strokes();
        double lr = right.stream().mapToDouble(Stroke::length).sum();
        double ll = left.stream().mapToDouble(Stroke::length).sum();
        assertEquals(lr, ll, 1e-6);
        for (Stroke st : left) {
            for (Curve2 c : st.curves()) {
                Vec2 m = c.pointAt(0.5);
                Vec2 back = Vec2.of(2 * ORIGIN.x() - m.x(), m.y());
                assertTrue(
                        right.stream().anyMatch(r -> r.curves().stream().anyMatch(k -> k.distanceTo(back) < 1e-6)),
                        "" + m);
            }
        }
    }

    static SoleTread sample() throws Exception {
        TreadItem heel = new TreadItem(
                "heel grooves",
                List.of(),
                List.of(call("SUB1A", "XA1=-34,YA1=-23,XB1=34,XC1=34,YC1=-18.6,XD1=-34")),
                TreadPattern.linear(0, 8.8, 3),
                SizeRule.SCALED,
                false,
                "bit");
        TreadItem rings = new TreadItem(
                "rings",
                List.of(),
                List.of(
                        call("SUB4", "XC=-32,YC=161,RA=23,XA4=-55,YA4=161,XB4=-9,YB4=161"),
                        call("SUB4", "XC=-32,YC=161,RA=16.5,XA4=-48.5,YA4=161,XB4=-15.5,YB4=161")),
                TreadPattern.single(),
                SizeRule.POSITION,
                false,
                "bit");
        return new SoleTread(List.of(heel, rings), 2);
    }

    @Test
    @InterpreterCheck
    void theTreadProgramIsAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        SoleTread tread = sample();
        Contour outline = men40();
        for (Foot foot : Foot.values()) {
            Toolpath tp = TreadProgram.toolpath(
                    tread.grooves(SizeScale.base("40", ORIGIN), foot, outline, TOL),
                    Map.of("bit", new TreadTool("bit", 5, 3.5, 4000, 160, 80)),
                    2,
                    5);
            assertTrue(
                    tp.sections().get(0).moves().stream().anyMatch(m -> m instanceof Move.Circular), "arcs stay arcs");
            StringWriter w = new StringWriter();
            NcPosts.defaultPost().write(tp, "tread-40-" + foot.id(), w);
            Path f = dir.resolve("tread-40-" + foot.id() + ".ngc");
            Files.writeString(f, w.toString());
            assertFalse(w.toString().isEmpty());
            Assumptions.assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
            org.fresa.post.Rs274.Result r = org.fresa.post.Rs274.run(f, 3.5);
            assertEquals(0, r.exitStatus(), org.fresa.post.Rs274.log(r));
        }
    }
}
