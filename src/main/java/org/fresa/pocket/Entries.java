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
 * leg is no longer than the cut; for a cutter that does not cut at its centre, legs that move its
 * centre by half its radius ({@link #movesTheCentre}), run on along the path followed at depth
 * where the cut is shorter, else a straight zig-zag of one radius, else none. The region engine
 * takes the same rule ({@link #keepingTheCoreMoving}).
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
        return movesTheCentreOver(points, toolRadiusMm);
    }

    /**
     * {@link #movesTheCentre} for the tool centre's positions along a descent: their smallest
     * enclosing circle is at least {@link #CORE_OF_RADIUS} of the tool radius.
     */
    public static boolean movesTheCentreOver(List<Vec2> centres, double toolRadiusMm) {
        return EnclosingCircle.radiusMm(centres) >= CORE_OF_RADIUS * toolRadiusMm - 1e-9;
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
    public static ToolTooLargeException tooSmallToGoDown(Vec2 at) {
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
        return choose(rule, start, cut, List.of(), ccw, room, room, toolRadiusMm, depthMm);
    }

    /**
     * The entry of a cut that the tool follows at depth by more path: for a cutter that does not
     * cut at its centre, a ramp whose legs along the cut alone would not move the centre by half
     * the radius ({@link #movesTheCentre}) runs its legs on along that path until they do, else
     * zig-zags along a straight leg of one radius inside the room ({@link #zigzagLeg}); where
     * neither fits there is no entry.
     *
     * @param onwards the path the tool follows at depth after the cut (the passes joined to it
     *     at depth with their links, may be empty), so that the cut and it are one chain
     * @param room where a helix may lie
     * @param legRoom where a straight zig-zag's leg may run (the region the cuts clear; a post
     *     that writes no helix still has room for a leg)
     * @see #choose(EntryRule, Vec2, List, boolean, Room, double, double)
     */
    public static Optional<Entry> choose(
            EntryRule rule,
            Vec2 start,
            List<Curve2> cut,
            List<Curve2> onwards,
            boolean ccw,
            Room room,
            Room legRoom,
            double toolRadiusMm,
            double depthMm) {
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
        Optional<Entry> ramp = rule.centreCutting()
                ? ramp(cut, horizontal)
                : rampMovingTheCentre(start, cut, onwards, legRoom, toolRadiusMm, horizontal);
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

    /**
     * A ramp for a cutter that does not cut at its centre: the legs along the cut where they move
     * the centre by half the radius, else run on along the cut and the path onwards just far
     * enough that they do (a thousandth more, for the program's rounding), else a zig-zag of one
     * radius inside the room.
     */
    private static Optional<Entry> rampMovingTheCentre(
            Vec2 start, List<Curve2> cut, List<Curve2> onwards, Room room, double toolRadiusMm, double horizontalMm) {
        Optional<Entry> along = ramp(cut, horizontalMm);
        double legMm = 0;
        if (along.isPresent() && along.get() instanceof Entry.Ramp r) {
            if (movesTheCentre(r.leg(), toolRadiusMm)) {
                return along;
            }
            legMm = r.legLengthMm();
        }
        List<Curve2> path = new ArrayList<>(cut);
        path.addAll(onwards);
        double need = shortestMovingTheCentre(path, toolRadiusMm * ROUNDING_MARGIN);
        if (need >= 0) {
            Optional<Entry> longer = legs(prefix(path, Math.max(legMm, need)), horizontalMm);
            if (longer.isPresent()) {
                return longer;
            }
        }
        return zigzagLeg(start, straight(room), toolRadiusMm).flatMap(leg -> legs(List.of(leg), horizontalMm));
    }

    /** A thousandth more than half the radius: rounding the program's coordinates never makes it less. */
    private static final double ROUNDING_MARGIN = 1.001;

    /**
     * The length of the shortest start of the path along which the centre moves by half the
     * radius ({@link #movesTheCentre}), or -1 when the whole path does not.
     */
    private static double shortestMovingTheCentre(List<Curve2> path, double toolRadiusMm) {
        double length = path.stream().mapToDouble(Curve2::length).sum();
        if (!(length >= MIN_LEG_MM) || !movesTheCentre(prefix(path, length), toolRadiusMm)) {
            return -1;
        }
        // the enclosing circle only grows along the path
        double lo = 0;
        double hi = length;
        while (hi - lo > 1e-4) {
            double mid = (lo + hi) / 2;
            if (movesTheCentre(prefix(path, mid), toolRadiusMm)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return hi;
    }

    /** Forth and back along the leg, as many legs (an even number) as the angle needs. */
    private static Optional<Entry> legs(List<Curve2> leg, double horizontalMm) {
        double length = leg.stream().mapToDouble(Curve2::length).sum();
        if (leg.isEmpty() || !(length >= MIN_LEG_MM)) {
            return Optional.empty();
        }
        double n = 2 * Math.ceil(horizontalMm / (2 * length) - 1e-12);
        int legs = (int) Math.max(2, n);
        if (!(n <= MAX_STEPS) || (long) legs * leg.size() > MAX_STEPS) {
            return Optional.empty();
        }
        return Optional.of(new Entry.Ramp(leg, legs));
    }

    /**
     * Whether a straight course keeps the tool centre where the room allows: points every 0.05 mm,
     * each farther inside than half the spacing, so that the course between two cannot leave.
     */
    private static Course straight(Room room) {
        return (a, b) -> {
            int n = Math.max(1, (int) Math.ceil(a.distance(b) / 0.05));
            for (int k = 1; k <= n; k++) {
                if (!room.holds(a.plus(b.minus(a).times((double) k / n)), 0.6 * a.distance(b) / n)) {
                    return false;
                }
            }
            return true;
        };
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
