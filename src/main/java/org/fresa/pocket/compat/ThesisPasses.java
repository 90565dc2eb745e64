package org.fresa.pocket.compat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Vec2;
import org.fresa.pocket.LoopState;
import org.fresa.pocket.PassPiece;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketElement;
import org.fresa.pocket.PocketPass;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.RecognitionNode;

/**
 * The passes of a plan made by the thesis's rules, recomputed in the thesis's own arithmetic for
 * the {@code 7m-compat} post: the same passes, elements, selectors and start points, but every
 * pass offset and every junction as GOTA.BAS computed them in Microsoft single precision.
 *
 * <p>What the program does between two passes (lines 3085-3345), and so what is reproduced here:
 * <ul>
 * <li>every element of the subcontour keeps its current D (line) or radius (arc) as 7-digit text;
 * moving the subcontour by TMAIS (routine 9500) adds {@code TMAIS·K} to each and writes it back
 * with {@code STR$}, so each pass starts from the rounded text of the previous one;
 * <li>the finishing pass at R is reached by +a then +(R - a) (a = finish fraction × D, R = D/2),
 * the pre-finish pass by +a; after a pass at DPERC the material limit DTESTE grows by
 * stepover × D, the subcontour moves to DTESTE (TMAIS = DTESTE - DPERC) and then by +R to the
 * next pass DPERC = DTESTE + R; the last pass of a sub-area lies at (leaf + DTESTE)/2 (or halfway
 * between the final subcontour's start and the leaf), reached by TMAIS = DPERC - DTESTE;
 * <li>a sub-area starts from its parent's subcontour at the parent's last pass;
 * <li>the stepover is the cut fraction, or {@code .9899999 - (1 - SIN(α/2·3.141593/180))/2}
 * (at least .5) when the sharpest corner α at DTESTE needs the correction (§7.6.1);
 * <li>each junction comes from {@link ThesisJunction}, with the element's selector.
 * </ul>
 * Which passes exist, their elements and selectors, the corner angles and the recognition tree's
 * offsets (leaves, starts of subcontours) come from the double-precision plan; the corner angle
 * and those offsets enter the single-precision chain rounded to single.
 */
public final class ThesisPasses {

    private final PocketPlan plan;
    private final Mbf diam;
    private final Mbf cut;
    private final Mbf allowance;
    private final Mbf radius;
    private final Mbf compar;
    private final Map<Integer, ThesisJunction.Carrier> reference = new HashMap<>();
    private final Map<Integer, RecognitionNode> nodes = new HashMap<>();
    private final Map<Integer, Integer> kByNumber = new HashMap<>();

    private static final Mbf TWO = Mbf.of(2);
    private static final Mbf HALF_STEP_FLOOR = BasicNumbers.val(".5");
    private static final Mbf CORRECTION_BASE = BasicNumbers.val(".9899999");
    private static final Mbf PI_THESIS = BasicNumbers.val("3.141593");
    private static final Mbf DEG_180 = Mbf.of(180);

    /** The subcontour's state in the chain: each element's current D or radius, and the two limits. */
    private static final class Chain {
        final Map<Integer, Mbf> d;
        Mbf dperc;
        Mbf dteste;
        double doubleOffset;

        Chain(Map<Integer, Mbf> d, Mbf dperc, Mbf dteste, double doubleOffset) {
            this.d = new HashMap<>(d);
            this.dperc = dperc;
            this.dteste = dteste;
            this.doubleOffset = doubleOffset;
        }

        Chain copy() {
            return new Chain(d, dperc, dteste, doubleOffset);
        }
    }

    private ThesisPasses(PocketPlan plan) {
        this.plan = plan;
        PocketTechnology t = plan.technology();
        this.diam = single(t.toolDiameterMm());
        this.cut = single(t.effectiveCut());
        this.allowance = single(t.finishFraction()).times(diam);
        this.radius = diam.dividedBy(TWO);
        collect(plan.recognition().root());
        LoopState ref = plan.recognition().reference();
        List<PocketElement> inputs = new ArrayList<>();
        for (PocketElement e : ref.elements()) {
            kByNumber.put(e.number(), e.k());
            if (!e.zeroRadius()) {
                inputs.add(e);
                reference.put(
                        e.number(), new ThesisJunction.Carrier(e.arc(), single(e.a()), single(e.b()), single(e.d())));
            }
        }
        inputs.sort(Comparator.comparingInt(PocketElement::number));
        Mbf sum = Mbf.ZERO;
        for (PocketElement e : inputs) {
            sum = sum.plus(single(e.d()).abs());
        }
        this.compar = sum.dividedBy(Mbf.of(inputs.size())).times(BasicNumbers.val(".0001"));
        for (int i = 0; i < ref.size(); i++) {
            PocketElement e = ref.get(i);
            if (e.zeroRadius()) {
                reference.put(e.number(), zeroArc(ref.get(i - 1), ref.get(i + 1), e));
            }
        }
    }

