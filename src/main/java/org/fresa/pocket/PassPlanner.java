package org.fresa.pocket;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;

/**
 * The thesis's pass rules (§7.6.1, §3.9 of the seed): finishing pass at R, pre-finish at R + a,
 * then + s with the corner-angle stepover correction evaluated at d - R; a division sends the
 * next pass into every child (depth first); a sub-area is done when all its leaves are within
 * the tool's reach d + R; the last pass lies midway between the leaf and the new material
 * boundary, clamped into the final subcontour's interval.
 */
public final class PassPlanner {

    /** Pass pieces (offset elements) a plan may hold; a plan needing more is refused, not built. */
    static final int MAX_PIECES = 1_000_000;

    private final PocketTechnology tech;
    private final boolean faithful;
    private final double r;
    private final List<PocketPass> generated = new ArrayList<>();

    private PassPlanner(PocketTechnology tech, boolean faithful) {
        this.tech = tech;
        this.faithful = faithful;
        this.r = tech.radiusMm();
    }

    /**
     * Plans the passes of a profile: by the thesis's rules on its elements as written (the 7M
     * compat output), or by Fresa's on the profile every other post mills, its lines of unit
     * normal and the junctions the thesis snaps across a gap bridged by a step, so that no pass
     * stands nearer the wall as drawn than its offset ({@link PocketProfile#withBridgedJunctions()}).
     *
     * @throws CamInputException when the recognition tree cannot be built (not clockwise or not closed)
     */
    public static PocketPlan plan(PocketProfile profile, PocketTechnology tech, boolean faithful)
            throws CamInputException, ToolTooLargeException {
        PocketProfile milled = faithful ? profile : profile.withUnitNormals().withBridgedJunctions();
        return plan(Recognition.of(milled), tech, faithful);
    }

    /** Plans the passes exactly by the thesis's rules (for the 7M compat output and tests). */
    public static PocketPlan plan(Recognition.Result rec, PocketTechnology tech) throws ToolTooLargeException {
        return plan(rec, tech, true);
    }

    /**
     * Plans the passes; fails when the tool does not fit (the thesis's tool checks).
     *
     * @param faithful the thesis's rules exactly; otherwise (Fresa's default) the stepover also
     *     respects the sharpest corner at d + R, and a pass at (event - R) is added before a
     *     division or a channel collapse that the regular step would jump over, so that the
     *     neck between sub-areas is cut
     */
    public static PocketPlan plan(Recognition.Result rec, PocketTechnology tech, boolean faithful)
            throws ToolTooLargeException {
        double a = tech.finishFraction() * tech.toolDiameterMm();
        if (tech.toolDiameterMm() + 2 * a > rec.maxHoleDiameterMm() + 1e-9) {
            throw new ToolTooLargeException("tool diameter plus twice the allowance ("
                    + (tech.toolDiameterMm() + 2 * a) + " mm) exceeds the largest hole (FURO MAXIMO "
                    + rec.maxHoleDiameterMm() + " mm): use a smaller tool");
        }
        PassPlanner p = new PassPlanner(tech, faithful);
        List<RecognitionNode> chain = new ArrayList<>();
        chain.add(rec.root());
        try {
            p.run(rec.root(), chain, p.r, Double.NaN);
        } catch (TooManyPasses e) {
            throw new ToolTooLargeException("the pocket needs more than " + MAX_PIECES + " pass elements with a "
                    + tech.toolDiameterMm() + " mm tool (largest hole " + rec.maxHoleDiameterMm()
                    + " mm): use a larger tool or split the pocket");
        }
        List<PocketPass> milled = new ArrayList<>(p.generated);
        Collections.reverse(milled);
        // each piece once cut and once ramped down, some arcs joined by short lines, and a link or
        // rapids and a plunge per pass (the thesis's pockets have 1.4 moves per piece and layer)
        tech.checkMoves(
                milled.stream().mapToLong(x -> 3L * x.pieces().size() + 4).sum());
        return new PocketPlan(rec, tech, p.generated, milled);
    }

    /** The thesis's corrected stepover fraction for the smallest corner angle alpha (degrees). */
    public static double stepoverFraction(double cut, double alphaDeg) {
        double p = Math.max(0.5, cut);
        double limit = Math.toDegrees(2 * Math.asin(2 * p - 1));
        if (alphaDeg <= limit) {
            p = Math.max(0.5, 0.99 - (1 - Math.sin(Math.toRadians(alphaDeg / 2))) / 2);
        }
        return p;
    }

    /** Table 7.4: the smallest corner angle (degrees) that needs no correction at stepover fraction p. */
    public static double minAngleWithoutCorrectionDeg(double p) {
        return Math.toDegrees(2 * Math.asin(2 * p - 1));
    }

