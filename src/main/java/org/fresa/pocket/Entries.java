package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.EnclosingCircle;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Chooses the entry of one cut (a {@link Entry}): a helix where the room beside the cut's start
 * holds one, else a zig-zag ramp along the cut, a plunge only for a centre-cutting tool (asked
 * for, or with room for neither). Units mm and degrees; Z up.
 *
 * <p>The helix: radius the tool radius, else three quarters or half of it (a smaller helix would
 * leave a core wider than the tool radius under a cutter that does not cut at its centre); its
 * sense is the cut's, and its axis lies first beside the cut's start so that the helix runs into
 * the cut tangentially, then in seven other directions, then nearer the start (half the radius
 * away, then at the start itself: the tool then joins the helix's circle level at the top and
 * comes back to the start at depth). The ramp: legs of
 * {@code H / n} along the cut, H = depth / tan(angle), n the smallest even number for which a
 * leg is no longer than the cut.
 */
public final class Entries {

    /** Most legs of a ramp or turns of a helix one entry may have: more is no usable entry. */
    public static final int MAX_STEPS = 10_000;

    /** The shortest cut a ramp may run along (mm). */
    static final double MIN_LEG_MM = 1e-3;

    private static final double[] HELIX_RADII = {1, 0.75, 0.5};

    /**
     * The uncut core of a cutter that does not cut at its centre, as a fraction of its radius: the
     * helix entries' least radius is the same figure.
     */
    public static final double CORE_OF_RADIUS = 0.5;

    /** Directions a straight zig-zag down may take (the first along +X, then round counter-clockwise). */
    private static final int ZIGZAG_DIRECTIONS = 16;

    private Entries() {}

    /** Whether a circle of tool-centre positions lies where the tool may cut (inside the region to clear). */
    @FunctionalInterface
    public interface Room {
        /**
         * @param centre the circle's centre (mm)
         * @param radiusMm the radius of the tool centre's circle (mm)
         */
        boolean holds(Vec2 centre, double radiusMm);

        /** No room for a helix anywhere. */
        Room NONE = (c, r) -> false;
    }

    /** Whether the straight course of the tool centre from a to b stays where the tool may cut. */
    @FunctionalInterface
    public interface Course {
        boolean holds(Vec2 a, Vec2 b);
    }

    /**
     * Whether a ramp along this course moves the tool's centre far enough for a cutter that does
     * not cut at its centre: a point within half the tool radius of every centre position stays
     * under the uncut core all the way down, as under a helix narrower than half the radius
     * (which the entries refuse). A course round a loop a few tenths of a millimetre across, or
     * forth and back along a cut shorter than the tool radius, is a plunge in all but name.
     */
    public static boolean movesTheCentre(List<Curve2> course, double toolRadiusMm) {
        List<Vec2> points = new ArrayList<>();
        // the course repeats its loop round by round: the first rounds hold every point of it
        for (Curve2 c : course.subList(0, Math.min(course.size(), 512))) {
            for (int k = 0; k < 8; k++) {
                points.add(c.pointAt(k / 8.0));
            }
            points.add(c.end());
        }
        return EnclosingCircle.radiusMm(points) >= CORE_OF_RADIUS * toolRadiusMm - 1e-9;
    }

    /**
     * The course down to a loop's start for the region engine: its ramp round the loop where that
     * moves the centre ({@link #movesTheCentre}) or the tool cuts at its centre, else a straight
     * zig-zag of one tool radius ending at the start ({@link #zigzagLeg}), as many rounds as the
     * angle needs (1 % more, so that Z rounded to the micrometre is never steeper).
     *
     * @param rule what is allowed
     * @param course the ramp round the loop, ending at its start
     * @param start the loop's start (mm)
     * @param inside where the tool centre may run straight
     * @param toolRadiusMm the cutter's radius
     * @param descentMm how far the entry goes down
     * @throws ToolTooLargeException where no zig-zag fits (only a tool that cuts at its centre could go down)
     */
    static List<Curve2> keepingTheCoreMoving(
            EntryRule rule, List<Curve2> course, Vec2 start, Course inside, double toolRadiusMm, double descentMm)
            throws ToolTooLargeException {
        if (rule.centreCutting() || movesTheCentre(course, toolRadiusMm)) {
            return course;
        }
        Optional<Segment2> leg = zigzagLeg(start, inside, toolRadiusMm);
        double want = 1.01 * descentMm / Math.tan(Math.toRadians(rule.angleDeg()));
        double lengthMm = zigzagLengthMm(toolRadiusMm);
        int rounds = Math.max(1, (int) Math.ceil(want / (2 * lengthMm) - 1e-9));
        if (leg.isEmpty() || rounds > MAX_STEPS) {
            throw tooSmallToGoDown(start);
        }
        List<Curve2> out = new ArrayList<>();
        for (int j = 0; j < rounds; j++) {
            out.add(leg.get());
            out.add(leg.get().reversed());
        }
        return out;
    }

    /**
     * A straight leg of one tool radius from the start (its enclosing circle half the radius, a
     * thousandth more), in the first of sixteen directions whose course stays inside, or none.
     */
    static Optional<Segment2> zigzagLeg(Vec2 start, Course inside, double toolRadiusMm) {
        double lengthMm = zigzagLengthMm(toolRadiusMm);
        for (int k = 0; k < ZIGZAG_DIRECTIONS; k++) {
            double a = k * 2 * Math.PI / ZIGZAG_DIRECTIONS;
            Vec2 e = start.plus(new Vec2(Math.cos(a), Math.sin(a)).times(lengthMm));
            if (inside.holds(start, e)) {
                return Optional.of(new Segment2(start, e));
            }
        }
        return Optional.empty();
    }

