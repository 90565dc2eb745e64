package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.RegionOffsetter;
import org.fresa.pocket.RegionPocket;
import org.fresa.pocket.ToolTooLargeException;

/**
 * A closed pocket whose floor meets its walls in a fillet (ISO 14649-10 planar_radius r) milled
 * with a cutter whose corner radius e is smaller, as a flat end mill: the cutter's corner cannot
 * follow the fillet, so the pocket is cut in three parts, none of which enters the fillet.
 *
 * <ol>
 *   <li>Above the fillet, from the top down to rho = r - e above the floor (the tool's tip there
 *       puts its corner's centre at the fillet's top): the pocket as drawn.
 *   <li>The floor, from there down: the region inset by rho, cleared by the region engine. The
 *       cutter's flat bottom then reaches the fillet's foot.
 *   <li>The fillet by Z-levels: at height h above the floor the walls are offset by what the fillet
 *       takes there, d(h) = rho - sqrt(rho^2 - (rho - h)^2) (the fillet of radius rho that the
 *       corner's centre must keep out of). The levels are spaced so that the material left
 *       between two of them, measured square to the fillet, is at most {@link #SCALLOP_MM}: the
 *       corner of the staircase between levels at angles a and b on the fillet (from the floor)
 *       lies rho (1 - sqrt(sin^2 a + cos^2 b)) inside it, and the cutter's own corner only cuts
 *       closer. Each level is led in square to a wall from a point the floor pass cleared down to
 *       the floor, and left the same way: the tool goes down only in the air.
 * </ol>
 *
 * <p>Bosses are walls too: the fillet runs round their feet as round the pocket's walls (leaving
 * it where the drawing meant a sharp foot keeps the tool out of the boss, where the opposite
 * would cut into it).
 */
final class FilletedFloor {

    /** The material the Z-levels may leave on the fillet, measured square to it (mm). */
    static final double SCALLOP_MM = 0.01;

    /** Plans the pocket as drawn from its top down to the bottom of the heights given. */
    interface Above {
        ToolpathSection plan(Heights h);
    }

    /** A Z-level: its height above the floor and how far its walls are offset there (mm). */
    record Level(double heightMm, double offsetMm) {}

    private FilletedFloor() {}

    /**
     * The Z-levels round a fillet of radius rho (the fillet less the cutter's corner), top down,
     * strictly between the floor and the fillet's top: the floor pass and the pass above the
     * fillet count as the levels at its ends.
     */
    static List<Level> levels(double rhoMm, double scallopMm) {
        List<Level> up = new ArrayList<>();
        if (rhoMm <= scallopMm) {
            return up;
        }
        double c = Math.pow(1 - scallopMm / rhoMm, 2);
        double a = 0;
        while (true) {
            double rest = c - Math.sin(a) * Math.sin(a);
            if (rest <= 0) {
                break;
            }
            double b = Math.acos(Math.sqrt(rest));
            if (b >= Math.PI / 2 - 1e-12) {
                break;
            }
            up.add(new Level(rhoMm * (1 - Math.cos(b)), rhoMm * (1 - Math.sin(b))));
            a = b;
        }
        List<Level> down = new ArrayList<>(up.size());
        for (int i = up.size() - 1; i >= 0; i--) {
            down.add(up.get(i));
        }
        return down;
    }

