package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * The DESCOM macro library of Ahrens (1986, App. C/E): each macro as a record with the thesis's
 * parameter names (lower case), all in mm in the part frame of the base-size sole, producing the
 * tool-centre path the macro describes.
 *
 * <p>Parameters the macros share and that live elsewhere here:
 * <ul>
 *   <li>{@code CTM} (shrinkage): every macro multiplies every coordinate and radius by (1 + CTM),
 *       which is a uniform scale about the part zero; it is applied to the whole tread
 *       ({@link SizeScale}), not per figure.
 *   <li>{@code PROF} (depth) and {@code AVAN} (feed): the tread's depth and its tool's feed.
 *   <li>{@code I} (subscript for EXAPT's geometry names): not needed.
 * </ul>
 *
 * <p>Topology (thesis Fig. c.1): the "A" types, SUB2 and SUB4 plunge and retract
 * ({@link FigurePath#joinsPrevious()} false); the "B" and "E" types and SUB7B/8B/9B carry on the
 * groove in progress from the tool's position, which PRIM or NOVO (or an earlier continuous
 * figure) left at depth. The thesis's OCR names SUB3E/SUB5E may stand for SUB3C/SUB5C; the
 * macro names here are the printed ones.
 *
 * <p>Start-ups and turns ({@code GO/ON,YPAR,x,ON,circle}, {@code GOLFT}/{@code GORGT}) depend in
 * EXAPT on the direction the tool came from. Here the arc macros take that choice as a sense
 * ({@code ccw}); with the approaches of the thesis's test programs every one of them turns
 * clockwise (over the top when travelling in +x), which is the default of the factories in
 * {@link TreadFigures}. Of the two points where x = XA meets a circle, the start is the one where
 * travel in the sense heads towards the end line.
 */
public sealed interface TreadFigure {

    /**
     * The special designs of Table 5.2 (groups F to J), which the thesis's library does not
     * cover: {@link SpecialDesigns}.
     */
    non-sealed interface Special extends TreadFigure {}

    /** The thesis's macro name, e.g. {@code SUB1A}. */
    String macro();

    /**
     * The tool-centre path.
     *
     * @param at where the tool is before the call (mm); the continuous types start there
     * @throws IllegalArgumentException when the parameters give no path (a line misses a circle)
     */
    FigurePath path(Vec2 at, Tolerance tol);

    private static FigurePath discontinuous(Stroke... strokes) {
        return new FigurePath(false, List.of(strokes), false);
    }

    private static List<Curve2> relative(Vec2 from, double... d) {
        List<Curve2> out = new ArrayList<>();
        Vec2 p = from;
        for (int i = 0; i < d.length; i += 2) {
            Vec2 q = p.plus(Vec2.of(d[i], d[i + 1]));
            out.add(new Segment2(p, q));
            p = q;
        }
        return out;
    }

    private static List<Curve2> joinFrom(Vec2 at, Vec2 start, Tolerance tol) {
        return at.eq(start, tol) ? new ArrayList<>() : new ArrayList<>(List.of(new Segment2(at, start)));
    }

    /**
     * PRIM: rapid to (XI, YI), then by (XA1, YA1), and plunge: starts a continuous groove.
     *
     * @param xi first point x
     * @param yi first point y
     * @param xa1 relative shift x (usually 0)
     * @param ya1 relative shift y (usually 0)
     */
    record Prim(double xi, double yi, double xa1, double ya1) implements TreadFigure {
        public String macro() {
            return "PRIM";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 first = Vec2.of(xi, yi);
            Vec2 start = first.plus(Vec2.of(xa1, ya1));
            List<Vec2> via = start.eq(first, tol) ? List.of() : List.of(first);
            return new FigurePath(false, List.of(new Stroke(via, start, List.of())), true);
        }
    }

    /**
     * NOVO: lift, rapid over (XF1, YF1) to (XF2, YF2) and plunge: restarts a continuous groove
     * elsewhere.
     *
     * @param xf1 intermediate point x
     * @param yf1 intermediate point y
     * @param xf2 new plunge point x
     * @param yf2 new plunge point y
     */
    record Novo(double xf1, double yf1, double xf2, double yf2) implements TreadFigure {
        public String macro() {
            return "NOVO";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return new FigurePath(
                    false, List.of(new Stroke(List.of(Vec2.of(xf1, yf1)), Vec2.of(xf2, yf2), List.of())), true);
        }
    }

    /**
     * SUB1A: a pair of grooves parallel to x: from (XA1, YA1) along y = YA1 to x = XB1, then from
     * (XC1, YC1) along y = YC1 to x = XD1 (usually back: a boustrophedon pair).
     */
    record Sub1a(double xa1, double ya1, double xb1, double yc1, double xc1, double xd1) implements TreadFigure {
        public String macro() {
            return "SUB1A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return discontinuous(
                    Stroke.of(Vec2.of(xa1, ya1), List.of(Segment2.of(xa1, ya1, xb1, ya1))),
                    Stroke.of(Vec2.of(xc1, yc1), List.of(Segment2.of(xc1, yc1, xd1, yc1))));
        }
    }

    /**
     * SUB1B: a pair of grooves parallel to y: from (XA1, YA1) along x = XA1 to y = YB1, then from
     * (XC1, YC1) along x = XC1 to y = YD1.
     */
    record Sub1b(double xa1, double ya1, double yb1, double yc1, double xc1, double yd1) implements TreadFigure {
        public String macro() {
            return "SUB1B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return discontinuous(
                    Stroke.of(Vec2.of(xa1, ya1), List.of(Segment2.of(xa1, ya1, xa1, yb1))),
                    Stroke.of(Vec2.of(xc1, yc1), List.of(Segment2.of(xc1, yc1, xc1, yd1))));
        }
    }

    /** SUB2: one straight groove from (XA2, YA2) by (XB2, YB2); YB2 != 0 inclines it (group B). */
    record Sub2(double xa2, double ya2, double xb2, double yb2) implements TreadFigure {
        public String macro() {
            return "SUB2";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 a = Vec2.of(xa2, ya2);
            return discontinuous(Stroke.of(a, relative(a, xb2, yb2)));
        }
    }

    /**
     * SUB3A: an arc groove on the circle (XC, YC) radius RA, from where x = XA3 meets it to the
     * first crossing of x = XB3.
     *
     * @param ccw the sense (thesis tests: clockwise)
     */
    record Sub3a(double xc, double yc, double ra, double xa3, double xb3, boolean ccw) implements TreadFigure {
        public String macro() {
            return "SUB3A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 c = Vec2.of(xc, yc);
            Vec2 s = CircleWalk.startAtX(c, ra, xa3, xb3, ccw, tol, macro());
            return discontinuous(Stroke.of(s, List.of(CircleWalk.toX(c, ra, s, ccw, xb3, tol, macro()))));
        }
    }

    /**
     * SUB3B: SUB3A as a continuous groove: a straight cut from the tool's position to the arc's
     * start, then the arc (phase-shifted arcs when copied).
     */
    record Sub3b(double xc, double yc, double ra, double xa3, double xb3, boolean ccw) implements TreadFigure {
        public String macro() {
            return "SUB3B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 c = Vec2.of(xc, yc);
            Vec2 s = CircleWalk.startAtX(c, ra, xa3, xb3, ccw, tol, macro());
            List<Curve2> cuts = joinFrom(at, s, tol);
            cuts.add(CircleWalk.toX(c, ra, s, ccw, xb3, tol, macro()));
            return new FigurePath(true, List.of(Stroke.of(at, cuts)), true);
        }
    }

    /**
     * SUB3E: successive arcs: the circle (XC, YC, RA) and N copies shifted by I * AFAS in x
     * (I = 1..N, N >= 1). From x = XA3 on the first circle to where it meets the second, then on
     * each copy I backwards (GOBACK) to x = XB3 + I * AFAS: a scalloped line.
     */
    record Sub3e(double xc, double yc, double ra, double xa3, double xb3, double afas, int n, boolean ccw)
            implements TreadFigure {
        public Sub3e {
            if (n < 1) {
                throw new IllegalArgumentException("SUB3E needs N >= 1 (the macro's loop runs at least once): " + n);
            }
        }

        public String macro() {
            return "SUB3E";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 c0 = Vec2.of(xc, yc);
            Vec2 s = CircleWalk.startAtX(c0, ra, xa3, xb3 + n * afas, ccw, tol, macro());
            List<Curve2> cuts = new ArrayList<>();
            Arc2 first = CircleWalk.toCircle(c0, s, ccw, Vec2.of(xc + afas, yc), ra, tol, macro());
            cuts.add(first);
            Vec2 heading = first.endTangent();
            Vec2 p = first.end();
            for (int i = 1; i <= n; i++) {
                Vec2 ci = Vec2.of(xc + i * afas, yc);
                boolean sense = CircleWalk.nextSense(heading, ci, p, false);
                Arc2 a = CircleWalk.toX(ci, ra, p, sense, xb3 + i * afas, tol, macro());
                cuts.add(a);
                heading = a.endTangent();
                p = a.end();
            }
            return discontinuous(Stroke.of(s, cuts));
        }
    }

    /**
     * SUB4: a full ring on the circle (XC, YC, RA). LN1 is the tangent from PTA = (XA4, YA4) on its
     * left (seen from PTA towards the centre), LN2 the parallel through PTB = (XB4, YB4). The cut
     * starts at the tangent point, runs to LN2 and on round back to the start.
     *
     * @param ccw the sense (thesis: GORGT, clockwise from an approach from the left)
     */
    record Sub4(double xc, double yc, double ra, double xa4, double ya4, double xb4, double yb4, boolean ccw)
            implements TreadFigure {
        public String macro() {
            return "SUB4";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 c = Vec2.of(xc, yc);
            Vec2 pta = Vec2.of(xa4, ya4);
            double d = pta.distance(c);
            Vec2 t;
            if (Math.abs(d - ra) <= tol.linear()) {
                t = pta;
            } else if (d < ra) {
                throw new IllegalArgumentException("SUB4: PTA lies inside the circle, no tangent");
            } else {
                Vec2 u = pta.minus(c).times(1 / d);
                double alpha = Math.acos(ra / d);
                Vec2 t1 = c.plus(u.rotated(alpha).times(ra));
                Vec2 t2 = c.plus(u.rotated(-alpha).times(ra));
                Vec2 left = c.minus(pta).leftNormal();
                t = t1.minus(pta).dot(left) >= t2.minus(pta).dot(left) ? t1 : t2;
            }
            Vec2 dir = t.minus(c).leftNormal();
            List<Vec2> onLn2 = org.fresa.geom.Intersections.lineCircle(Vec2.of(xb4, yb4), dir, c, ra, tol);
            List<Vec2> ahead = onLn2.stream().filter(p -> !p.eq(t, tol)).toList();
            if (ahead.isEmpty()) {
                return discontinuous(Stroke.of(t, List.of(new Arc2(c, t, t, ccw))));
            }
            Vec2 h = CircleWalk.firstHit(c, t, ccw, ahead, "SUB4");
            return discontinuous(Stroke.of(t, List.of(new Arc2(c, t, h, ccw), new Arc2(c, h, t, ccw))));
        }
    }

    /**
     * SUB5A: a wave on two circles with centres PC1 = (XC1, YC1) and PC2 = (XC2, YC2), both
     * through PTAN = (XT, YT): from x = XA5 on circle 1 to PTAN, then forward on circle 2 to x = XB5.
     *
     * @param ccw the sense on circle 1 (thesis: clockwise)
     */
    record Sub5a(
            double xc1, double yc1, double xc2, double yc2, double xt, double yt, double xa5, double xb5, boolean ccw)
            implements TreadFigure {
        public String macro() {
            return "SUB5A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            List<Curve2> w = Waves.wave(xc1, yc1, xc2, yc2, xt, yt, xa5, xb5, 0, 0, ccw, tol, macro());
            return discontinuous(Stroke.of(w.get(0).start(), w));
        }
    }

    /** SUB5B: SUB5A as a continuous groove (a straight cut from the tool's position first). */
    record Sub5b(
            double xc1, double yc1, double xc2, double yc2, double xt, double yt, double xa5, double xb5, boolean ccw)
            implements TreadFigure {
        public String macro() {
            return "SUB5B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            List<Curve2> w = Waves.wave(xc1, yc1, xc2, yc2, xt, yt, xa5, xb5, 0, 0, ccw, tol, macro());
            List<Curve2> cuts = joinFrom(at, w.get(0).start(), tol);
            cuts.addAll(w);
            return new FigurePath(true, List.of(Stroke.of(at, cuts)), true);
        }
    }

    /**
     * SUB5E: successive waves: the SUB5A pair and N pairs shifted by I * AFAS in x (N >= 1), cut
     * forward through every circle, ending at x = XB5 + N * AFAS.
     */
    record Sub5e(
            double xc1,
            double yc1,
            double xc2,
            double yc2,
            double xt,
            double yt,
            double xa5,
            double xb5,
            double afas,
            int n,
            boolean ccw)
            implements TreadFigure {
        public Sub5e {
            if (n < 1) {
                throw new IllegalArgumentException("SUB5E needs N >= 1 (the macro's loop runs at least once): " + n);
            }
        }

        public String macro() {
            return "SUB5E";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            List<Curve2> w = Waves.wave(xc1, yc1, xc2, yc2, xt, yt, xa5, xb5, afas, n, ccw, tol, macro());
            return discontinuous(Stroke.of(w.get(0).start(), w));
        }
    }

    /** SUB7A: a "V": from (XA7, YA7) by (XB7, YB7) then by (XC7, YC7). */
    record Sub7a(double xa7, double ya7, double xb7, double yb7, double xc7, double yc7) implements TreadFigure {
        public String macro() {
            return "SUB7A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 a = Vec2.of(xa7, ya7);
            return discontinuous(Stroke.of(a, relative(a, xb7, yb7, xc7, yc7)));
        }
    }

    /** SUB7B: two relative cuts (XB7, YB7), (XC7, YC7) from the tool's position: zig-zags when copied. */
    record Sub7b(double xb7, double yb7, double xc7, double yc7) implements TreadFigure {
        public String macro() {
            return "SUB7B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return new FigurePath(true, List.of(Stroke.of(at, relative(at, xb7, yb7, xc7, yc7))), true);
        }
    }

    /** SUB8A: from (XA8, YA8) three relative cuts B, C, D. */
    record Sub8a(double xa8, double ya8, double xb8, double yb8, double xc8, double yc8, double xd8, double yd8)
            implements TreadFigure {
        public String macro() {
            return "SUB8A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 a = Vec2.of(xa8, ya8);
            return discontinuous(Stroke.of(a, relative(a, xb8, yb8, xc8, yc8, xd8, yd8)));
        }
    }

    /** SUB8B: three relative cuts from the tool's position (a trapezoid wave when copied). */
    record Sub8b(double xb8, double yb8, double xc8, double yc8, double xd8, double yd8) implements TreadFigure {
        public String macro() {
            return "SUB8B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return new FigurePath(true, List.of(Stroke.of(at, relative(at, xb8, yb8, xc8, yc8, xd8, yd8))), true);
        }
    }

    /** SUB9A: from (XA9, YA9) four relative cuts B, C, D, E; closes on itself for parallelograms (group F). */
    record Sub9a(
            double xa9,
            double ya9,
            double xb9,
            double yb9,
            double xc9,
            double yc9,
            double xd9,
            double yd9,
            double xe9,
            double ye9)
            implements TreadFigure {
        public String macro() {
            return "SUB9A";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 a = Vec2.of(xa9, ya9);
            return discontinuous(Stroke.of(a, relative(a, xb9, yb9, xc9, yc9, xd9, yd9, xe9, ye9)));
        }
    }

    /** SUB9B: four relative cuts from the tool's position. */
    record Sub9b(double xb9, double yb9, double xc9, double yc9, double xd9, double yd9, double xe9, double ye9)
            implements TreadFigure {
        public String macro() {
            return "SUB9B";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return new FigurePath(
                    true, List.of(Stroke.of(at, relative(at, xb9, yb9, xc9, yc9, xd9, yd9, xe9, ye9))), true);
        }
    }
}
