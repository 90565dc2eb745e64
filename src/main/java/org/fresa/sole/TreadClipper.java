package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.pocket.LineArcOffsetter;

/**
 * Clips tread grooves to a sole outline shrunk by a margin: what the thesis did by hand with
 * about 90 explicit moves in the toe region of its insert program.
 *
 * <p>The allowed region is the outline offset inwards by the margin, computed exactly (lines and
 * arcs) by {@link LineArcOffsetter}; with a zero margin it is the outline itself. Every groove
 * curve is split where it crosses the region's boundary ({@link Intersections}) and the pieces
 * whose middle lies inside (or on the boundary) are kept; consecutive kept pieces that meet stay
 * one stroke, and a stroke that leaves and re-enters becomes two (retract, reposition, plunge).
 * So every kept point is at least {@code margin} from the outline (within the tolerance), and
 * strokes with no cut left are dropped. Arcs stay arcs.
 */
public final class TreadClipper {

    private final List<Contour> boundary;
    private final boolean ccw;
    private final Tolerance tol;

    private TreadClipper(List<Contour> boundary, boolean ccw, Tolerance tol) {
        this.boundary = boundary;
        this.ccw = ccw;
        this.tol = tol;
    }

    /**
     * A clipper for the outline shrunk by marginMm (>= 0). The region may be empty (an outline
     * narrower than twice the margin): then nothing is kept.
     */
    public static TreadClipper of(Contour outline, double marginMm, Tolerance tol) {
        if (!(marginMm >= 0) || !Double.isFinite(marginMm)) {
            throw new IllegalArgumentException("margin must be finite and >= 0: " + marginMm);
        }
        List<Contour> b = marginMm == 0 ? List.of(outline) : LineArcOffsetter.offset(outline, -marginMm, tol);
        return new TreadClipper(b, outline.isCcw(), tol);
    }

    /** One-liner: the strokes clipped to the outline shrunk by marginMm. */
    public static List<Stroke> clip(List<Stroke> strokes, Contour outline, double marginMm, Tolerance tol) {
        return of(outline, marginMm, tol).clip(strokes);
    }

    /** The boundary of the allowed region (the shrunk outline's loops). */
    public List<Contour> boundary() {
        return boundary;
    }

    /** Whether p is inside the allowed region or on its boundary. */
    public boolean allows(Vec2 p) {
        int w = 0;
        for (Contour c : boundary) {
            if (c.distanceTo(p) <= tol.linear()) {
                return true;
            }
            w += c.windingNumber(p);
        }
        return ccw ? w > 0 : w < 0;
    }

    public List<Stroke> clip(List<Stroke> strokes) {
        List<Stroke> out = new ArrayList<>();
        for (Stroke s : strokes) {
            List<Curve2> run = new ArrayList<>();
            boolean first = true;
            for (Curve2 c : s.curves()) {
                for (Curve2 piece : split(c)) {
                    if (allows(piece.pointAt(0.5))) {
                        if (!run.isEmpty() && !run.get(run.size() - 1).end().eq(piece.start(), tol)) {
                            out.add(stroke(s, run, first));
                            first = false;
                            run = new ArrayList<>();
                        }
                        run.add(piece);
                    } else if (!run.isEmpty()) {
                        out.add(stroke(s, run, first));
                        first = false;
                        run = new ArrayList<>();
                    } else {
                        first = false;
                    }
                }
            }
            if (!run.isEmpty()) {
                out.add(stroke(s, run, first));
            }
        }
        return out;
    }

    private static Stroke stroke(Stroke from, List<Curve2> run, boolean first) {
        Vec2 start = run.get(0).start();
        List<Vec2> via = first && start.equals(from.start()) ? from.via() : List.of();
        return new Stroke(via, start, run);
    }

    /** The curve split at every crossing with the boundary. */
    List<Curve2> split(Curve2 c) {
        double len = c.length();
        if (len <= tol.linear()) {
            return List.of();
        }
        List<Double> ts = new ArrayList<>();
        for (Contour b : boundary) {
            for (Curve2 k : b.curves()) {
                if (!c.bounds().intersects(grow(k))) {
                    continue;
                }
                for (Vec2 p : Intersections.of(c, k, tol)) {
                    double t = fraction(c, p);
                    if (t * len > tol.linear() && (1 - t) * len > tol.linear()) {
                        ts.add(t);
                    }
                }
            }
        }
        if (ts.isEmpty()) {
            return List.of(c);
        }
        ts.sort(Double::compare);
        List<Curve2> out = new ArrayList<>();
        Vec2 from = c.start();
        double last = 0;
        for (double t : ts) {
            if ((t - last) * len <= tol.linear()) {
                continue;
            }
            Vec2 to = c.pointAt(t);
            out.add(piece(c, from, to));
            from = to;
            last = t;
        }
        out.add(piece(c, from, c.end()));
        return out;
    }

    private org.fresa.geom.Box2 grow(Curve2 k) {
        org.fresa.geom.Box2 b = k.bounds();
        double e = tol.linear();
        return new org.fresa.geom.Box2(b.minX() - e, b.minY() - e, b.maxX() + e, b.maxY() + e);
    }

    private static Curve2 piece(Curve2 c, Vec2 from, Vec2 to) {
        if (c instanceof Segment2) {
            return new Segment2(from, to);
        }
        Arc2 a = (Arc2) c;
        return new Arc2(a.center(), from, to, a.ccw());
    }

    private static double fraction(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            Vec2 d = s.direction();
            return p.minus(s.start()).dot(d) / d.dot(d);
        }
        Arc2 a = (Arc2) c;
        return CircleWalk.sweep(a.center(), a.start(), p, a.ccw()) / Math.abs(a.sweepRad());
    }
}