    /**
     * @param boundary the pocket's walls and its bosses with the region on their left
     *     ({@link RegionOffsetter#oriented})
     * @param rhoMm the planar radius less the cutter's corner radius, > 0
     * @throws UnsupportedOperationException when the fillet is as high as the pocket, or a level
     *     has no room to be led in from the floor cleared
     */
    static ToolpathSection section(
            String label,
            List<Contour> boundary,
            double rhoMm,
            Heights h,
            Tooling t,
            double stepoverMm,
            double axialMm,
            double sideAllowanceMm,
            double bottomAllowanceMm,
            boolean climb,
            EntryRule entry,
            Tolerance tol,
            Above above) {
        double floor = h.bottomZ() + bottomAllowanceMm;
        double filletTop = filletTopZ(floor, rhoMm, h, tol);
        double r = t.radiusMm();
        double wall = r + sideAllowanceMm;
        ToolpathSection top =
                above.plan(new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), filletTop - bottomAllowanceMm));
        // the floor: the region inset by rho, from the fillet's top down
        List<Contour> band = RegionOffsetter.inward(boundary, rhoMm + sideAllowanceMm, tol);
        if (band.isEmpty()) {
            throw new UnsupportedOperationException(
                    "the pocket is narrower than its floor's fillets: no floor is left" + " between them");
        }
        PocketTechnology tech = t.regionTechnology(stepoverMm, filletTop, floor, axialMm > 0 ? axialMm : rhoMm);
        ToolpathSection floorPass;
        try {
            floorPass = RegionPocket.plan(band, tech, climb, entry, true, false)
                    .toolpath()
                    .sections()
                    .get(0);
        } catch (ToolTooLargeException e) {
            throw new UnsupportedOperationException("the floor between the fillets: " + e.getMessage());
        }
        MoveBuilder b = new MoveBuilder(top.start());
        b.append(top.moves());
        // the region engine traverses just above its own top, here inside the pocket: at the retract height instead
        double engineSafe = filletTop + 5;
        Vec3 s0 = atRetract(floorPass.start(), engineSafe, h);
        b.rapid(new Vec3(s0.x(), s0.y(), b.at().z()));
        b.rapid(s0);
        for (Move m : floorPass.moves()) {
            if (m instanceof Move.Rapid rp) {
                b.rapid(atRetract(rp.end(), engineSafe, h));
            } else {
                b.append(List.of(m));
            }
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        filletLevels(b, boundary, rhoMm, wall, floor, h, t, climb, tol);
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return t.section(label, top.start(), b.moves());
    }

    /**
     * The height of the fillet's top (rho above the floor, which is the floor's height with its
     * allowance).
     *
     * @throws UnsupportedOperationException when the fillet reaches the feature's top
     */
    static double filletTopZ(double floorZ, double rhoMm, Heights h, Tolerance tol) {
        double filletTop = floorZ + rhoMm;
        if (!(filletTop < h.topZ() - tol.linear())) {
            throw new UnsupportedOperationException("the floor's " + ToolpathPlanner.mm(rhoMm)
                    + " mm fillet (less the cutter's corner) is as high as the pocket: only fillets lower than the"
                    + " pocket's walls are milled");
        }
        return filletTop;
    }

    /**
     * The offsets from the walls of a level's passes, inside out: the slab between the wall's
     * offset there (the wall's own offset plus what the fillet takes) and the floor pass's (the
     * wall's plus rho), passes 0.9 of the cutter's radius apart.
     */
    static List<Double> slab(Level level, double wallMm, double rhoMm, double toolRadiusMm) {
        List<Double> offsets = new ArrayList<>();
        double d0 = wallMm + level.offsetMm();
        double deep = wallMm + rhoMm;
        int extra = (int) Math.ceil((rhoMm - level.offsetMm() - toolRadiusMm) / (0.9 * toolRadiusMm) - 1e-9);
        for (int k = Math.max(extra, 0); k >= 0; k--) {
            offsets.add(Math.min(d0 + k * 0.9 * toolRadiusMm, deep));
        }
        return offsets;
    }

    private static Vec3 atRetract(Vec3 p, double engineSafe, Heights h) {
        return Math.abs(p.z() - engineSafe) < 1e-9 ? new Vec3(p.x(), p.y(), Math.max(h.retractZ(), p.z())) : p;
    }

    /** A point on the region's boundary and the direction square to it into the region. */
    private record Anchor(Vec2 foot, Vec2 inward) {
        Vec2 at(double d) {
            return foot.plus(inward.times(d));
        }
    }

    /** A pass of a level: its loop (started at its lead-in) and where it is led in from. */
    private record Pass(int anchor, double z, Contour loop, Vec2 from) {}

    private static void filletLevels(
            MoveBuilder b,
            List<Contour> boundary,
            double rhoMm,
            double wallMm,
            double floor,
            Heights h,
            Tooling t,
            boolean climb,
            Tolerance tol) {
        double deep = wallMm + rhoMm;
        List<Anchor> anchors = new ArrayList<>();
        for (Contour c : boundary) {
            for (Curve2 cu : c.curves()) {
                Vec2 tangent = cu.pointAt(0.5 + 1e-4).minus(cu.pointAt(0.5 - 1e-4));
                if (tangent.norm() < 1e-12) {
                    continue;
                }
                Anchor a = new Anchor(cu.pointAt(0.5), tangent.normalized().leftNormal());
                // led in from a point the floor pass cleared: as deep in the region as it reached
                if (distance(boundary, a.at(deep)) >= deep - 1e-7 && inside(boundary, a.at(deep))) {
                    anchors.add(a);
                }
            }
        }
        List<Pass> passes = new ArrayList<>();
        for (Level level : levels(rhoMm, SCALLOP_MM)) {
            double z = floor + level.heightMm();
            for (double d : slab(level, wallMm, rhoMm, t.radiusMm())) {
                for (Contour loop : RegionOffsetter.inward(boundary, d, tol)) {
                    passes.add(ledIn(loop, anchors, d, z, climb));
                }
            }
        }
        // each anchor's passes top down, so that the tool goes down from one to the next in the air
        passes.sort(java.util.Comparator.comparingInt(Pass::anchor).thenComparing(p -> -p.z()));
        int at = -1;
        for (Pass p : passes) {
            Vec2 from = anchors.get(p.anchor()).at(deep);
            if (p.anchor() != at) {
                b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
                b.rapid(Vec3.of(from, h.retractZ()));
                at = p.anchor();
            }
            // down in the air where the floor pass cleared (no feed down: the cutter enters no
            // material there), then square to the wall into the slab
            b.rapid(Vec3.of(from, p.z()));
            b.feed(Vec3.of(p.loop().get(0).start(), p.z()), t.feedMmPerMin());
            b.curves(p.loop().curves(), p.z(), t.feedMmPerMin());
            b.feed(Vec3.of(from, p.z()), t.feedMmPerMin());
        }
    }

    private static Pass ledIn(Contour loop, List<Anchor> anchors, double d, double z, boolean climb) {
        for (int i = 0; i < anchors.size(); i++) {
            Vec2 p = anchors.get(i).at(d);
            if (loop.distanceTo(p) < 1e-6) {
                Contour started = startingAt(climb ? loop : loop.reversed(), p);
                return new Pass(i, z, started, p);
            }
        }
        Vec2 s = loop.get(0).start();
        throw new UnsupportedOperationException("the floor's fillet: no room to lead the pass at X"
                + ToolpathPlanner.mm(s.x()) + " Y" + ToolpathPlanner.mm(s.y()) + " in from the floor cleared between"
                + " the fillets");
    }

    /** The loop run from p (on it) round to p. */
    static Contour startingAt(Contour loop, Vec2 p) {
        int k = 0;
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < loop.size(); i++) {
            double dist = loop.get(i).distanceTo(p);
            if (dist < best) {
                best = dist;
                k = i;
            }
        }
        Curve2 c = loop.get(k);
        List<Curve2> out = new ArrayList<>();
        Curve2[] halves = split(c, p);
        if (halves[1] != null) {
            out.add(halves[1]);
        }
        for (int i = 1; i < loop.size(); i++) {
            out.add(loop.get((k + i) % loop.size()));
        }
        if (halves[0] != null) {
            out.add(halves[0]);
        }
        return new Contour(out);
    }

    private static Curve2[] split(Curve2 c, Vec2 p) {
        Curve2 first = null;
        Curve2 second = null;
        if (c instanceof Arc2 a) {
            Vec2 q = a.center().plus(p.minus(a.center()).normalized().times(a.radius()));
            if (a.isFullCircle()) {
                Vec2 opposite = a.center().times(2).minus(q);
                return new Curve2[] {
                    new Arc2(a.center(), opposite, q, a.ccw()), new Arc2(a.center(), q, opposite, a.ccw())
                };
            }
            first = q.distance(a.start()) > 1e-9 ? new Arc2(a.center(), a.start(), q, a.ccw()) : null;
            second = q.distance(a.end()) > 1e-9 ? new Arc2(a.center(), q, a.end(), a.ccw()) : null;
        } else {
            first = p.distance(c.start()) > 1e-9 ? new Segment2(c.start(), p) : null;
            second = p.distance(c.end()) > 1e-9 ? new Segment2(p, c.end()) : null;
        }
        return new Curve2[] {first, second};
    }

    private static double distance(List<Contour> boundary, Vec2 p) {
        double d = Double.POSITIVE_INFINITY;
        for (Contour c : boundary) {
            d = Math.min(d, c.distanceTo(p));
        }
        return d;
    }

    /** Inside the outer loop and outside every island (the islands run clockwise). */
    private static boolean inside(List<Contour> boundary, Vec2 p) {
        int w = 0;
        for (Contour c : boundary) {
            w += c.windingNumber(p);
        }
        return w != 0;
    }
}
