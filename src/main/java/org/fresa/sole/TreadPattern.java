package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * How a block of figures is repeated (the thesis's {@code INDEX/COPY}): explicit copies, each a
 * similarity of the block (translate, rotate, mirror), or a fill of a region.
 */
public sealed interface TreadPattern {

    /**
     * Explicit copies in cutting order; the identity is the block as defined.
     *
     * @param copies at least one
     */
    record Copies(List<Similarity2> copies) implements TreadPattern {
        public Copies {
            copies = List.copyOf(copies);
            if (copies.isEmpty()) {
                throw new IllegalArgumentException("a pattern has at least one copy");
            }
        }
    }

    /**
     * Copies on a grid of pitch (dx, dy) over the region's bounding box, every other row shifted
     * by rowShiftMm (bricks, honeycomb-like staggering), keeping those whose anchor (the block's
     * bounding-box centre moved by the copy) lies inside the region. Rows run alternately left
     * to right and back, to shorten the rapids.
     */
    record Fill(Contour region, double dxMm, double dyMm, double rowShiftMm) implements TreadPattern {
        public Fill {
            if (!(dxMm > 0) || !(dyMm > 0)) {
                throw new IllegalArgumentException("fill pitches must be > 0");
            }
        }
    }

    static TreadPattern single() {
        return new Copies(List.of(Similarity2.IDENTITY));
    }

    /** count copies, each shifted by (dx, dy) from the previous (thesis: COPY/n,TRANSL,dx,dy,0,count-1). */
    static TreadPattern linear(double dxMm, double dyMm, int count) {
        List<Similarity2> l = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            l.add(Similarity2.translation(i * dxMm, i * dyMm));
        }
        return new Copies(l);
    }

    /** count copies rotated by stepDeg each about the centre. */
    static TreadPattern polar(Vec2 center, double stepDeg, int count) {
        List<Similarity2> l = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            l.add(Similarity2.rotation(center, i * stepDeg));
        }
        return new Copies(l);
    }

    /** cols x rows copies at pitch (dx, dy), odd rows shifted by rowShiftMm, rows boustrophedon. */
    static TreadPattern grid(double dxMm, double dyMm, int cols, int rows, double rowShiftMm) {
        List<Similarity2> l = new ArrayList<>();
        for (int r = 0; r < rows; r++) {
            for (int k = 0; k < cols; k++) {
                int c = r % 2 == 0 ? k : cols - 1 - k;
                l.add(Similarity2.translation(c * dxMm + (r % 2) * rowShiftMm, r * dyMm));
            }
        }
        return new Copies(l);
    }

    /** The copies for a block whose anchor is given. */
    default List<Similarity2> copies(Vec2 anchor, Tolerance tol) {
        if (this instanceof Copies c) {
            return c.copies();
        }
        Fill f = (Fill) this;
        org.fresa.geom.Box2 b = f.region().bounds();
        List<Similarity2> l = new ArrayList<>();
        int row = 0;
        for (double y = b.minY(); y <= b.maxY() + f.dyMm(); y += f.dyMm(), row++) {
            List<Similarity2> rowCopies = new ArrayList<>();
            double shift = (row % 2) * f.rowShiftMm();
            // grid aligned on the anchor so that a copy sits on the block as defined
            double kx0 = Math.floor((b.minX() - anchor.x() - shift) / f.dxMm()) - 1;
            double ky = Math.floor((y - anchor.y()) / f.dyMm());
            for (double kx = kx0; anchor.x() + shift + kx * f.dxMm() <= b.maxX() + f.dxMm(); kx++) {
                Vec2 d = Vec2.of(kx * f.dxMm() + shift, ky * f.dyMm());
                if (f.region().contains(anchor.plus(d), tol)) {
                    rowCopies.add(Similarity2.translation(d));
                }
            }
            if (row % 2 == 1) {
                java.util.Collections.reverse(rowCopies);
            }
            l.addAll(rowCopies);
        }
        return l;
    }
}
