package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;

/**
 * How the tool goes down into material at the start of a cut, from straight above the cut's
 * start at the top of the material to the start at the cut's depth (mm, tool along +Z, heights
 * as Z). Chosen per entry by {@link Entries#choose}.
 *
 * <p>The moves keep arcs as arcs: a helix is one {@link Move.Circular} with full turns, a ramp
 * over an arc of the cut is a helical arc (G2/G3 with Z in the posts).
 */
public sealed interface Entry permits Entry.Helix, Entry.Ramp, Entry.Plunge {

    /** Where the entry ends, at the cut's depth (XY, mm). */
    Vec2 start();

    /**
     * The moves from (start, topZ), where the tool is, down to (start, z).
     *
     * @param topZ the height the entry starts from: the top of the material here (mm)
     * @param z the cut's depth, below topZ (mm)
     * @param feedMmPerMin the entry's feed
     */
    List<Move> moves(double topZ, double z, double feedMmPerMin);

    /**
     * Down a helix of radius {@code radiusMm} about {@code centre}, as many full turns as the angle
     * needs, then one full turn at depth so that the floor inside the helix is flat. The helix
     * begins on its circle nearest the cut's start; when the start is not on the circle, the tool
     * first moves there level at the top of the material and returns at depth, inside the hole the
     * helix has cut (the start lies within the helix radius of its centre).
     *
     * @param start the cut's start (mm)
     * @param centre the helix axis (mm), at most radiusMm from start
     * @param radiusMm the helix radius, > 0
     * @param ccw counter-clockwise seen from +Z
     * @param angleDeg steepest descent allowed (deg)
     */
    record Helix(Vec2 start, Vec2 centre, double radiusMm, boolean ccw, double angleDeg) implements Entry {
        public Helix {
            Objects.requireNonNull(start, "start");
            Objects.requireNonNull(centre, "centre");
            if (!(radiusMm > 0) || !(angleDeg > 0 && angleDeg < 90) || start.distance(centre) > radiusMm * (1 + 1e-9)) {
                throw new IllegalArgumentException("bad helix: radius " + radiusMm + ", angle " + angleDeg + ", start "
                        + start.distance(centre) + " from the centre");
            }
        }

        /** Where the helix begins and ends (XY). */
        public Vec2 onCircle() {
            Vec2 d = start.minus(centre);
            return d.norm() < 1e-9 ? centre.plus(new Vec2(radiusMm, 0)) : centre.plus(d.times(radiusMm / d.norm()));
        }

        /** Full turns down a depth of dz (mm), at least one. */
        public int turns(double dz) {
            double pitch = 2 * Math.PI * radiusMm * Math.tan(Math.toRadians(angleDeg));
            return Math.max(1, (int) Math.ceil(dz / pitch - 1e-9));
        }

        @Override
        public List<Move> moves(double topZ, double z, double feedMmPerMin) {
            if (!(topZ > z)) {
                return List.of();
            }
            int n = turns(topZ - z);
            Vec2 p = onCircle();
            boolean off = p.distance(start) > 1e-9;
            List<Move> out = new ArrayList<>();
            if (off) {
                out.add(new Move.Linear(at(p, topZ), feedMmPerMin));
            }
            out.add(new Move.Circular(at(p, z), at(centre, topZ), Vec3.UNIT_Z, ccw, n - 1, feedMmPerMin));
            out.add(new Move.Circular(at(p, z), at(centre, z), Vec3.UNIT_Z, ccw, 0, feedMmPerMin));
            if (off) {
                out.add(new Move.Linear(at(start, z), feedMmPerMin));
            }
            return out;
        }
    }

    /**
     * Down a zig-zag ramp: along {@code leg} and back, as many times as the angle needs, each
     * leg descending the same height, ending at the start at depth.
     *
     * @param leg the path of one leg from the start (lines and arcs chained), length > 0
     * @param legs number of legs, even, >= 2
     */
    record Ramp(List<Curve2> leg, int legs) implements Entry {
        public Ramp {
            leg = List.copyOf(leg);
            if (leg.isEmpty() || legs < 2 || legs % 2 != 0) {
                throw new IllegalArgumentException("bad ramp: " + leg.size() + " curves, " + legs + " legs");
            }
        }

        @Override
        public Vec2 start() {
            return leg.get(0).start();
        }

        /** Length of one leg (mm). */
        public double legLengthMm() {
            return leg.stream().mapToDouble(Curve2::length).sum();
        }

        @Override
        public List<Move> moves(double topZ, double z, double feedMmPerMin) {
            if (!(topZ > z)) {
                return List.of();
            }
            List<Curve2> back = new ArrayList<>();
            for (int i = leg.size() - 1; i >= 0; i--) {
                back.add(leg.get(i).reversed());
            }
            double total = legs * legLengthMm();
            double done = 0;
            List<Move> out = new ArrayList<>();
            for (int k = 0; k < legs; k++) {
                for (Curve2 c : k % 2 == 0 ? leg : back) {
                    double z0 = topZ - (topZ - z) * done / total;
                    done += c.length();
                    double z1 = k == legs - 1 && c == back.get(back.size() - 1) ? z : topZ - (topZ - z) * done / total;
                    emit(out, c, z0, z1, feedMmPerMin);
                }
            }
            return out;
        }

        private static void emit(List<Move> out, Curve2 c, double z0, double z1, double feed) {
            if (c instanceof Arc2 a && a.radius() > 1e-9 && !a.isFullCircle()) {
                out.add(new Move.Circular(at(a.end(), z1), at(a.center(), z0), Vec3.UNIT_Z, a.ccw(), 0, feed));
            } else if (c instanceof Arc2 a && a.radius() > 1e-9) {
                Vec2 mid = a.pointAt(0.5);
                double zm = (z0 + z1) / 2;
                out.add(new Move.Circular(at(mid, zm), at(a.center(), z0), Vec3.UNIT_Z, a.ccw(), 0, feed));
                out.add(new Move.Circular(at(a.end(), z1), at(a.center(), zm), Vec3.UNIT_Z, a.ccw(), 0, feed));
            } else if (c instanceof Segment2 || c instanceof Arc2) {
                out.add(new Move.Linear(at(c.end(), z1), feed));
            }
        }
    }

    /** Straight down along the tool axis: only for a tool that cuts at its centre. */
    record Plunge(Vec2 start) implements Entry {
        public Plunge {
            Objects.requireNonNull(start, "start");
        }

        @Override
        public List<Move> moves(double topZ, double z, double feedMmPerMin) {
            return topZ > z ? List.of(new Move.Linear(at(start, z), feedMmPerMin)) : List.of();
        }
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }
}
