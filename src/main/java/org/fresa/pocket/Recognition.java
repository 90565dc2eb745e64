package org.fresa.pocket;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;

/**
 * The thesis's recognition tree (§6.2-6.4): the offset t is swept inward event by event.
 * Cancellations are incentres of consecutive triples; divisions are concave arcs (zero-radius ones
 * at reflex corners included) meeting a non-adjacent element inside both reference sectors;
 * coincident events (within compar) are applied together. Unlike the thesis, a division may give
 * any number of sub-areas (several coincident divisions), and sub-areas that vanish at once (a
 * parallel channel collapsing) are dropped.
 */
public final class Recognition {

    /**
     * The tree and the thesis's reported sizes.
     *
     * @param root the root node (the reference contour at t = 0)
     * @param reference the reference contour: the input plus zero-radius arcs at reflex corners
     * @param maxHoleDiameterMm FURO MAXIMO: 2 × the largest leaf offset
     * @param maxToolDiameterMm DIAMETRO MAXIMO: 2 × the first division offset (= FURO MAXIMO without division)
     * @param wallToolDiameterMm DIAMETRO p/ SUPERF: 2 × the root's first event offset
     * @param leafOffsets every leaf's offset, in tree order (mm)
     */
    public record Result(
            RecognitionNode root,
            LoopState reference,
            double maxHoleDiameterMm,
            double maxToolDiameterMm,
            double wallToolDiameterMm,
            List<Double> leafOffsets) {}

    private final double compar;
    private final java.util.Map<Integer, Vec2> origin = new java.util.HashMap<>();
    private int nextId = 1;

    private Recognition(double compar) {
        this.compar = compar;
    }

    /** Builds the tree of a clockwise profile. */
    public static Result of(PocketProfile profile) throws CamInputException {
        Recognition r = new Recognition(profile.compar());
        LoopState ref = referenceContour(profile);
        for (int i = 0; i < ref.size(); i++) {
            PocketElement e = ref.get(i);
            r.origin.put(
                    e.number(), e.zeroRadius() ? e.center() : ref.start(i, 0).orElse(e.center()));
        }
        RecognitionNode root = r.build(ref);
        List<Double> leaves = new ArrayList<>();
        double[] firstDivision = {Double.POSITIVE_INFINITY};
        collect(root, leaves, firstDivision);
        double maxLeaf = leaves.stream().mapToDouble(Double::doubleValue).max().orElse(0);
        double dmax = Double.isInfinite(firstDivision[0]) ? 2 * maxLeaf : 2 * firstDivision[0];
        double first = root.events().isEmpty()
                ? (root.isLeaf() ? root.leafT() : root.splitT())
                : root.events().get(0).t();
        return new Result(root, ref, 2 * maxLeaf, dmax, 2 * first, leaves);
    }

    private static void collect(RecognitionNode n, List<Double> leaves, double[] firstDivision) {
        if (n.isLeaf()) {
            leaves.add(n.leafT());
        } else {
            firstDivision[0] = Math.min(firstDivision[0], n.splitT());
            for (RecognitionNode c : n.children()) {
                collect(c, leaves, firstDivision);
            }
        }
        for (RecognitionNode.Event e : n.events()) {
            if (e.kind().equals("divide")) {
                firstDivision[0] = Math.min(firstDivision[0], e.t());
            }
        }
    }

    /**
     * The reference contour (§5.5): a concave zero-radius arc inserted at every junction whose
     * interior angle exceeds 180.3°. The pointer is the closing element N.
     */
    public static LoopState referenceContour(PocketProfile profile) {
        List<PocketElement> els = profile.elements();
        double compar = profile.compar();
        int n = els.size();
        List<Vec2> v = profile.vertices();
        List<PocketElement> out = new ArrayList<>();
        int created = els.stream().mapToInt(PocketElement::number).max().orElse(n);
        int pointer = -1;
        for (int i = 0; i < n; i++) {
            PocketElement prev = els.get((i + n - 1) % n);
            PocketElement e = els.get(i);
            double angle = ElementGeometry.interiorAngleDeg(prev, e, v.get(i));
            if (angle > 180.3) {
                out.add(new PocketElement(
                        ++created, true, v.get(i).x(), v.get(i).y(), 0, 1, 'S'));
                e = e.withSelector('S');
            }
            out.add(e);
            if (i == n - 1) {
                pointer = out.size() - 1;
            }
        }
        return new LoopState(0, out, pointer, compar);
    }