    /**
     * The plan with every pass offset and junction recomputed in the thesis's arithmetic; empty
     * when a junction does not exist there (where the thesis's program would stop).
     *
     * @param plan a plan made by the thesis's rules ({@link PassPlanner#plan(org.fresa.pocket.Recognition.Result,
     *     PocketTechnology)})
     */
    public static Optional<PocketPlan> of(PocketPlan plan) {
        try {
            return new ThesisPasses(plan).run();
        } catch (ArithmeticException e) {
            // an overflow or a division by zero: the thesis's program would have stopped too
            return Optional.empty();
        }
    }

    /** The thesis's tolerance COMPAR of the plan's contour, in single precision. */
    public static Mbf compar(PocketPlan plan) {
        return new ThesisPasses(plan).compar;
    }

    /** A number typed or read as text, as BASIC's VAL reads it. */
    static Mbf single(double v) {
        return BasicNumbers.val(Double.toString(v));
    }

    private void collect(RecognitionNode n) {
        nodes.put(n.id(), n);
        for (RecognitionNode c : n.children()) {
            collect(c);
        }
    }

    /**
     * A zero-radius arc at a reflex corner (routine 9350): centre the junction of its neighbours
     * at t = 0, as 7-digit text, radius blank.
     */
    private ThesisJunction.Carrier zeroArc(PocketElement before, PocketElement after, PocketElement arc) {
        ThesisJunction.Carrier p = reference.get(before.number());
        ThesisJunction.Carrier q = reference.get(after.number());
        Vec2 c = arc.center();
        ThesisJunction.Point best = null;
        double bd = Double.POSITIVE_INFINITY;
        for (boolean large : new boolean[] {false, true}) {
            Optional<ThesisJunction.Point> j =
                    p == null || q == null ? Optional.empty() : ThesisJunction.of(p, q, large, compar);
            if (j.isPresent()) {
                double dd =
                        Math.hypot(j.get().x().toDouble() - c.x(), j.get().y().toDouble() - c.y());
                if (dd < bd) {
                    bd = dd;
                    best = j.get();
                }
            }
        }
        Mbf x = best == null ? single(c.x()) : BasicNumbers.roundTrip(best.x());
        Mbf y = best == null ? single(c.y()) : BasicNumbers.roundTrip(best.y());
        return new ThesisJunction.Carrier(true, x, y, Mbf.ZERO);
    }

    private Optional<PocketPlan> run() {
        List<PocketPass> generated = plan.generated();
        List<PocketPass> out = new ArrayList<>();
        Map<List<Integer>, Chain> chains = new HashMap<>();
        Map<Integer, Chain> atDivision = new HashMap<>();
        Chain root = null;
        for (int k = 0; k < generated.size(); k++) {
            PocketPass pass = generated.get(k);
            Chain chain;
            if (k == 0) {
                Map<Integer, Mbf> d = new HashMap<>();
                reference.forEach((n, c) -> d.put(n, c.d()));
                root = new Chain(d, radius, allowance, radius.toDouble());
                move(root, allowance);
                move(root, radius.minus(allowance));
                chain = root;
            } else if (k == 1) {
                chain = root;
                move(chain, allowance);
                chain.dperc = chain.dperc.plus(allowance);
            } else {
                chain = next(pass, chains, atDivision);
            }
            chain.doubleOffset = pass.offsetMm();
            chains.put(pass.nodePath(), chain);
            Optional<PocketPass> p = recompute(pass, chain);
            if (p.isEmpty()) {
                return Optional.empty();
            }
            out.add(p.get());
        }
        List<PocketPass> milled = new ArrayList<>(out);
        Collections.reverse(milled);
        return Optional.of(new PocketPlan(plan.recognition(), plan.technology(), out, milled));
    }

    /** The chain for a pass after the second: a further pass of its node, or the first of a sub-area. */
    private Chain next(PocketPass pass, Map<List<Integer>, Chain> chains, Map<Integer, Chain> atDivision) {
        List<Integer> path = pass.nodePath();
        Chain own = chains.get(path);
        Chain chain;
        if (own != null) {
            chain = own;
            advance(chain, path);
        } else {
            chain = divided(path, chains, atDivision).copy();
        }
        Mbf dperc = chain.dteste.plus(radius);
        if (Math.abs(pass.offsetMm() - dperc.toDouble()) < 1e-4) {
            move(chain, radius);
            chain.dperc = dperc;
        } else {
            Mbf last = lastPass(pass, chain);
            move(chain, last.minus(chain.dteste));
            chain.dperc = last;
        }
        return chain;
    }

