package org.fresa.sole;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * The special designs of Ahrens (1986, Table 5.2, groups F to J), which the thesis made by
 * machining, punching or EDM and for which its DESCOM library has no macro (only F, as closed
 * SUB9A copies): parametric fields of grooves laid over a region of the sole and clipped to the
 * outline by the tread, like every other figure. Each groove of a field is cut once (a side two
 * cells share is one groove), and successive grooves run back and forth so that the rapids
 * between them stay short.
 *
 * <p>Names and parameters are ours, in the thesis's style (upper-case keywords, mm and degrees):
 * PARAL (F), COLMEIA (G), PIRAM (H), TEXTURA (I), LOGO (J).
 */
public final class SpecialDesigns {

    /** The macro names of the special designs, groups F to J. */
    public static final List<String> MACROS = List.of("PARAL", "COLMEIA", "PIRAM", "TEXTURA", "LOGO");

    private SpecialDesigns() {}

    /** The group of Table 5.2 a special design's macro makes, with the thesis's description. */
    public static String group(String macro) {
        return switch (macro.toUpperCase(Locale.ROOT)) {
            case "PARAL" -> "F (parallelograms)";
            case "COLMEIA" -> "G (hexagons, honeycomb)";
            case "PIRAM" -> "H (inverted-pyramid cavities)";
            case "TEXTURA" -> "I (surfaces imitating leather, fabric, stitching)";
            case "LOGO" -> "J (logos, trade marks, size numbers)";
            default -> throw new IllegalArgumentException("not a special design: " + macro);
        };
    }

    private static Vec2 dir(double angDeg) {
        double a = Math.toRadians(angDeg);
        return Vec2.of(Math.cos(a), Math.sin(a));
    }

    private static int count(int n, String name) {
        if (n < 1 || n > 1000) {
            throw new IllegalArgumentException(name + " must be from 1 to 1000: " + n);
        }
        return n;
    }

