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
 *
 * @param h the feature's heights in its frame
 * @param t the cutter and its feeds
 * @param axialMm depth of each layer; 0 or less for one layer
 * @param sideAllowanceMm material left on the walls, >= 0
 * @param bottomAllowanceMm material left on the floor, >= 0
 * @param climb climb milling (the material on the tool's right with M3), else conventional
 * @param tol the tolerance of the geometry
 */
record OpenSideMilling(
        Heights h,
        Tooling t,
        double axialMm,
        double sideAllowanceMm,
        double bottomAllowanceMm,
        boolean climb,
        Tolerance tol) {

    /** How far outside the stock the tool goes down and comes back up, beyond its radius (mm). */
    static final double OUTSIDE_MM = 2.0;

    /**
     * A step in its frame: x along the open boundary from its start (0 to length), the wall at
     * y 0 with the material kept at +y, the step's floor from the wall out to the stock's edge at
     * y = -width, z the feature axis (top 0). Passes run parallel to the wall, the first one at
     * the open side, each a stepover nearer the wall, the last one with the tool touching the
     * wall (less the side allowance); each is entered from the air beyond the open side at its
     * layer's depth. An end of the step where the stock ends lets the tool run past it; a closed
     * end keeps the tool's edge within the path's length.
     *
     * <p>A wall that slopes back from its foot: each layer's passes go in to the wall where it
     * stands at the layer's bottom, so the tool stays within the step and leaves a step on the
     * wall as high as the layer.
     *
     * @param footPerMm how far (mm) the wall lies farther out (towards -y) for each mm below the
     *     step's top: 0 for a vertical wall, -1 / tan(profile_angle) for a sloped one
     * <p>Climbing with M3, passes run along -x (the step's material on the tool's right).
     *
     * @throws UnsupportedOperationException when the tool does not fit between closed ends
     */
    ToolpathSection step(
            String label,
            double lengthMm,
            double widthMm,
            boolean openStart,
            boolean openEnd,
            double footPerMm,
            double stepoverMm) {
        double r = t.radiusMm();
        double x0 = openStart ? -(r + OUTSIDE_MM) : r;
        double x1 = openEnd ? lengthMm + r + OUTSIDE_MM : lengthMm - r;
        if (x1 < x0 - tol.linear()) {
            throw new UnsupportedOperationException("the tool (" + ToolpathPlanner.mm(t.diameterMm())
                    + " mm) is longer than the step between its closed ends (" + ToolpathPlanner.mm(lengthMm) + " mm)");
        }
        x1 = Math.max(x1, x0);
        double outY = -(widthMm + r + OUTSIDE_MM);
        ToolpathPlanner.bounded("the step's width", widthMm, "the stepover", stepoverMm);
        double xa = climb ? x1 : x0;
        double xb = climb ? x0 : x1;
        MoveBuilder b = new MoveBuilder(new Vec3(xa, outY, h.clearanceZ()));
        b.rapid(new Vec3(xa, outY, h.retractZ()));
        for (double z : layerZs()) {
            double wallY = -(r + sideAllowanceMm) - footPerMm * (h.topZ() - z);
            // the first pass takes one stepover off the open edge, each next one a stepover nearer the wall
            List<Double> ys = new ArrayList<>();
            double y = -widthMm - r + stepoverMm;
            while (y < wallY - tol.linear()) {
                ys.add(y);
                y += stepoverMm;
            }
            ys.add(wallY);
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
        return t.section(label, new Vec3(xa, outY, h.clearanceZ()), b.moves());
    }

    /**
     * A closed outside profile: one loop per layer at the tool's radius (and the side allowance)
     * outside the part's outline, entered and left along a straight line from the air beyond the
     * stock, at the loop's point nearest to it.
     *
     * @param part the part's outline (the material kept), counter-clockwise, in the feature frame
     * @param stock the stock's outline in the same frame, counter-clockwise
     * <p>Climbing with M3, the loop runs clockwise (the part on the tool's right).
     *
     * @throws UnsupportedOperationException when no straight lead-in from outside the stock clears the part
     */
    ToolpathSection outsideProfile(String label, Contour part, Contour stock) {
        double r = t.radiusMm();
        double off = r + sideAllowanceMm;
        List<Contour> loops = org.fresa.pocket.LineArcOffsetter.offset(part, off, tol);
        Contour loop = loops.stream()
                .filter(Contour::isCcw)
                .max(java.util.Comparator.comparingDouble(Contour::area))
                .orElseThrow(() -> new UnsupportedOperationException(
                        "the profile has no outward offset by " + ToolpathPlanner.mm(off) + " mm"));
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
            ring = reversed(ring);
        }
        return passesFromTheAir(label, bestOut, ring, bestOut);
    }

    /**
     * An open outside profile: a chain of lines and arcs from the block's edge across the block
     * to its edge again, the material kept on its left as it runs (ISO 14649-10). One pass per
     * layer at the tool's radius (and the side allowance) on the chain's right, the offset made
     * from the kept part's outline (the chain closed along the block's edge on its left, so
     * that the chain's corners are rounded or trimmed as a closed profile's), led in and out
     * along the chain's end tangents from the air beyond the block.
     *
     * @param chain the profile, start to end, in the feature frame
     * @param stock the stock's outline in the same frame, counter-clockwise
     * <p>Climbing with M3, the pass runs against the chain (the material on the tool's right).
     *
     * @throws UnsupportedOperationException when an end is not on the block's edge, the chain
     *     leaves the block, or an end meets the edge too obliquely to lead out along it
     */
    ToolpathSection openOutsideProfile(String label, List<Curve2> chain, Contour stock, List<String> problems) {
        double r = t.radiusMm();
        double off = r + sideAllowanceMm;
        Vec2 s = chain.get(0).start();
        Vec2 e = chain.get(chain.size() - 1).end();
        for (Vec2 p : List.of(s, e)) {
            if (stock.distanceTo(p) > tol.linear()) {
                throw new UnsupportedOperationException("the open outside profile ends at (" + xy(p) + "), not on the"
                        + " edge of the workpiece's block: only profiles from edge to edge across the block are cut");
            }
        }
        for (Curve2 c : chain) {
            Vec2 m = c.pointAt(0.5);
            if (stock.windingNumber(m) == 0 || stock.distanceTo(m) < tol.linear()) {
                throw new UnsupportedOperationException("the open outside profile runs outside the workpiece's block"
                        + " or along its edge near (" + xy(m) + ")");
            }
        }
        List<Curve2> edge = edgeFrom(stock, e, s, tol);
        List<Curve2> closed = new ArrayList<>(chain);
        closed.addAll(edge);
        Contour part = Contour.of(closed, Tolerance.DRAWING);
        if (!part.isCcw()) {
            throw new UnsupportedOperationException(
                    "the open outside profile does not divide the block with the" + " material on its left");
        }
        Contour loop = org.fresa.pocket.LineArcOffsetter.offset(part, off, tol).stream()
                .filter(Contour::isCcw)
                .max(java.util.Comparator.comparingDouble(Contour::area))
                .orElseThrow(() -> new UnsupportedOperationException(
                        "the profile has no outward offset by " + ToolpathPlanner.mm(off) + " mm"));
        List<Curve2> along = chain;
        List<Curve2> rest = edge.isEmpty() ? List.of(new Segment2(e, s)) : edge;
        // the loop's pieces that run beside the chain, not beside the block's edge or round its ends
        List<Curve2> cs = loop.curves();
        int n = cs.size();
        boolean[] beside = new boolean[n];
        for (int i = 0; i < n; i++) {
            Vec2 m = cs.get(i).pointAt(0.5);
            beside[i] = Math.abs(distance(along, m) - off) < 10 * tol.linear()
                    && distance(rest, m) > off + 10 * tol.linear();
        }
        int first = -1;
        for (int i = 0; i < n; i++) {
            if (beside[i] && !beside[(i + n - 1) % n]) {
                if (first >= 0) {
                    throw new UnsupportedOperationException("the tool's path beside the open outside profile"
                            + " breaks into pieces: the profile comes within the tool's diameter of the block's edge");
                }
                first = i;
            }
        }
        if (first < 0) {
            throw new UnsupportedOperationException("no path beside the open outside profile for the "
                    + ToolpathPlanner.mm(t.diameterMm()) + " mm tool");
        }
        List<Curve2> path = new ArrayList<>();
        for (int k = 0; beside[(first + k) % n]; k++) {
            path.add(cs.get((first + k) % n));
        }
        Vec2 in = leadPoint(path.get(0).start(), path.get(0).startTangent().negated(), stock, r, tol);
        Vec2 out = leadPoint(
                path.get(path.size() - 1).end(), path.get(path.size() - 1).endTangent(), stock, r, tol);
        if (!clears(part, in, path.get(0).start(), off, tol)
                || !clears(part, path.get(path.size() - 1).end(), out, off, tol)) {
            throw new UnsupportedOperationException(
                    "no straight lead-in or lead-out along the open outside profile's" + " ends clears the part");
        }
        if (climb) {
            path = reversed(path);
            Vec2 x = in;
            in = out;
            out = x;
        }
        double reach = 0;
        for (Curve2 c : stock.curves()) {
            // the block's corners on the cut side, not those on the part kept
            if (part.windingNumber(c.start()) == 0 && part.distanceTo(c.start()) > tol.linear()) {
                reach = Math.max(reach, distance(along, c.start()));
            }
        }
        if (reach > t.diameterMm() + tol.linear()) {
            problems.add(
                    "workingstep '" + label + "': the stock reaches " + ToolpathPlanner.mm(reach) + " mm beyond the"
                            + " open outside profile; the pass cuts the " + ToolpathPlanner.mm(t.diameterMm())
                            + " mm next to it");
        }
        return passesFromTheAir(label, in, path, out);
    }

    /**
     * One pass a layer from the air: down beyond the stock at {@code in}, in at depth to the
     * path's start, along the path, out to {@code out} beyond the stock and up to the retract
     * height; from the clearance height and back to it.
     */
    private ToolpathSection passesFromTheAir(String label, Vec2 in, List<Curve2> path, Vec2 out) {
        MoveBuilder b = new MoveBuilder(Vec3.of(in, h.clearanceZ()));
        b.rapid(Vec3.of(in, h.retractZ()));
        for (double z : layerZs()) {
            b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
            b.rapid(Vec3.of(in, h.retractZ()));
            b.feed(Vec3.of(in, z), t.plungeFeedMmPerMin());
            b.feed(Vec3.of(path.get(0).start(), z), t.feedMmPerMin());
            b.curves(path, z, t.feedMmPerMin());
            b.feed(Vec3.of(out, z), t.feedMmPerMin());
            b.rapid(Vec3.of(out, h.retractZ()));
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return t.section(label, Vec3.of(in, h.clearanceZ()), b.moves());
    }

    /** The layers' heights down to the floor, the bottom allowance left on it (never above the top). */
    private double[] layerZs() {
        double floor = h.bottomZ() + bottomAllowanceMm;
        return new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), Math.min(h.topZ(), floor)).layers(axialMm);
    }

    private static double distance(List<Curve2> cs, Vec2 p) {
        double d = Double.POSITIVE_INFINITY;
        for (Curve2 x : cs) {
            d = Math.min(d, x.distanceTo(p));
        }
        return d;
    }

    /**
     * The point along a direction from p where the tool's disc is clear of the stock by the
     * clearance: the lead-in or lead-out, straight along the chain's end tangent.
     */
    private static Vec2 leadPoint(Vec2 p, Vec2 dir, Contour stock, double r, Tolerance tol) {
        Vec2 u = dir.normalized();
        double step = 0.5;
        for (double d = 0; d <= 4 * (r + OUTSIDE_MM) + 1e-9; d += step) {
            Vec2 q = p.plus(u.times(d));
            if (stock.windingNumber(q) == 0 && stock.distanceTo(q) >= r + OUTSIDE_MM - tol.linear()) {
                return q;
            }
        }
        throw new UnsupportedOperationException("the open outside profile meets the block's edge at (" + xy(p)
                + ") too obliquely to lead the tool in or out along it");
    }

    /** The stock's outline from a onto b, both on it, counter-clockwise (the stock on the left). */
    private static List<Curve2> edgeFrom(Contour stock, Vec2 a, Vec2 b, Tolerance tol) {
        List<Curve2> cs = stock.curves();
        int n = cs.size();
        int ia = on(cs, a, tol);
        int ib = on(cs, b, tol);
        List<Curve2> out = new ArrayList<>();
        if (ia == ib && b.minus(a).dot(cs.get(ia).end().minus(cs.get(ia).start())) > 0) {
            add(out, a, b, tol);
            return out;
        }
        add(out, a, cs.get(ia).end(), tol);
        for (int i = (ia + 1) % n; i != ib; i = (i + 1) % n) {
            out.add(cs.get(i));
        }
        add(out, cs.get(ib).start(), b, tol);
        return out;
    }

    private static int on(List<Curve2> cs, Vec2 p, Tolerance tol) {
        int best = 0;
        for (int i = 0; i < cs.size(); i++) {
            if (cs.get(i).distanceTo(p) < cs.get(best).distanceTo(p)) {
                best = i;
            }
        }
        // a point at a corner belongs to the side that starts there
        Curve2 c = cs.get(best);
        if (c.end().distance(p) <= tol.linear()) {
            return (best + 1) % cs.size();
        }
        return best;
    }

    private static void add(List<Curve2> out, Vec2 a, Vec2 b, Tolerance tol) {
        if (a.distance(b) > tol.linear()) {
            out.add(new Segment2(a, b));
        }
    }

    /**
     * An open pocket: its walls (an open chain of lines and arcs, in the feature frame) closed by
     * the straight open side from the chain's end back to its start, which must lie on the
     * stock's edge. The region is carried past the open side by a cutter's diameter and the
     * clearance, so that each layer is cut by passes square to the open side that start in the
     * air beyond it at depth, run in to the far wall and come back out the same way, then by one
     * loop along the walls entered at its point farthest out. No entry ramp is needed.
     *
     * @param walls the wall chain, start to end
     * @param stock the stock's outline in the feature frame, counter-clockwise
     * <p>Climbing with M3, passes run in order with the material on the tool's right, the loop
     * counter-clockwise.
     *
     * @throws UnsupportedOperationException when the open side is not on the stock's edge or the
     *     tool does not fit
     */
    ToolpathSection openPocket(
            String label, List<Curve2> walls, Contour stock, double stepoverMm, List<String> problems) {
        Layout layout = layout(label, walls, stock, t.radiusMm() + sideAllowanceMm, stepoverMm, problems);
        MoveBuilder b = new MoveBuilder(Vec3.of(layout.first(), h.clearanceZ()));
        cut(b, layout, layerZs());
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return t.section(label, Vec3.of(layout.first(), h.clearanceZ()), b.moves());
    }

    /**
     * An open pocket whose floor meets its walls in a fillet that the cutter's corner cannot
     * follow (rho, the planar radius less the corner's radius), milled as {@link FilletedFloor}
     * mills a closed pocket's: the pocket as drawn down to the fillet's top; the floor from there
     * down with the walls offset by rho, so that the cutter's flat bottom reaches the fillet's
     * foot; then the fillet by Z-levels at FilletedFloor's heights and wall offsets. The fillet
     * runs along the walls only: the open side has no wall to meet. Every pass and every level's
     * loop along the walls is entered from the air beyond the open side, at depth.
     *
     * @param rhoMm the planar radius less the cutter's corner radius, > 0
     * @throws UnsupportedOperationException as {@link #openPocket(String, List, Contour, double,
     *     List)}, when the fillet is as high as the pocket, or when the open side is too narrow for
     *     the tool between its fillets
     */
    ToolpathSection filletedOpenPocket(
            String label, List<Curve2> walls, Contour stock, double stepoverMm, double rhoMm, List<String> problems) {
        double wall = t.radiusMm() + sideAllowanceMm;
        double floor = h.bottomZ() + bottomAllowanceMm;
        double filletTop = FilletedFloor.filletTopZ(floor, rhoMm, h, tol);
        Layout above = layout(label, walls, stock, wall, stepoverMm, problems);
        // the floor and the levels: the region carried past the open side far enough for the floor pass's offset
        List<String> floorProblems = new ArrayList<>();
        Layout floorPass = layout(label, walls, stock, wall + rhoMm, stepoverMm, floorProblems);
        floorProblems.stream().filter(x -> !problems.contains(x)).forEach(problems::add);
        MoveBuilder b = new MoveBuilder(Vec3.of(above.first(), h.clearanceZ()));
        cut(b, above, new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), filletTop).layers(axialMm));
        cut(b, floorPass, new Heights(h.clearanceZ(), h.retractZ(), filletTop, floor).layers(axialMm));
        Profile region =
                new Profile.General(carriedPastOpenSide(walls, stock, wall + rhoMm, t, tol), ContourOffsetter.EXACT);
        Vec2 out = outOfOpenSide(walls);
        double edge = walls.get(0).start().dot(out);
        int left = 0;
        for (FilletedFloor.Level level : FilletedFloor.levels(rhoMm, FilletedFloor.SCALLOP_MM)) {
            double z = floor + level.heightMm();
            for (double d : FilletedFloor.slab(level, wall, rhoMm, t.radiusMm())) {
                for (Ring ring : region.insetAll(d, tol)) {
                    List<Curve2> loop = startFarthestOut(ring.curves(), out);
                    if (!climb) {
                        loop = reversed(loop);
                    }
                    Vec2 in = loop.get(0).start();
                    if (in.dot(out) < edge + t.radiusMm() + OUTSIDE_MM / 2) {
                        // a part of the fillet the loop cannot reach from the open side
                        left++;
                        continue;
                    }
                    b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
                    b.rapid(Vec3.of(in, h.retractZ()));
                    b.feed(Vec3.of(in, z), t.plungeFeedMmPerMin());
                    b.curves(loop, z, t.feedMmPerMin());
                }
            }
        }
        if (left > 0) {
            problems.add("workingstep '" + label + "': " + left + " Z-level loop(s) round the floor's fillet that the"
                    + " tool cannot reach from the open side are left");
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return t.section(label, Vec3.of(above.first(), h.clearanceZ()), b.moves());
    }

    /** An open pocket's passes from the open side and its loop along the walls, at one offset from them. */
    private record Layout(List<Pass> passes, List<Curve2> loop) {
        Vec2 first() {
            return passes.isEmpty() ? loop.get(0).start() : passes.get(0).start();
        }
    }

    /**
     * The passes square to the open side that start in the air beyond it, and the loop along the
     * walls started at its point farthest out, with the tool's axis {@code off} from the walls.
     */
    private Layout layout(
            String label, List<Curve2> walls, Contour stock, double off, double stepoverMm, List<String> problems) {
        double r = t.radiusMm();
        Profile region = new Profile.General(carriedPastOpenSide(walls, stock, off, t, tol), ContourOffsetter.EXACT);
        Vec2 s = walls.get(0).start();
        Vec2 out = outOfOpenSide(walls);
        List<Ring> rings = region.insetAll(off, tol);
        if (rings.isEmpty()) {
            throw new UnsupportedOperationException(
                    "the tool (" + ToolpathPlanner.mm(t.diameterMm()) + " mm) does not" + " fit in the open pocket");
        }
        Ring ring = rings.get(0);
        if (rings.size() > 1) {
            problems.add("workingstep '" + label + "': " + (rings.size() - 1) + " part(s) of the pocket the "
                    + ToolpathPlanner.mm(t.diameterMm()) + " mm tool cannot reach from the open side are left");
        }
        double edge = s.dot(out);
        List<Pass> passes = new ArrayList<>();
        int skipped = 0;
        for (Pass p : PlanarPasses.parallelSplit(ring, stepoverMm, out.negated(), false, tol)) {
            // only passes that start in the air past the open side: the others would need an entry ramp
            if (p.start().dot(out) >= edge + r + OUTSIDE_MM / 2) {
                passes.add(p);
            } else {
                skipped++;
            }
        }
        if (skipped > 0) {
            problems.add("workingstep '" + label + "': " + skipped + " pass(es) behind the walls, which the tool"
                    + " cannot reach straight from the open side, are left to the loop along the walls");
        }
        if (!climb) {
            java.util.Collections.reverse(passes);
        }
        List<Curve2> loop = startFarthestOut(ring.curves(), out);
        if (!climb) {
            loop = reversed(loop);
        }
        return new Layout(passes, loop);
    }

    /** Each layer: the passes from the open side, then the loop along the walls, each entered from the air. */
    private void cut(MoveBuilder b, Layout layout, double[] zs) {
        Vec2 loopStart = layout.loop().get(0).start();
        for (double z : zs) {
            for (Pass p : layout.passes()) {
                b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
                b.rapid(Vec3.of(p.start(), h.retractZ()));
                b.feed(Vec3.of(p.start(), z), t.plungeFeedMmPerMin());
                b.curves(p.curves(), z, t.feedMmPerMin());
                b.feed(Vec3.of(p.start(), z), t.feedMmPerMin());
            }
            b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
            b.rapid(Vec3.of(loopStart, h.retractZ()));
            b.feed(Vec3.of(loopStart, z), t.plungeFeedMmPerMin());
            b.curves(layout.loop(), z, t.feedMmPerMin());
            b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        }
    }

    /** The closed chain started at its vertex farthest along out (with straight segments split at their middles). */
    private static List<Curve2> startFarthestOut(List<Curve2> cs, Vec2 out) {
        List<Curve2> split = splitAtMiddles(cs);
        int best = 0;
        for (int i = 1; i < split.size(); i++) {
            if (split.get(i).start().dot(out) > split.get(best).start().dot(out) + 1e-9) {
                best = i;
            }
        }
        List<Curve2> ring = new ArrayList<>(split.subList(best, split.size()));
        ring.addAll(split.subList(0, best));
        return ring;
    }

    /**
     * The open pocket's region carried past its open side (the straight line from the walls' end
     * back to their start) by a cutter's diameter (twice the offset) and the clearance, so that
     * the tool at the offset from it runs in the air there.
     *
     * @param off the tool's radius and the side allowance
     * @throws UnsupportedOperationException when the open side is not on the stock's edge or too
     *     narrow for the tool
     */
    static Contour carriedPastOpenSide(List<Curve2> walls, Contour stock, double off, Tooling t, Tolerance tol) {
        Vec2 s = walls.get(0).start();
        Vec2 e = walls.get(walls.size() - 1).end();
        if (s.distance(e) < 2 * off + tol.linear()) {
            throw new UnsupportedOperationException("the open side (" + ToolpathPlanner.mm(s.distance(e)) + " mm) is"
                    + " too narrow for the " + ToolpathPlanner.mm(t.diameterMm()) + " mm tool to come in through it");
        }
        for (Vec2 p : List.of(s, e, s.interpolate(e, 0.5))) {
            if (stock.distanceTo(p) > tol.linear()) {
                throw new UnsupportedOperationException("the open side of the pocket, from (" + xy(e) + ") to (" + xy(s)
                        + "), is not on the edge of the workpiece's block");
            }
        }
        Vec2 out = outOfOpenSide(walls);
        // past the open side by a diameter and the clearance: the loop inset by the radius runs in the air there
        double past = 2 * off + OUTSIDE_MM;
        List<Curve2> grown = new ArrayList<>(walls);
        Vec2 e2 = e.plus(out.times(past));
        Vec2 s2 = s.plus(out.times(past));
        grown.add(new Segment2(e, e2));
        grown.add(new Segment2(e2, s2));
        grown.add(new Segment2(s2, s));
        return Contour.of(grown, Tolerance.DRAWING);
    }

    /** The unit normal of the open side pointing out of the pocket. */
    private static Vec2 outOfOpenSide(List<Curve2> walls) {
        Vec2 s = walls.get(0).start();
        Vec2 e = walls.get(walls.size() - 1).end();
        List<Curve2> closed = new ArrayList<>(walls);
        closed.add(new Segment2(e, s));
        Contour pocket = Contour.of(closed, Tolerance.DRAWING);
        Vec2 chord = s.minus(e).normalized();
        Vec2 out = chord.leftNormal();
        if (pocket.windingNumber(s.interpolate(e, 0.5).plus(out.times(1e-3))) != 0) {
            out = out.negated();
        }
        return out;
    }

    private static List<Curve2> reversed(List<Curve2> cs) {
        List<Curve2> rev = new ArrayList<>();
        for (int i = cs.size() - 1; i >= 0; i--) {
            Curve2 c = cs.get(i);
            rev.add(c instanceof Arc2 a ? a.reversed() : ((Segment2) c).reversed());
        }
        return rev;
    }

    private static String xy(Vec2 p) {
        return ToolpathPlanner.mm(p.x()) + ", " + ToolpathPlanner.mm(p.y());
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
