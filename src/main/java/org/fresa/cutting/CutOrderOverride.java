package org.fresa.cutting;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Vec2;

/**
 * The planner's own cut order and start points, laid over the automatic ones: the contours named
 * here are cut first, in this order, each started where it says; the contours it does not name
 * follow in the automatic order, except that a contour inside a named one (a hole of a named
 * part) is cut just before it.
 *
 * <p>A contour is named by a point on its drawn outline ({@code atMm}, within {@link #MATCH_MM}),
 * so the override survives a change of the labels or of the automatic order; the label
 * ({@code contour}) is kept for the planner's eyes and to tell apart the loops of one hole cut
 * as several (a waist narrower than the kerf). A point on no contour is warned about and ignored.
 *
 * <p>An order that cuts a part before one of its holes, or a hole before a part inside it, is
 * refused ({@link Refused}, naming both contours), not repaired: the planner asked for that
 * order, and a silent repair would cut something else than what the tab showed.
 *
 * @param cuts the contours in the order wanted
 */
public record CutOrderOverride(List<Cut> cuts) {

    /** No override: the automatic order and start points. */
    public static final CutOrderOverride NONE = new CutOrderOverride(List.of());
    /** How far (mm) a contour's reference point may be from its drawn outline and still name it. */
    public static final double MATCH_MM = 0.05;

    /**
     * One contour of the override.
     *
     * @param contour its label when the override was made, e.g. "part 2 hole 1"
     * @param atMm a point on its drawn outline
     * @param startMm where its cut should start (projected onto the tool path), or empty for the
     *     automatic start
     */
    public record Cut(String contour, Vec2 atMm, Optional<Vec2> startMm) {
        public Cut {
            Objects.requireNonNull(contour, "contour");
            Objects.requireNonNull(atMm, "atMm");
            Objects.requireNonNull(startMm, "startMm");
            if (!Double.isFinite(atMm.x() + atMm.y())
                    || startMm.map(s -> !Double.isFinite(s.x() + s.y())).orElse(false)) {
                throw new IllegalArgumentException("a cut's reference and start points must be finite");
            }
        }

        /** The same contour started at p (empty: the automatic start). */
        public Cut withStart(Optional<Vec2> p) {
            return new Cut(contour, atMm, p);
        }

        /** "part 2 hole 1 at (12.500, 3.000)": for messages. */
        String named() {
            return String.format(Locale.ROOT, "%s at (%.3f, %.3f)", contour, atMm.x(), atMm.y());
        }
    }

    /** An override that would cut a contour before one inside it. */
    public static final class Refused extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        public Refused(String message) {
            super(message);
        }
    }

    public CutOrderOverride {
        cuts = List.copyOf(cuts);
    }

    public boolean isEmpty() {
        return cuts.isEmpty();
    }

    /** The override with cut {@code from} moved to place {@code to} (both 0-based), the others in order. */
    public CutOrderOverride moved(int from, int to) {
        List<Cut> l = new ArrayList<>(cuts);
        Cut c = l.remove(from);
        l.add(to, c);
        return new CutOrderOverride(l);
    }

    /** The override with cut {@code i} started at p (empty: the automatic start). */
    public CutOrderOverride withStart(int i, Optional<Vec2> p) {
        List<Cut> l = new ArrayList<>(cuts);
        l.set(i, l.get(i).withStart(p));
        return new CutOrderOverride(l);
    }

    /**
     * The override that keeps a plan's order: every cut in its place, each started automatically.
     * Each contour is named by the first point of its drawn outline.
     */
    public static CutOrderOverride of(List<CutPath> order) {
        List<Cut> l = new ArrayList<>();
        for (CutPath c : order) {
            l.add(new Cut(c.label(), c.part().get(0).start(), Optional.empty()));
        }
        return new CutOrderOverride(l);
    }
}
