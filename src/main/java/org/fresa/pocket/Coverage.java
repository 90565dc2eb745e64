package org.fresa.pocket;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * What a pocket's passes leave at the floor, on a square grid of cells (their centres sampled):
 * the material the tool can reach is every point within the tool radius R of the region its
 * centre may go (the finishing offset's faces, F); a point is cut when it lies within R of a pass
 * the tool follows at the floor. Arcs are followed by chords within half a micrometre, and each
 * chord's disc-swept band (a capsule, convex) meets a row of cells in one run, so the grid is
 * filled row by row in time proportional to the chords times the rows they span. Units mm.
 */
public final class Coverage {

    /** Sagitta of the chords that stand for arcs (mm). */
    static final double CHORD_MM = 5e-4;

    /** Most cells of a grid: finer cells than this leave the grid coarser, never the check slower. */
    static final int MAX_CELLS = 4_000_000;

    /** A reachable point within this of the wall's own offset (mm) is the finishing pass's, not a sliver. */
    static final double REACH_MARGIN_MM = 0.01;

    private final double x0;
    private final double y0;
    private final double cellMm;
    private final int nx;
    private final int ny;
    private final BitSet inside;
    private final BitSet reach;
    private final BitSet cut;
    private final List<Vec2[]> faceChords;
    private final double radiusMm;

    private Coverage(
            Box2 box,
            double cellMm,
            List<Contour> faces,
            List<List<Curve2>> passes,
            double passesRadiusMm,
            double radiusMm) {
        this.cellMm = cellMm;
        this.x0 = box.minX();
        this.y0 = box.minY();
        this.nx = Math.max(1, (int) Math.ceil(box.width() / cellMm));
        this.ny = Math.max(1, (int) Math.ceil(box.height() / cellMm));
        this.inside = new BitSet(nx * ny);
        this.reach = new BitSet(nx * ny);
        this.cut = new BitSet(nx * ny);
        this.faceChords = new ArrayList<>();
        this.radiusMm = radiusMm;
        for (Contour c : faces) {
            faceChords.addAll(chords(c.curves()));
        }
        fillInside();
        for (Vec2[] s : faceChords) {
            capsule(reach, s[0], s[1], radiusMm - REACH_MARGIN_MM);
        }
        reach.or(inside);
        for (List<Curve2> pass : passes) {
            for (Vec2[] s : chords(pass)) {
                capsule(cut, s[0], s[1], passesRadiusMm);
            }
        }
    }

    private Coverage(Coverage c) {
        this.x0 = c.x0;
        this.y0 = c.y0;
        this.cellMm = c.cellMm;
        this.nx = c.nx;
        this.ny = c.ny;
        this.inside = c.inside;
        this.reach = c.reach;
        this.cut = (BitSet) c.cut.clone();
        this.faceChords = c.faceChords;
        this.radiusMm = c.radiusMm;
    }

    /**
     * The coverage of the passes.
     *
     * @param faces the loops of the finishing offset (faces counter-clockwise, holes clockwise): where
     *     the tool's centre may go
     * @param passes the curves the centre follows at the floor
     * @param radiusMm the tool radius
     * @param cellMm the grid's cell (coarser when the pocket would need more than {@link #MAX_CELLS})
     */
    public static Coverage of(List<Contour> faces, List<List<Curve2>> passes, double radiusMm, double cellMm) {
        return of(faces, passes, radiusMm, radiusMm, cellMm);
    }

    /**
     * What a smaller second tool can reach and a first tool's passes leave: the rest material.
     * The reachable cells are the second tool's (within its radius of its own finishing offset),
     * the cut ones those within the first tool's radius of its passes at the floor; what is cut
     * later ({@link #cutAlong}) and the links ({@link #clearedAlong}) are the second tool's.
     *
     * @param faces the second tool's finishing offset (faces counter-clockwise, holes clockwise)
     * @param firstPasses the curves the first tool's centre follows at the floor
     * @param firstRadiusMm the first tool's radius
     * @param radiusMm the second tool's radius
     * @param cellMm the grid's cell, as {@link #of}
     */
    public static Coverage rest(
            List<Contour> faces, List<List<Curve2>> firstPasses, double firstRadiusMm, double radiusMm, double cellMm) {
        return of(faces, firstPasses, firstRadiusMm, radiusMm, cellMm);
    }

    private static Coverage of(
            List<Contour> faces, List<List<Curve2>> passes, double passesRadiusMm, double radiusMm, double cellMm) {
        Box2 box = null;
        for (Contour c : faces) {
            box = box == null ? c.bounds() : box.union(c.bounds());
        }
        if (box == null) {
            throw new IllegalArgumentException("no face to cover");
        }
        box = new Box2(box.minX() - radiusMm, box.minY() - radiusMm, box.maxX() + radiusMm, box.maxY() + radiusMm);
        double h = Math.max(cellMm, Math.sqrt(box.width() * box.height() / MAX_CELLS));
        return new Coverage(box, h, faces, passes, passesRadiusMm, radiusMm);
    }

    /** A copy whose cut cells may grow apart from this one's (the grid and the faces shared). */
    Coverage copy() {
        return new Coverage(this);
    }

    /** Whether the tool's disc along the segment ab meets a cell it can reach that is not cut. */
    boolean meetsUncut(Vec2 a, Vec2 b) {
        boolean[] met = {false};
        runs(a, b, radiusMm, (from, to) -> {
            for (int k = reach.nextSetBit(from); k >= 0 && k < to && !met[0]; k = reach.nextSetBit(k + 1)) {
                met[0] = !cut.get(k);
            }
        });
        return met[0];
    }

    /** The reachable cells no pass has cut, as a set of cell indices. */
    BitSet uncutCells() {
        BitSet u = (BitSet) reach.clone();
        u.andNot(cut);
        return u;
    }

    /** The centre of a cell by its index. */
    Vec2 cellCentre(int index) {
        return centre(index % nx, index / nx);
    }

    /** The cells [from, to) of one row. */
    @FunctionalInterface
    private interface Run {
        void cells(int from, int to);
    }

    /** The side of a cell (mm). */
    public double cellMm() {
        return cellMm;
    }

    /** The centres of the cells the tool can reach and no pass cuts. */
    public List<Vec2> uncut() {
        BitSet u = (BitSet) reach.clone();
        u.andNot(cut);
        List<Vec2> out = new ArrayList<>();
        for (int i = u.nextSetBit(0); i >= 0; i = u.nextSetBit(i + 1)) {
            out.add(centre(i % nx, i / nx));
        }
        return out;
    }

    /** The uncut area (mm2): cells times their area. */
    public double uncutAreaMm2() {
        BitSet u = (BitSet) reach.clone();
        u.andNot(cut);
        return u.cardinality() * cellMm * cellMm;
    }

    /** Adds what the tool cuts along the curves (its centre's path at the floor) to the cut cells. */
    void cutAlong(List<Curve2> pass) {
        for (Vec2[] s : chords(pass)) {
            capsule(cut, s[0], s[1], radiusMm);
        }
    }

    /**
     * Whether the tool may feed straight from a to b inside material already cut: its centre stays
     * inside the faces and every cell its disc sweeps is cut, or is cut by the pass that starts at b
     * (the disc taken two cells smaller, for the grid's own edge).
     */
    boolean clearedAlong(Vec2 a, Vec2 b, List<Curve2> next) {
        BitSet need = new BitSet();
        capsule(need, a, b, radiusMm - 2 * cellMm);
        need.andNot(cut);
        if (!need.isEmpty()) {
            BitSet ahead = new BitSet();
            for (Vec2[] s : chords(next)) {
                capsule(ahead, s[0], s[1], radiusMm);
            }
            need.andNot(ahead);
        }
        return need.isEmpty() && staysInside(a, b);
    }

    /** Whether every cell the tool can reach within r of c is cut. */
    boolean clearedDisc(Vec2 c, double r) {
        BitSet need = new BitSet();
        capsule(need, c, c, r);
        need.and(reach);
        need.andNot(cut);
        return need.isEmpty();
    }

    /** Whether the point lies inside the region the centre may go (by the chords of its faces). */
    boolean insideFaces(Vec2 p) {
        int w = 0;
        for (Vec2[] s : faceChords) {
            Vec2 a = s[0];
            Vec2 b = s[1];
            if (a.y() <= p.y() && b.y() > p.y() && b.minus(a).cross(p.minus(a)) > 0) {
                w++;
            } else if (a.y() > p.y() && b.y() <= p.y() && b.minus(a).cross(p.minus(a)) < 0) {
                w--;
            }
        }
        return w != 0;
    }

    /** The point of the faces' boundary nearest p. */
    Vec2 nearestOnFaces(Vec2 p) {
        Vec2 best = p;
        double bestD = Double.POSITIVE_INFINITY;
        for (Vec2[] s : faceChords) {
            Vec2 q = nearestOnSegment(s[0], s[1], p);
            double d = q.distance(p);
            if (d < bestD) {
                bestD = d;
                best = q;
            }
        }
        return best;
    }

    /**
     * Whether the straight move from a to b keeps the centre inside the faces: it crosses none of
     * their chords away from its ends, and its middle is inside.
     */
    boolean staysInside(Vec2 a, Vec2 b) {
        if (!insideFaces(a.interpolate(b, 0.5))) {
            return false;
        }
        Vec2 d = b.minus(a);
        double len = d.norm();
        if (len < 1e-9) {
            return true;
        }
        for (Vec2[] s : faceChords) {
            Vec2 e = s[1].minus(s[0]);
            double den = d.cross(e);
            if (Math.abs(den) < 1e-15) {
                continue;
            }
            Vec2 w = s[0].minus(a);
            double t = w.cross(e) / den;
            double u = w.cross(d) / den;
            if (t * len > 1e-6 && (1 - t) * len > 1e-6 && u >= -1e-12 && u <= 1 + 1e-12) {
                return false;
            }
        }
        return true;
    }

    static Vec2 nearestOnSegment(Vec2 a, Vec2 b, Vec2 p) {
        Vec2 d = b.minus(a);
        double dd = d.dot(d);
        double t = dd < 1e-24 ? 0 : Math.max(0, Math.min(1, p.minus(a).dot(d) / dd));
        return a.plus(d.times(t));
    }

    private Vec2 centre(int i, int j) {
        return new Vec2(x0 + (i + 0.5) * cellMm, y0 + (j + 0.5) * cellMm);
    }

    /** Scanline: cells whose centre has a non-zero winding number about the faces' chords. */
    private void fillInside() {
        for (int j = 0; j < ny; j++) {
            double y = y0 + (j + 0.5) * cellMm;
            List<double[]> xs = new ArrayList<>();
            for (Vec2[] s : faceChords) {
                Vec2 a = s[0];
                Vec2 b = s[1];
                if ((a.y() <= y) != (b.y() <= y)) {
                    double x = a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
                    xs.add(new double[] {x, b.y() > a.y() ? 1 : -1});
                }
            }
            xs.sort((p, q) -> Double.compare(p[0], q[0]));
            int w = 0;
            for (int k = 0; k + 1 < xs.size(); k++) {
                w += (int) xs.get(k)[1];
                if (w != 0) {
                    setRun(inside, j, xs.get(k)[0], xs.get(k + 1)[0]);
                }
            }
        }
    }

    /** Marks the cells whose centre lies within r of the segment ab. */
    private void capsule(BitSet bits, Vec2 a, Vec2 b, double r) {
        runs(a, b, r, bits::set);
    }

    /** The runs of cells, row by row, whose centre lies within r of the segment ab. */
    private void runs(Vec2 a, Vec2 b, double r, Run out) {
        if (!(r > 0)) {
            return;
        }
        int j0 = Math.max(0, (int) Math.floor((Math.min(a.y(), b.y()) - r - y0) / cellMm - 0.5));
        int j1 = Math.min(ny - 1, (int) Math.ceil((Math.max(a.y(), b.y()) + r - y0) / cellMm - 0.5));
        Vec2 d = b.minus(a);
        double len = d.norm();
        for (int j = j0; j <= j1; j++) {
            double y = y0 + (j + 0.5) * cellMm;
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (Vec2 c : new Vec2[] {a, b}) {
                double dy = y - c.y();
                if (Math.abs(dy) <= r) {
                    double dx = Math.sqrt(r * r - dy * dy);
                    lo = Math.min(lo, c.x() - dx);
                    hi = Math.max(hi, c.x() + dx);
                }
            }
            if (len > 1e-12 && Math.abs(d.y()) > 1e-12) {
                // the band of the segment between the perpendiculars at its ends: a parallelogram row
                Vec2 n = new Vec2(-d.y() / len, d.x() / len);
                for (int side = -1; side <= 1; side += 2) {
                    Vec2 a2 = a.plus(n.times(side * r));
                    Vec2 b2 = b.plus(n.times(side * r));
                    if ((a2.y() <= y) != (b2.y() <= y) || Math.abs(a2.y() - y) < 1e-15) {
                        double x = Math.abs(b2.y() - a2.y()) < 1e-15
                                ? a2.x()
                                : a2.x() + (y - a2.y()) / (b2.y() - a2.y()) * (b2.x() - a2.x());
                        lo = Math.min(lo, x);
                        hi = Math.max(hi, x);
                    }
                }
                // the ends' perpendiculars bound the band too; a row between the offset lines inside them
                for (Vec2 c : new Vec2[] {a, b}) {
                    Vec2 p1 = c.plus(n.times(r));
                    Vec2 p2 = c.minus(n.times(r));
                    if ((p1.y() <= y) != (p2.y() <= y)) {
                        double x = p1.x() + (y - p1.y()) / (p2.y() - p1.y()) * (p2.x() - p1.x());
                        lo = Math.min(lo, x);
                        hi = Math.max(hi, x);
                    }
                }
            } else if (len > 1e-12 && Math.abs(y - a.y()) <= r) {
                lo = Math.min(lo, Math.min(a.x(), b.x()));
                hi = Math.max(hi, Math.max(a.x(), b.x()));
            }
            if (lo <= hi) {
                int i0 = Math.max(0, (int) Math.ceil((lo - x0) / cellMm - 0.5));
                int i1 = Math.min(nx - 1, (int) Math.floor((hi - x0) / cellMm - 0.5));
                if (i0 <= i1) {
                    out.cells(j * nx + i0, j * nx + i1 + 1);
                }
            }
        }
    }

    /** Sets the cells of row j whose centre x lies in [lo, hi]. */
    private void setRun(BitSet bits, int j, double lo, double hi) {
        int i0 = Math.max(0, (int) Math.ceil((lo - x0) / cellMm - 0.5));
        int i1 = Math.min(nx - 1, (int) Math.floor((hi - x0) / cellMm - 0.5));
        if (i0 <= i1) {
            bits.set(j * nx + i0, j * nx + i1 + 1);
        }
    }

    /** The curves as chords: lines as they are, arcs cut so that no chord strays more than {@link #CHORD_MM}. */
    static List<Vec2[]> chords(List<Curve2> curves) {
        List<Vec2[]> out = new ArrayList<>();
        for (Curve2 c : curves) {
            if (c instanceof Arc2 a && a.radius() > CHORD_MM) {
                double sweep = Math.abs(a.sweepRad());
                if (a.isFullCircle() || sweep < 1e-12) {
                    sweep = 2 * Math.PI;
                }
                double step = 2 * Math.acos(1 - CHORD_MM / a.radius());
                int n = Math.max(1, (int) Math.ceil(sweep / step));
                double sign = a.ccw() ? 1 : -1;
                double a0 = a.startAngleRad();
                Vec2 prev = a.start();
                for (int k = 1; k <= n; k++) {
                    Vec2 q = k == n
                            ? a.end()
                            : a.center()
                                    .plus(new Vec2(
                                                    Math.cos(a0 + sign * sweep * k / n),
                                                    Math.sin(a0 + sign * sweep * k / n))
                                            .times(a.radius()));
                    out.add(new Vec2[] {prev, q});
                    prev = q;
                }
            } else {
                out.add(new Vec2[] {c.start(), c.end()});
            }
        }
        return out;
    }
}
