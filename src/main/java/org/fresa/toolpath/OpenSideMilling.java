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
import org.fresa.model.ToolpathSection;

/**
 * Features open to the outside of the stock, milled with the tool coming in from the air at
 * depth rather than ramping into the material: steps (ISO 14649-10 step) and general outside
 * profiles. With the spindle turning clockwise (M3), climb milling keeps the material being cut
 * on the right of the tool's travel.
 */
final class OpenSideMilling {

    /** How far outside the stock the tool goes down and comes back up, beyond its radius (mm). */
    static final double OUTSIDE_MM = 2.0;

    private OpenSideMilling() {
    }

    /**
     * A step in its frame: x along the open boundary from its start (0 to length), the wall at
     * y 0 with the material kept at +y, the step's floor from the wall out to the stock's edge at
     * y = -width, z the feature axis (top 0). Passes run parallel to the wall, the first one at
     * the open side, each a stepover nearer the wall, the last one with the tool touching the
     * wall (less the side allowance); each is entered from the air beyond the open side at its
     * layer's depth. An end of the step where the stock ends lets the tool run past it; a closed
     * end keeps the tool's edge within the path's length.
     *
     * @param climb with M3: passes run along -x (the step's material on the tool's right)
     * @throws UnsupportedOperationException when the tool does not fit between closed ends
     */
    static ToolpathSection step(String label, double lengthMm, double widthMm, boolean openStart, boolean openEnd,
            Heights h, Tooling t, double stepoverMm, double axialMm, double sideAllowanceMm,
            double bottomAllowanceMm, boolean climb, Tolerance tol) {
        double r = t.radiusMm();
        double x0 = openStart ? -(r + OUTSIDE_MM) : r;
        double x1 = openEnd ? lengthMm + r + OUTSIDE_MM : lengthMm - r;
        if (x1 < x0 - tol.linear()) {
            throw new UnsupportedOperationException("the tool (" + ToolpathPlanner.mm(t.diameterMm())
                    + " mm) is longer than the step between its closed ends (" + ToolpathPlanner.mm(lengthMm) + " mm)");
        }
        x1 = Math.max(x1, x0);
        double wallY = -(r + sideAllowanceMm);
        double outY = -(widthMm + r + OUTSIDE_MM);
        // the first pass takes one stepover off the open edge, each next one a stepover nearer the wall
        List<Double> ys = new ArrayList<>();
        double y = -widthMm - r + stepoverMm;
        ToolpathPlanner.bounded("the step's width", widthMm, "the stepover", stepoverMm);
        while (y < wallY - tol.linear()) {
            ys.add(y);
            y += stepoverMm;
        }
        ys.add(wallY);
        double floor = h.bottomZ() + bottomAllowanceMm;
        Heights layers = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), Math.min(h.topZ(), floor));
        double xa = climb ? x1 : x0;
        double xb = climb ? x0 : x1;
        MoveBuilder b = new MoveBuilder(new Vec3(xa, outY, h.clearanceZ()));
        b.rapid(new Vec3(xa, outY, h.retractZ()));
        for (double z : layers.layers(axialMm)) {
            for (double py : ys) {
                b.rapid(new Vec3(xa, outY, h.retractZ()));
                // down in the air beyond the open side, then in at depth
                b.feed(new Vec3(xa, outY, z), t.plungeFeedMmPerMin());
                b.feed(new Vec3(xa, py, z), t.feedMmPerMin());
                b.feed(new Vec3(xb, py, z), t.feedMmPerMin());
                b.feed(new Vec3(xb, outY, z), t.feedMmPerMin());
                b.rapid(new Vec3(xb, outY, h.retractZ()));
            }
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return new ToolpathSection(label, Vec3.UNIT_Z, t.diameterMm(), t.toolNumber(), t.spindleRpm(),
                new Vec3(xa, outY, h.clearanceZ()), b.moves());
    }

    /**
     * A closed outside profile: one loop per layer at the tool's radius (and the side allowance)
     * outside the part's outline, entered and left along a straight line from the air beyond the
     * stock, at the loop's point nearest to it.
     *
     * @param part the part's outline (the material kept), counter-clockwise, in the feature frame
     * @param stock the stock's outline in the same frame, counter-clockwise
     * @param climb with M3: the loop runs clockwise (the part on the tool's right)
     * @throws UnsupportedOperationException when no straight lead-in from outside the stock clears the part
     */
    static ToolpathSection outsideProfile(String label, Contour part, Contour stock, Heights h, Tooling t,
            double axialMm, double sideAllowanceMm, double bottomAllowanceMm, boolean climb, Tolerance tol) {
        double r = t.radiusMm();
        double off = r + sideAllowanceMm;
        List<Contour> loops = org.fresa.pocket.LineArcOffsetter.offset(part, off, tol);
        Contour loop = loops.stream().filter(Contour::isCcw).max(java.util.Comparator.comparingDouble(Contour::area))
                .orElseThrow(() -> new UnsupportedOperationException("the profile has no outward offset by "
                        + ToolpathPlanner.mm(off) + " mm"));
        // where the loop comes nearest the stock's edge: there the lead-in crosses the least material
        List<Curve2> cs = splitAtMiddles(loop.curves());
        int best = -1;
        double bestD = Double.POSITIVE_INFINITY;
        Vec2 bestOut = null;
        for (int i = 0; i < cs.size(); i++) {
            Vec2 p = cs.get(i).start();
            Vec2 q = outside(stock, p, r + OUTSIDE_MM);
            if (q == null) {
                continue;
            }
            double d = p.distance(q);
            if (d < bestD && clears(part, p, q, off, tol)) {
                best = i;
                bestD = d;
                bestOut = q;
            }
        }
        if (best < 0) {
            throw new UnsupportedOperationException("no straight lead-in from outside the stock reaches the profile"
                    + " without cutting into the part");
        }
        List<Curve2> ring = new ArrayList<>(cs.subList(best, cs.size()));
        ring.addAll(cs.subList(0, best));
        if (climb) {
            List<Curve2> rev = new ArrayList<>();
            for (int i = ring.size() - 1; i >= 0; i--) {
                Curve2 c = ring.get(i);
                rev.add(c instanceof Arc2 a ? a.reversed() : ((Segment2) c).reversed());
            }
            ring = rev;
        }
        Vec2 p = ring.get(0).start();
        double floor = h.bottomZ() + bottomAllowanceMm;
        Heights layers = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), Math.min(h.topZ(), floor));
        MoveBuilder b = new MoveBuilder(Vec3.of(bestOut, h.clearanceZ()));
        b.rapid(Vec3.of(bestOut, h.retractZ()));
        for (double z : layers.layers(axialMm)) {
            b.rapid(Vec3.of(bestOut, h.retractZ()));
            b.feed(Vec3.of(bestOut, z), t.plungeFeedMmPerMin());
            b.feed(Vec3.of(p, z), t.feedMmPerMin());
            b.curves(ring, z, t.feedMmPerMin());
            b.feed(Vec3.of(bestOut, z), t.feedMmPerMin());
            b.rapid(Vec3.of(bestOut, h.retractZ()));
        }
        b.rapid(Vec3.of(bestOut, h.clearanceZ()));
        return new ToolpathSection(label, Vec3.UNIT_Z, t.diameterMm(), t.toolNumber(), t.spindleRpm(),
                Vec3.of(bestOut, h.clearanceZ()), b.moves());
    }

    /** The curves with every straight segment split at its middle: more places to lead in. */
    private static List<Curve2> splitAtMiddles(List<Curve2> cs) {
        List<Curve2> out = new ArrayList<>();
        for (Curve2 c : cs) {
            if (c instanceof Segment2 s && s.start().distance(s.end()) > 1e-6) {
                Vec2 m = s.start().interpolate(s.end(), 0.5);
                out.add(new Segment2(s.start(), m));
                out.add(new Segment2(m, s.end()));
            } else {
                out.add(c);
            }
        }
        return out;
    }

    /**
     * The point straight out from p past the nearest edge of the stock by the clearance, or null
     * when p is not inside the stock (the loop is in the air there already).
     */
    private static Vec2 outside(Contour stock, Vec2 p, double clearance) {
        Vec2 nearest = null;
        double best = Double.POSITIVE_INFINITY;
        for (Curve2 c : stock.curves()) {
            if (c instanceof Segment2 s) {
                Vec2 d = s.end().minus(s.start());
                double len2 = d.dot(d);
                double u = len2 > 0 ? Math.max(0, Math.min(1, p.minus(s.start()).dot(d) / len2)) : 0;
                Vec2 q = s.start().plus(d.times(u));
                if (q.distance(p) < best) {
                    best = q.distance(p);
                    nearest = q;
                }
            }
        }
        if (nearest == null) {
            return null;
        }
        if (stock.windingNumber(p) == 0) {
            return p;
        }
        Vec2 dir = best > 1e-9 ? nearest.minus(p).normalized() : null;
        if (dir == null) {
            return null;
        }
        return nearest.plus(dir.times(clearance));
    }

    /** Whether the tool along p..q stays the offset away from the part (sampled every 0.1 mm). */
    private static boolean clears(Contour part, Vec2 p, Vec2 q, double off, Tolerance tol) {
        int n = Math.max(2, (int) Math.ceil(p.distance(q) / 0.1));
        for (int k = 0; k <= n; k++) {
            Vec2 x = p.interpolate(q, (double) k / n);
            if (part.windingNumber(x) != 0 || part.distanceTo(x) < off - tol.linear()) {
                return false;
            }
        }
        return true;
    }
}