    private void run(RecognitionNode node, List<RecognitionNode> chain, double d, double prevD) {
        double eps = 1e-9;
        while (true) {
            if (!node.isLeaf() && node.splitT() <= d + eps) {
                for (RecognitionNode c : node.children()) {
                    List<RecognitionNode> cc = new ArrayList<>(chain);
                    cc.add(c);
                    run(c, cc, d, prevD);
                }
                return;
            }
            if (node.isLeaf() && d >= node.leafT() - eps && !Double.isNaN(prevD)) {
                if (faithful && prevD < node.tStart() - eps) {
                    // the thesis enters a sub-area with the pass that crossed the division; when
                    // that pass lies beyond the sub-area's leaf (the sub-area begins and ends
                    // between two passes of its parent) it writes no pass there (cavity 05's
                    // sliver {8, 10, 12}, 11.535 to 11.766 between passes 6.7 and 13.9); Fresa's
                    // default mills it with the last-pass rule
                    return;
                }
                double leaf = node.leafT();
                double last = (leaf + d - r) / 2;
                double tPrev = node.stateAt(leaf - eps).tFrom();
                if (last < tPrev) {
                    last = (tPrev + leaf) / 2;
                }
                emit(node, chain, last);
                return;
            }
            emit(node, chain, d);
            if (node.maxLeafT() <= d + r + eps) {
                return;
            }
            double next;
            if (Double.isNaN(prevD)) {
                next = r + tech.finishFraction() * tech.toolDiameterMm();
            } else {
                double alpha = stateAt(chain, d - r).minAngleDeg(d - r);
                if (!faithful) {
                    double ahead = node.isLeaf() ? d + r : Math.min(d + r, node.splitT() - 1e-6);
                    alpha = Math.min(alpha, node.stateAt(ahead).minAngleDeg(ahead));
                }
                next = d + stepoverFraction(tech.cutFraction(), alpha) * tech.toolDiameterMm();
                if (!faithful) {
                    double barrier = Double.POSITIVE_INFINITY;
                    if (!node.isLeaf()) {
                        barrier = node.splitT();
                    }
                    for (RecognitionNode.Event e : node.events()) {
                        if (e.kind().equals("collapse") && e.t() > d) {
                            barrier = Math.min(barrier, e.t());
                        }
                    }
                    if (next >= barrier - eps && d + r < barrier - 1e-6) {
                        next = Math.max(barrier - r, d + 1e-3);
                    } else {
                        // where the subcontour changes (an element vanishes, a neck divides) the
                        // offsets stop being parallel: the only step that is sure to leave nothing
                        // between two passes is R, as dist(x, pass d) = w(x) - d for w(x) > d
                        boolean changes = next >= barrier - eps;
                        for (RecognitionNode.Event e : node.events()) {
                            changes |= e.t() > d + eps
                                    && e.t() <= next + r
                                    && !e.kind().equals("leaf");
                        }
                        if (changes) {
                            next = Math.min(next, d + r);
                        }
                    }
                }
            }
            prevD = d;
            d = next;
        }
    }

    private static LoopState stateAt(List<RecognitionNode> chain, double t) {
        for (int i = chain.size() - 1; i >= 0; i--) {
            RecognitionNode n = chain.get(i);
            if (n.tStart() <= t + 1e-9 || i == 0) {
                return n.stateAt(t);
            }
        }
        return chain.get(0).stateAt(t);
    }

    /** The plan outgrows {@link #MAX_PIECES}: a huge pocket for the tool, or a stepover that does not advance. */
    private static final class TooManyPasses extends RuntimeException {
        private static final long serialVersionUID = 1L;

        TooManyPasses() {
            super(null, null, false, false);
        }
    }

    private int pieceCount;

    private void emit(RecognitionNode node, List<RecognitionNode> chain, double d) {
        LoopState s = node.stateAt(d);
        pieceCount += s.size();
        if (pieceCount > MAX_PIECES || !Double.isFinite(d)) {
            throw new TooManyPasses();
        }
        List<PassPiece> pieces = new ArrayList<>();
        int n = s.size();
        for (int k = 1; k <= n; k++) {
            int i = s.pointer() + k;
            Optional<Vec2> vs = s.start(i, d);
            Optional<Vec2> ve = s.start(i + 1, d);
            if (vs.isEmpty() || ve.isEmpty()) {
                continue;
            }
            pieces.add(new PassPiece(s.get(i), d, vs.get(), ve.get(), false));
        }
        List<Integer> path = new ArrayList<>();
        for (RecognitionNode c : chain) {
            path.add(c.id());
        }
        generated.add(new PocketPass(path, d, generated.isEmpty(), pieces));
    }
}