    private static double zigzagLengthMm(double toolRadiusMm) {
        return 2 * CORE_OF_RADIUS * toolRadiusMm * 1.001;
    }

    /** The refusal where a cutter that does not cut at its centre has no way down, naming the place. */
    static ToolTooLargeException tooSmallToGoDown(Vec2 at) {
        return new ToolTooLargeException(String.format(
                java.util.Locale.ROOT,
                "the area about X%.3f Y%.3f is too small to go down into with a cutter that does not cut at its centre"
                        + " (no helix or ramp there moves its centre by half its radius): a centre-cutting tool"
                        + " (--centre-cutting) may go down there, or use a smaller tool",
                at.x(),
                at.y()));
    }

    /**
     * The entry of a cut.
     *
     * @param rule what is allowed
     * @param start where the cut starts (mm)
     * @param cut the cut's path from its start (lines and arcs chained, may be empty); the ramp runs along it
     * @param ccw the cut's sense (a helix turns the same way)
     * @param room where a helix may lie
     * @param toolRadiusMm the cutter's radius
     * @param depthMm how far the entry goes down (mm, >= 0)
     * @return the entry, or empty when the rule allows none here (no room for a helix or a ramp
     *     and a tool that does not cut at its centre)
     */
    public static Optional<Entry> choose(
            EntryRule rule, Vec2 start, List<Curve2> cut, boolean ccw, Room room, double toolRadiusMm, double depthMm) {
        if (rule.kind() == EntryRule.Kind.PLUNGE) {
            return Optional.of(new Entry.Plunge(start));
        }
        double horizontal = depthMm / Math.tan(Math.toRadians(rule.angleDeg()));
        if (rule.angleDeg() >= 90 || !(horizontal > 1e-9)) {
            // a vertical entry is what the rule allows (90 deg), or there is no depth to go down
            return Optional.of(new Entry.Plunge(start));
        }
        Optional<Entry> helix = rule.kind() == EntryRule.Kind.RAMP
                ? Optional.empty()
                : helix(start, cut, ccw, room, toolRadiusMm, rule.angleDeg(), depthMm);
        if (helix.isPresent()) {
            return helix;
        }
        Optional<Entry> ramp = ramp(cut, horizontal);
        if (ramp.isPresent()) {
            return ramp;
        }
        if (rule.kind() == EntryRule.Kind.RAMP) {
            helix = helix(start, cut, ccw, room, toolRadiusMm, rule.angleDeg(), depthMm);
            if (helix.isPresent()) {
                return helix;
            }
        }
        return rule.centreCutting() ? Optional.of(new Entry.Plunge(start)) : Optional.empty();
    }

    private static Optional<Entry> helix(
            Vec2 start,
            List<Curve2> cut,
            boolean ccw,
            Room room,
            double toolRadiusMm,
            double angleDeg,
            double depthMm) {
        Vec2 t = tangent(cut);
        Vec2 side = ccw ? t.leftNormal() : t.leftNormal().negated();
        List<Vec2> directions = new ArrayList<>();
        directions.add(side);
        for (int k = 1; k < 8; k++) {
            directions.add(side.rotated(k * Math.PI / 4));
        }
        // through the start first (the helix runs into the cut), then about points nearer the start
        for (double near : new double[] {1, 0.5, 0}) {
            for (double f : HELIX_RADII) {
                double r = f * toolRadiusMm;
                for (Vec2 d : near == 0 ? List.of(side) : directions) {
                    Vec2 c = start.plus(d.times(r * near));
                    if (room.holds(c, r)) {
                        Entry.Helix h = new Entry.Helix(start, c, r, ccw, angleDeg);
                        if (h.turns(depthMm) <= MAX_STEPS) {
                            return Optional.of(h);
                        }
                    }
                }
            }
        }
        return Optional.empty();
    }

    private static Vec2 tangent(List<Curve2> cut) {
        for (Curve2 c : cut) {
            if (c.length() > 1e-9) {
                try {
                    return c.startTangent().normalized();
                } catch (IllegalArgumentException e) {
                    // a zero-radius corner arc has no tangent: the next element gives it
                }
            }
        }
        return Vec2.UNIT_X;
    }

    /** Legs along the first H/n of the cut, n even and as small as the cut's length allows. */
    private static Optional<Entry> ramp(List<Curve2> cut, double horizontalMm) {
        double length = cut.stream().mapToDouble(Curve2::length).sum();
        if (!(length >= MIN_LEG_MM)) {
            return Optional.empty();
        }
        double n = 2 * Math.ceil(horizontalMm / (2 * length) - 1e-12);
        int legs = (int) Math.max(2, n);
        if (!(n <= MAX_STEPS)) {
            return Optional.empty();
        }
        double leg = Math.min(length, horizontalMm / legs);
        if (!(leg >= MIN_LEG_MM / 10)) {
            return Optional.empty();
        }
        List<Curve2> path = prefix(cut, leg);
        if ((long) legs * path.size() > MAX_STEPS) {
            return Optional.empty();
        }
        return Optional.of(new Entry.Ramp(path, legs));
    }

    /** The first {@code len} mm of a chain of curves. */
    static List<Curve2> prefix(List<Curve2> cut, double len) {
        List<Curve2> out = new ArrayList<>();
        double left = len;
        for (Curve2 c : cut) {
            double l = c.length();
            if (l <= 0) {
                continue;
            }
            if (l >= left - 1e-12) {
                if (left >= l) {
                    out.add(c);
                } else if (c instanceof Arc2 a) {
                    out.add(new Arc2(a.center(), a.start(), a.pointAt(left / l), a.ccw()));
                } else {
                    out.add(new Segment2(c.start(), c.pointAt(left / l)));
                }
                return out;
            }
            out.add(c);
            left -= l;
        }
        return out;
    }
}