    private record Cancel(double t, Vec2 point) {}

    private record Division(double t, int a, int b, Vec2 point, int na, int nb) {}

    private RecognitionNode build(LoopState s0) throws CamInputException {
        int id = nextId++;
        List<LoopState> states = new ArrayList<>();
        List<RecognitionNode.Event> events = new ArrayList<>();
        states.add(s0);
        LoopState s = s0;
        double t = s0.tFrom();
        Vec2 lastPoint = null;
        for (int guard = 0; guard < 1000; guard++) {
            int n = s.size();
            if (n <= 2) {
                return leaf(id, states, events, s, t);
            }
            Cancel[] cancels = new Cancel[n];
            double ttm = Double.POSITIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                cancels[i] = cancellation(s, i, t).orElse(null);
                if (cancels[i] != null) {
                    ttm = Math.min(ttm, cancels[i].t());
                }
            }
            List<Division> divisions = divisions(s, t);
            double tdm = divisions.stream().mapToDouble(Division::t).min().orElse(Double.POSITIVE_INFINITY);
            double te = Math.min(ttm, tdm);
            if (Double.isInfinite(te) && lastPoint != null && vanished(states)) {
                // the last event left a subcontour turned inside out: the area vanished there
                states.remove(states.size() - 1);
                return new RecognitionNode(
                        id, states, withLeaf(events, t), List.of(), Double.NaN, t, Optional.of(lastPoint));
            }
            if (Double.isInfinite(te)) {
                String els = s.elements().toString();
                throw new CamInputException(
                        "contour",
                        "recognition found no event at t = " + t + " in "
                                + (els.length() > 200
                                        ? els.substring(0, 200) + "... ("
                                                + s.elements().size() + " elements)"
                                        : els)
                                + " (is the contour clockwise and closed?)");
            }
            Set<Integer> gone = new HashSet<>();
            for (int i = 0; i < n; i++) {
                if (cancels[i] != null && cancels[i].t() <= te + compar) {
                    gone.add(i);
                }
            }
            if (!gone.isEmpty()) {
                List<Integer> numbers = new ArrayList<>();
                for (int i : gone) {
                    numbers.add(s.get(i).number());
                }
                numbers.sort(null);
                events.add(new RecognitionNode.Event(te, "cancel", numbers));
                lastPoint = cancels[gone.iterator().next()].point();
                if (n - gone.size() <= 1) {
                    Vec2 p = cancels[gone.iterator().next()].point();
                    return new RecognitionNode(
                            id, states, withLeaf(events, te), List.of(), Double.NaN, te, Optional.of(p));
                }
                List<PocketElement> kept = new ArrayList<>();
                int ptr = s.pointer();
                while (gone.contains(((ptr % n) + n) % n)) {
                    ptr--;
                }
                ptr = ((ptr % n) + n) % n;
                int newPtr = 0;
                for (int i = 0; i < n; i++) {
                    if (gone.contains(i)) {
                        continue;
                    }
                    PocketElement e = s.get(i);
                    if (gone.contains(((i - 1) % n + n) % n)) {
                        int j = i - 1;
                        while (gone.contains(((j % n) + n) % n)) {
                            j--;
                        }
                        PocketElement prev = s.get(j);
                        Vec2 near = cancels[((i - 1) % n + n) % n].point();
                        e = e.withSelector(ElementGeometry.selectorNear(prev, e, te, near, compar));
                    }
                    if (i == ptr) {
                        newPtr = kept.size();
                    }
                    kept.add(e);
                }
                s = rejoined(s.with(te, kept, newPtr), divisions, te);
                states.add(s);
                if (kept.size() == 2) {
                    return leaf(id, states, events, s, te);
                }
                // the divisions found before the cancellation stay valid (their sectors may involve
                // a junction that no longer exists, e.g. a collapsing channel)
                List<Division> carried = new ArrayList<>();
                for (Division d : divisions) {
                    int ia = indexOf(s, d.na()), ib = indexOf(s, d.nb());
                    if (d.t() <= te + compar && ia >= 0 && ib >= 0) {
                        carried.add(new Division(d.t(), ia, ib, d.point(), d.na(), d.nb()));
                    }
                }
                divisions = carried;
            }
            List<Division> now = divisions.stream()
                    .filter(d -> d.t() <= te + compar)
                    .sorted((p, q) -> Double.compare(p.t(), q.t()))
                    .toList();
            if (!now.isEmpty()) {
                List<LoopState> loops = divide(s, now, te);
                lastPoint = now.get(0).point();
                List<Integer> numbers = new ArrayList<>();
                for (Division d : now) {
                    numbers.add(d.na());
                    numbers.add(d.nb());
                }
                if (loops.isEmpty()) {
                    return new RecognitionNode(
                            id,
                            states,
                            withLeaf(events, te),
                            List.of(),
                            Double.NaN,
                            te,
                            Optional.of(now.get(0).point()));
                }
                if (loops.size() == 1) {
                    events.add(new RecognitionNode.Event(te, "collapse", numbers));
                    s = loops.get(0);
                    states.add(s);
                } else {
                    events.add(new RecognitionNode.Event(te, "divide", numbers));
                    List<RecognitionNode> children = new ArrayList<>();
                    for (LoopState c : loops) {
                        children.add(build(c));
                    }
                    return new RecognitionNode(id, states, events, children, te, Double.NaN, Optional.empty());
                }
            }
            t = te;
        }
        throw new CamInputException("contour", "recognition did not converge");
    }

    /**
     * A division coincident with a cancellation whose element lay between the division's pair
     * leaves that pair adjacent. Their junction nearest the vanished element's point may, at a
     * near-tangent meeting, be the far one, which keeps a lens of ground the division's concave
     * element has already passed. The division's own junction (the first meeting along the
     * divided element) is taken instead when it leaves a smaller area: every point of the offset
     * area lies beyond both elements, so of the two closings the smaller one is the offset.
     */
    private LoopState rejoined(LoopState s, List<Division> divisions, double te) {
        double tt = te + 10 * compar;
        LoopState out = s;
        for (Division d : divisions) {
            int n = out.size();
            int ia = indexOf(out, d.na()), ib = indexOf(out, d.nb());
            if (d.t() > te + compar || ia < 0 || ib < 0 || n < 3) {
                continue;
            }
            PocketElement a = out.get(ia), b = out.get(ib);
            List<Vec2> js = divisionJunctions(a, b, d.point(), tt);
            List<PocketElement> els = new ArrayList<>(out.elements());
            if ((ib + 1) % n == ia) {
                els.set(ia, a.withSelector(ElementGeometry.selectorNear(b, a, tt, js.get(0), compar)));
            } else if ((ia + 1) % n == ib) {
                els.set(ib, b.withSelector(ElementGeometry.selectorNear(a, b, tt, js.get(1), compar)));
            } else {
                continue;
            }
            LoopState alt = out.with(out.tFrom(), els, out.pointer());
            Optional<Double> now = out.signedArea(tt);
            Optional<Double> then = alt.signedArea(tt);
            boolean nowValid = now.isPresent() && now.get() < 0;
            if (then.isPresent() && then.get() < 0 && (!nowValid || then.get() > now.get())) {
                out = alt;
            }
        }
        return out;
    }

    /**
     * Whether the newest subcontour of a node is no area at all: offsetting only shrinks an area,
     * so a subcontour that has none just after its event, is traversed the wrong way round, or
     * encloses more than an earlier one of the same node did is what is left of an area that
     * vanished at that event (several elements meeting at one point, met one by one within the
     * tolerance).
     */
    private boolean vanished(List<LoopState> states) {
        if (states.size() < 2) {
            return false;
        }
        double delta = 10 * compar;
        LoopState last = states.get(states.size() - 1);
        Optional<Double> area = last.signedArea(last.tFrom() + delta);
        if (area.isEmpty() || area.get() >= -compar * compar) {
            return true;
        }
        for (LoopState earlier : states.subList(0, states.size() - 1)) {
            Optional<Double> a = earlier.signedArea(earlier.tFrom() + delta);
            if (a.isPresent() && a.get() < 0 && -area.get() > -a.get()) {
                return true;
            }
        }
        return false;
    }

    private static List<RecognitionNode.Event> withLeaf(List<RecognitionNode.Event> events, double t) {
        List<RecognitionNode.Event> out = new ArrayList<>(events);
        out.add(new RecognitionNode.Event(t, "leaf", List.of()));
        return out;
    }

    /** The two-element final (Fig. 4.5): half the remaining lens width. */
    private RecognitionNode leaf(
            int id, List<LoopState> states, List<RecognitionNode.Event> events, LoopState s, double t) {
        double leafT = t;
        Optional<Vec2> point = Optional.empty();
        if (s.size() == 2) {
            PocketElement e1 = s.get(0), e2 = s.get(1);
            if (e1.arc() && !e2.arc()) {
                PocketElement x = e1;
                e1 = e2;
                e2 = x;
            }
            if (!e1.arc() && !e2.arc()) {
                double nn = e1.a() * e1.a() + e1.b() * e1.b();
                Vec2 p = new Vec2(e1.a(), e1.b()).times(e1.at(t) / nn);
                leafT = (t + e2.offsetThrough(p)) / 2;
            } else if (!e1.arc()) {
                double d = (e1.offsetThrough(e2.center()) - t) / e1.normalLength();
                if (e2.convex()) {
                    leafT = t + (d + e2.at(t)) / 2;
                    Vec2 w = new Vec2(e1.a(), e1.b()).times(e1.k() / e1.normalLength());
                    point = Optional.of(e2.center().minus(w.times(e2.at(leafT))));
                }
            } else {
                double dist = e1.center().distance(e2.center());
                double r1 = e1.at(t), r2 = e2.at(t);
                if (e1.convex() && e2.convex()) {
                    leafT = t + (r1 + r2 - dist) / 2;
                } else if (e1.concave() && e2.convex()) {
                    leafT = t + (r2 - r1 + dist) / 2;
                } else if (e1.convex() && e2.concave()) {
                    leafT = t + (r1 - r2 + dist) / 2;
                }
            }
            leafT = Math.max(leafT, t);
        } else if (s.size() == 1 && s.get(0).convex()) {
            leafT = s.get(0).d();
            point = Optional.of(s.get(0).center());
        }
        return new RecognitionNode(id, states, withLeaf(events, leafT), List.of(), Double.NaN, leafT, point);
    }

    /** The offset at which element i vanishes (incentre of i-1, i, i+1), validated by the selectors. */
    private Optional<Cancel> cancellation(LoopState s, int i, double t) {
        PocketElement e1 = s.get(i - 1), e2 = s.get(i), e3 = s.get(i + 1);
        for (Incentres.Solution sol : Incentres.of(e1, e2, e3)) {
            double ts = sol.t();
            if (!(ts > t + compar) || !Double.isFinite(ts)) {
                continue;
            }
            // a convex arc shrinks to a point at t = R: the thesis's ILMAX; near-tangent input
            // (snapped junctions) puts the incentre slightly beyond it, so clamp within the snap
            boolean ok = true;
            double limit = Double.POSITIVE_INFINITY;
            for (PocketElement e : List.of(e1, e2, e3)) {
                if (e.convex()) {
                    limit = Math.min(limit, e.d());
                    if (ts > e.d() + 100 * compar) {
                        ok = false;
                    }
                }
            }
            if (!ok) {
                continue;
            }
            Optional<Vec2> j1 = ElementGeometry.junction(e1, e2, ts, compar);
            Optional<Vec2> j2 = ElementGeometry.junction(e2, e3, ts, compar);
            double tolV = 100 * compar;
            if (j1.isPresent()
                    && j2.isPresent()
                    && j1.get().distance(sol.point()) <= tolV
                    && j2.get().distance(sol.point()) <= tolV) {
                return Optional.of(new Cancel(Math.min(ts, Math.max(limit, t + 10 * compar)), sol.point()));
            }
        }
        return Optional.empty();
    }

    /** Concave arcs against non-adjacent elements (§6.3), inside the reference sectors. */
    private List<Division> divisions(LoopState s, double t) {
        List<Division> out = new ArrayList<>();
        int n = s.size();
        if (n < 4) {
            return out;
        }
        for (int ia = 0; ia < n; ia++) {
            PocketElement a = s.get(ia);
            if (!a.concave()) {
                continue;
            }
            for (int off = 2; off <= n - 2; off++) {
                int ib = (ia + off) % n;
                PocketElement b = s.get(ib);
                if (b.concave() && ib < ia) {
                    continue;
                }
                double ra = a.at(t);
                double rel;
                Vec2 p;
                if (!b.arc()) {
                    double hIn = (b.offsetThrough(a.center()) - t) / b.normalLength();
                    if (hIn <= 0) {
                        continue;
                    }
                    rel = (hIn - ra) / 2;
                    Vec2 w = new Vec2(b.a(), b.b()).times(b.k() / b.normalLength());
                    p = a.center().minus(w.times(ra + rel));
                } else {
                    double dist = a.center().distance(b.center());
                    if (dist <= compar) {
                        continue;
                    }
                    double rb = b.at(t);
                    if (b.concave()) {
                        rel = (dist - ra - rb) / 2;
                        p = a.center().plus(b.center().minus(a.center()).times((ra + rel) / dist));
                    } else {
                        rel = (rb - ra - dist) / 2;
                        p = a.center().plus(a.center().minus(b.center()).times((ra + rel) / dist));
                    }
                }
                // a division within the tolerance of now went with the event just taken (events up
                // to te + compar are applied together); any later one is an event still to come
                if (!(rel > compar)) {
                    continue;
                }
                double tt = t + rel;
                if (inSector(s, ia, p, t) && inSector(s, ib, p, t)) {
                    out.add(new Division(tt, ia, ib, p, a.number(), b.number()));
                }
            }
        }
        return out;
    }

    private boolean inSector(LoopState s, int i, Vec2 p, double t) {
        PocketElement e = s.get(i);
        // a zero-radius arc still of (almost) no radius has its vertices on its centre, so its
        // sector (the normals of its neighbours) is read a little further in
        double tv = e.zeroRadius() && e.at(t) < 100 * compar ? t + 100 * compar : t;
        Optional<Vec2> vs = s.start(i, tv);
        Optional<Vec2> ve = s.start(i + 1, tv);
        if (vs.isEmpty() || ve.isEmpty()) {
            return false;
        }
        if (!e.arc()) {
            double n = e.normalLength();
            Vec2 w = new Vec2(e.a(), e.b()).times(1 / n);
            double h = (e.a() * p.x() + e.b() * p.y() - e.at(t)) / n;
            Vec2 foot = p.minus(w.times(h));
            double excess =
                    vs.get().distance(foot) + foot.distance(ve.get()) - vs.get().distance(ve.get());
            return excess <= 10 * compar;
        }
        double r = Math.max(e.at(tv), compar);
        double tolAng = Math.toRadians(0.5) + 10 * compar / r;
        double sweep = LoopState.sweep(e, vs.get(), ve.get());
        double at = LoopState.sweep(e, vs.get(), p);
        return at <= sweep + tolAng || at >= 2 * Math.PI - tolAng;
    }

    private List<LoopState> divide(LoopState s, List<Division> divisions, double te) {
        double delta = 10 * compar;
        List<LoopState> loops = new ArrayList<>();
        loops.add(s);
        for (Division d : divisions) {
            int a = d.na(), b = d.nb();
            for (int li = 0; li < loops.size(); li++) {
                LoopState l = loops.get(li);
                int ia = indexOf(l, a), ib = indexOf(l, b);
                int n = l.size();
                if (ia < 0 || ib < 0 || (ia + 1) % n == ib || (ib + 1) % n == ia || n < 4) {
                    continue;
                }
                loops.remove(li);
                loops.addAll(li, splitLoop(l, ia, ib, d.point(), te + delta));
                break;
            }
        }
        List<LoopState> alive = new ArrayList<>();
        for (LoopState l : loops) {
            Optional<Double> area = l.size() < 2 ? Optional.empty() : l.signedArea(te + delta);
            if (area.isPresent() && area.get() < -compar * compar && insideParent(s, l, te + delta)) {
                alive.add(l);
            }
        }
        // pointers: keep the parent's pointer where its junction survives, else the nearest vertex
        PocketElement pe = s.get(s.pointer());
        PocketElement succ = s.get(s.pointer() + 1);
        Vec2 pv = s.start(s.pointer() + 1, te).orElse(divisions.get(0).point());
        List<LoopState> first = new ArrayList<>();
        List<LoopState> rest = new ArrayList<>();
        for (LoopState l : alive) {
            int ip = indexOf(l, pe.number());
            if (ip >= 0 && (l.get(ip + 1).number() == succ.number() || alive.size() == 1)) {
                // the pointer's junction survives, or only a collapsed channel was dropped
                first.add(l.with(te, l.elements(), ip));
            } else if (alive.size() == 1) {
                List<Vec2> vs = l.vertices(te + delta).orElse(List.of());
                int best = 0;
                double bd = Double.POSITIVE_INFINITY;
                for (int i = 0; i < vs.size(); i++) {
                    if (vs.get(i).distance(pv) < bd) {
                        bd = vs.get(i).distance(pv);
                        best = i;
                    }
                }
                first.add(l.with(te, l.elements(), ((best - 1) % l.size() + l.size()) % l.size()));
            } else {
                // the thesis's subroutines 9200/9300: the element whose start vertex, as first
                // computed on the reference contour, lies nearest the parent's start vertex (the
                // last of equals wins)
                Vec2 ref = origin.getOrDefault(succ.number(), pv);
                int best = 0;
                double bd = Double.POSITIVE_INFINITY;
                for (int i = 0; i < l.size(); i++) {
                    double dd = origin.getOrDefault(l.get(i).number(), pv).distance(ref);
                    if (dd <= bd) {
                        bd = dd;
                        best = i;
                    }
                }
                int ptr = ((best - 1) % l.size() + l.size()) % l.size();
                rest.add(l.with(te, l.elements(), ptr));
            }
        }
        first.addAll(rest);
        return first;
    }

    /**
     * A loop left by coincident divisions is real only if its vertices lie inside the offset of
     * every element of the parent that it lost (a collapsing channel between several divisions
     * can otherwise leave a loop of pieces from both of its walls).
     */
    private boolean insideParent(LoopState parent, LoopState loop, double t) {
        Optional<List<Vec2>> vs = loop.vertices(t);
        if (vs.isEmpty()) {
            return false;
        }
        for (int i = 0; i < parent.size(); i++) {
            PocketElement e = parent.get(i);
            if (e.zeroRadius() || indexOf(loop, e.number()) >= 0) {
                continue;
            }
            for (Vec2 v : vs.get()) {
                // in front of the element (not behind a wall of another sub-area) yet nearer than t
                double f = e.offsetThrough(v);
                if (f >= 0 && f < t - 10 * compar && inSector(parent, i, v, t)) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The two junctions a division of concave element a against element b leaves at offset tt: the
     * first along b's travel ends b where a takes over ({@code b → a}), the second starts b again
     * after a ({@code a → b}). Both fall on p when the carriers only touch.
     */
    private List<Vec2> divisionJunctions(PocketElement a, PocketElement b, Vec2 p, double tt) {
        List<Vec2> c = ElementGeometry.candidates(b, a, tt, compar);
        if (c.size() != 2) {
            return List.of(p, p);
        }
        Vec2 tb = b.tangentAt(p);
        boolean firstBefore = c.get(0).minus(p).dot(tb) <= c.get(1).minus(p).dot(tb);
        return firstBefore ? List.of(c.get(0), c.get(1)) : List.of(c.get(1), c.get(0));
    }

    private List<LoopState> splitLoop(LoopState l, int ia, int ib, Vec2 p, double tt) {
        int n = l.size();
        PocketElement a = l.get(ia), b = l.get(ib);
        List<Vec2> js = divisionJunctions(a, b, p, tt);
        Vec2 j1 = js.get(0), j2 = js.get(1);
        List<PocketElement> l1 = new ArrayList<>();
        for (int i = ia; ; i = (i + 1) % n) {
            PocketElement e = l.get(i);
            l1.add(i == ia ? e.withSelector(ElementGeometry.selectorNear(b, a, tt, j1, compar)) : e);
            if (i == ib) {
                break;
            }
        }
        List<PocketElement> l2 = new ArrayList<>();
        for (int i = ib; ; i = (i + 1) % n) {
            PocketElement e = l.get(i);
            l2.add(i == ib ? e.withSelector(ElementGeometry.selectorNear(a, b, tt, j2, compar)) : e);
            if (i == ia) {
                break;
            }
        }
        return List.of(l.with(l.tFrom(), l1, 0), l.with(l.tFrom(), l2, 0));
    }

    private static int indexOf(LoopState l, int number) {
        for (int i = 0; i < l.size(); i++) {
            if (l.get(i).number() == number) {
                return i;
            }
        }
        return -1;
    }
}