    private static double positive(double v, String name) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be > 0: " + v);
        }
        return v;
    }

    /**
     * The grooves of a lattice of parallelograms with corner {@code o}, sides {@code u} and
     * {@code v} and {@code nu} by {@code nv} cells: the nv + 1 lines along u, then the nu + 1
     * lines along v, each set back and forth.
     */
    static List<Stroke> lattice(Vec2 o, Vec2 u, Vec2 v, int nu, int nv) {
        List<Stroke> out = new ArrayList<>();
        for (int j = 0; j <= nv; j++) {
            Vec2 a = o.plus(v.times(j));
            Vec2 b = a.plus(u.times(nu));
            out.add(j % 2 == 0 ? line(a, b) : line(b, a));
        }
        for (int i = 0; i <= nu; i++) {
            // the first line along v starts at the end of u where the last line along u ended, at its top
            int at = nv % 2 == 0 ? nu - i : i;
            Vec2 a = o.plus(u.times(at));
            Vec2 b = a.plus(v.times(nv));
            out.add(i % 2 == 0 ? line(b, a) : line(a, b));
        }
        return out;
    }

    private static Stroke line(Vec2 a, Vec2 b) {
        return Stroke.of(a, List.of(new Segment2(a, b)));
    }

    private static FigurePath field(List<Stroke> strokes) {
        return new FigurePath(false, strokes, false);
    }

    /**
     * Group F, parallelograms (PARAL): a lattice of NA by NB parallelograms from the corner
     * (XO, YO), sides A along x and B at ANG degrees from x.
     */
    public record Parallelograms(double xo, double yo, double a, double b, double angDeg, int na, int nb)
            implements TreadFigure.Special {
        public Parallelograms {
            positive(a, "A");
            positive(b, "B");
            double s = Math.abs(Math.sin(Math.toRadians(angDeg)));
            if (!(s > 1e-3)) {
                throw new IllegalArgumentException("ANG must not make the sides parallel: " + angDeg);
            }
            count(na, "NA");
            count(nb, "NB");
        }

        public String macro() {
            return "PARAL";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return field(lattice(Vec2.of(xo, yo), Vec2.of(a, 0), dir(angDeg).times(b), na, nb));
        }
    }

    /**
     * Group H, inverted pyramids (PIRAM): V grooves in two directions at right angles, pitch P,
     * the first direction at ANG degrees from x, N1 by N2 pyramids from the corner (XO, YO). A V
     * bit of included angle 2 beta cut P / (2 tan beta) deep leaves sharp pyramids; shallower,
     * flat-topped ones.
     */
    public record InvertedPyramids(double xo, double yo, double p, double angDeg, int n1, int n2)
            implements TreadFigure.Special {
        public InvertedPyramids {
            positive(p, "P");
            count(n1, "N1");
            count(n2, "N2");
        }

        public String macro() {
            return "PIRAM";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            return field(lattice(
                    Vec2.of(xo, yo), dir(angDeg).times(p), dir(angDeg + 90).times(p), n1, n2));
        }
    }

    /**
     * Group G, honeycomb (COLMEIA): NX by NY hexagons of side S with a vertex up, the first centred
     * at (XO, YO), rows 1.5 S apart, every other row shifted by half a cell (sqrt(3) S / 2). Each
     * side is cut once, the sides chained into as few grooves as a walk along free sides gives.
     */
    public record Honeycomb(double xo, double yo, double s, int nx, int ny) implements TreadFigure.Special {
        public Honeycomb {
            positive(s, "S");
            count(nx, "NX");
            count(ny, "NY");
            if ((long) nx * ny > 10_000) {
                throw new IllegalArgumentException("at most 10000 cells: " + nx + " x " + ny);
            }
        }

        public String macro() {
            return "COLMEIA";
        }

        /** The centre of cell (i, j). */
        public Vec2 centre(int i, int j) {
            double w = Math.sqrt(3) * s;
            return Vec2.of(xo + i * w + (j % 2 == 1 ? w / 2 : 0), yo + j * 1.5 * s);
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            // every side once: keyed by its end points rounded to 1e-6 mm, in a fixed order
            Map<String, Segment2> sides = new LinkedHashMap<>();
            for (int j = 0; j < ny; j++) {
                for (int i = 0; i < nx; i++) {
                    Vec2 c = centre(i, j);
                    for (int k = 0; k < 6; k++) {
                        Vec2 p = c.plus(dir(90 + 60 * k).times(s));
                        Vec2 q = c.plus(dir(150 + 60 * k).times(s));
                        String a = key(p);
                        String b = key(q);
                        sides.putIfAbsent(a.compareTo(b) < 0 ? a + b : b + a, new Segment2(p, q));
                    }
                }
            }
            return field(chained(new ArrayList<>(sides.values())));
        }

        private static String key(Vec2 p) {
            return String.format(Locale.ROOT, "(%.6f,%.6f)", p.x(), p.y());
        }

        /** Walks the sides into grooves: each groove goes on along any free side at its end. */
        private static List<Stroke> chained(List<Segment2> free) {
            List<Stroke> out = new ArrayList<>();
            while (!free.isEmpty()) {
                Segment2 first = free.remove(0);
                List<Curve2> cs = new ArrayList<>(List.of(first));
                Vec2 end = first.end();
                boolean more = true;
                while (more) {
                    more = false;
                    for (int k = 0; k < free.size(); k++) {
                        Segment2 n = free.get(k);
                        if (key(n.start()).equals(key(end))) {
                            cs.add(n);
                        } else if (key(n.end()).equals(key(end))) {
                            n = new Segment2(n.end(), n.start());
                            cs.add(n);
                        } else {
                            continue;
                        }
                        free.remove(k);
                        end = n.end();
                        more = true;
                        break;
                    }
                }
                out.add(Stroke.of(first.start(), cs));
            }
            return out;
        }
    }

    /**
     * Group I, surfaces imitating leather, fabric or stitching (TEXTURA): N parallel lines of
     * length L at ANG degrees from x, P apart, the first from (XO, YO); with a dash length DASH
     * above 0 each line is cut as dashes DASH long with GAP between them (stitching), else
     * whole (fabric ribs, leather grain at a fine pitch).
     */
    public record TextureLines(double xo, double yo, double l, double p, double angDeg, int n, double dash, double gap)
            implements TreadFigure.Special {
        public TextureLines {
            positive(l, "L");
            positive(p, "P");
            count(n, "N");
            if (!(dash >= 0) || !(gap >= 0) || !Double.isFinite(dash) || !Double.isFinite(gap)) {
                throw new IllegalArgumentException("DASH and GAP must be >= 0");
            }
            if (dash > 0 && !(gap > 0)) {
                throw new IllegalArgumentException("a dashed line needs GAP > 0");
            }
            if (dash > 0 && l / (dash + gap) > 10_000) {
                throw new IllegalArgumentException("at most 10000 dashes a line");
            }
        }

        public String macro() {
            return "TEXTURA";
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Vec2 u = dir(angDeg);
            Vec2 v = dir(angDeg + 90).times(p);
            List<Stroke> out = new ArrayList<>();
            for (int k = 0; k < n; k++) {
                Vec2 a = Vec2.of(xo, yo).plus(v.times(k));
                List<double[]> pieces = new ArrayList<>();
                if (dash > 0) {
                    for (double t = 0; t < l - 1e-9; t += dash + gap) {
                        pieces.add(new double[] {t, Math.min(t + dash, l)});
                    }
                } else {
                    pieces.add(new double[] {0, l});
                }
                if (k % 2 == 1) {
                    java.util.Collections.reverse(pieces);
                }
                for (double[] d : pieces) {
                    Vec2 s = a.plus(u.times(d[0]));
                    Vec2 e = a.plus(u.times(d[1]));
                    out.add(k % 2 == 0 ? line(s, e) : line(e, s));
                }
            }
            return field(out);
        }
    }

    /**
     * Group J, logos, trade marks and size numbers (LOGO): the outlines of a drawing (text
     * converted to outlines in the CAD system, or a logo), scaled uniformly to the height H and
     * placed with the lower left corner of their extents at (X, Y); each outline a groove, arcs
     * kept as arcs. The drawing's chains are given by whoever reads its file.
     *
     * @param chains the drawing's outlines (closed or open chains of lines and arcs), in its frame
     */
    public record Logo(double x, double y, double h, List<List<Curve2>> chains) implements TreadFigure.Special {
        public Logo {
            positive(h, "H");
            chains = chains.stream().map(List::copyOf).toList();
            if (chains.isEmpty() || chains.stream().anyMatch(List::isEmpty)) {
                throw new IllegalArgumentException("LOGO needs the outlines of a drawing (the figure's file)");
            }
            if (!(extents(chains).height() > 0)) {
                throw new IllegalArgumentException("the drawing's outlines have no height");
            }
        }

        public String macro() {
            return "LOGO";
        }

        static Box2 extents(List<List<Curve2>> chains) {
            Box2 b = null;
            for (List<Curve2> c : chains) {
                for (Curve2 k : c) {
                    b = b == null ? k.bounds() : b.union(k.bounds());
                }
            }
            return b;
        }

        public FigurePath path(Vec2 at, Tolerance tol) {
            Box2 b = extents(chains);
            Similarity2 t = Similarity2.translation(-b.minX(), -b.minY())
                    .then(Similarity2.scale(Vec2.ZERO, h / b.height()))
                    .then(Similarity2.translation(x, y));
            List<Stroke> out = new ArrayList<>();
            for (List<Curve2> c : chains) {
                List<Curve2> cs = c.stream().map(t::apply).toList();
                out.add(Stroke.of(cs.get(0).start(), cs));
            }
            return field(out);
        }
    }
}