    /**
     * The subcontour a sub-area starts from: its nearest ancestor's at that ancestor's last pass,
     * moved on to DTESTE (the same for every sub-area of one division).
     */
    private Chain divided(List<Integer> path, Map<List<Integer>, Chain> chains, Map<Integer, Chain> atDivision) {
        for (int i = path.size() - 1; i >= 1; i--) {
            List<Integer> ancestor = path.subList(0, i);
            int id = ancestor.get(i - 1);
            Chain snapshot = atDivision.get(id);
            if (snapshot != null) {
                return snapshot;
            }
            Chain last = chains.get(ancestor);
            if (last != null) {
                Chain c = last.copy();
                advance(c, ancestor);
                atDivision.put(id, c);
                return c;
            }
        }
        throw new IllegalStateException("a sub-area's pass before any pass of the pocket: " + path);
    }

    /** After a pass at DPERC: DTESTE grows by the stepover and the subcontour moves there. */
    private void advance(Chain chain, List<Integer> path) {
        double d = chain.doubleOffset;
        double r = plan.technology().radiusMm();
        double alpha = stateAt(path, d - r).minAngleDeg(d - r);
        Mbf step = stepover(alpha);
        chain.dteste = chain.dteste.plus(step.times(diam));
        move(chain, chain.dteste.minus(chain.dperc));
    }

    private Mbf kOf(int number) {
        return Mbf.of(kByNumber.getOrDefault(number, 1));
    }

    /** The step fraction of lines 3143-3145. */
    private Mbf stepover(double alphaDeg) {
        double p = plan.technology().effectiveCut();
        if (PassPlanner.stepoverFraction(p, alphaDeg) == p) {
            return cut;
        }
        Mbf arg = single(alphaDeg).dividedBy(TWO).times(PI_THESIS).dividedBy(DEG_180);
        Mbf sin = single(Math.sin(arg.toDouble()));
        Mbf d = CORRECTION_BASE.minus(Mbf.ONE.minus(sin).dividedBy(TWO));
        return d.lessThan(HALF_STEP_FLOOR) ? HALF_STEP_FLOOR : d;
    }

    /** The last pass of a sub-area (lines 3109, 3300-3345). */
    private Mbf lastPass(PocketPass pass, Chain chain) {
        RecognitionNode node = nodes.get(pass.nodeId());
        Mbf leaf = single(node.leafT());
        Mbf last = leaf.plus(chain.dteste).dividedBy(TWO);
        Mbf start = single(node.stateAt(node.leafT() - 1e-9).tFrom());
        if (last.lessThan(start)) {
            last = start.plus(leaf).dividedBy(TWO);
        }
        return last;
    }

    /** Routine 9500: every element of the subcontour moves by TMAIS·K, written back as text. */
    private void move(Chain chain, Mbf tmais) {
        for (Map.Entry<Integer, Mbf> e : chain.d.entrySet()) {
            e.setValue(BasicNumbers.roundTrip(e.getValue().plus(tmais.times(kOf(e.getKey())))));
        }
    }

    private LoopState stateAt(List<Integer> path, double t) {
        for (int i = path.size() - 1; i >= 0; i--) {
            RecognitionNode n = nodes.get(path.get(i));
            if (n.tStart() <= t + 1e-9 || i == 0) {
                return n.stateAt(t);
            }
        }
        return nodes.get(path.get(0)).stateAt(t);
    }

    private Optional<PocketPass> recompute(PocketPass pass, Chain chain) {
        List<PassPiece> pieces = pass.pieces();
        int n = pieces.size();
        List<Vec2> starts = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            PocketElement prev = pieces.get((i + n - 1) % n).element();
            PocketElement e = pieces.get(i).element();
            Optional<ThesisJunction.Point> j =
                    ThesisJunction.of(carrier(prev, chain), carrier(e, chain), e.selector() == 'L', compar);
            if (j.isEmpty()) {
                return Optional.empty();
            }
            starts.add(new Vec2(j.get().x().toDouble(), j.get().y().toDouble()));
        }
        List<PassPiece> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            PassPiece p = pieces.get(i);
            out.add(new PassPiece(p.element(), chain.dperc.toDouble(), starts.get(i), starts.get((i + 1) % n), false));
        }
        return Optional.of(new PocketPass(pass.nodePath(), chain.dperc.toDouble(), pass.finishing(), out));
    }

    private ThesisJunction.Carrier carrier(PocketElement e, Chain chain) {
        ThesisJunction.Carrier ref = reference.get(e.number());
        Mbf d = chain.d.getOrDefault(e.number(), ref.d());
        return new ThesisJunction.Carrier(ref.circle(), ref.a(), ref.b(), d);
    }
}
