package org.fresa.pocket.compat;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.pocket.Entries;
import org.fresa.pocket.Entry;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PassPiece;
import org.fresa.pocket.PocketPass;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.PocketToolpath;
import org.fresa.pocket.ToolTooLargeException;

/**
 * The 1988 thesis's post-processor for the Thyssen Hüller NBH-65 with a Siemens Sinumerik 7M
 * (DIN 66025): coordinates as integer micrometres, BASIC {@code STR$} spacing ({@code X 23680},
 * {@code J-2214}), blocks N05, N10, ... in steps of 5, modal G01/G02/G03 suppressed, I/J the
 * arc centre minus the start point from the rounded integers, tool-centre path with G40.
 *
 * <p>{@link Mode#COMPAT} reproduces the printed programs with their defects: extra depth passes
 * copied at the first depth with the finishing feed still modal, negative numbers rounded with
 * the floor bias of {@code INT(v - .499)}, no blank after 3-digit block numbers in copied blocks.
 * {@link Mode#CORRECTED} cuts every depth pass at its own depth, enters each sub-area at each
 * depth on a zig-zag ramp no steeper than the entry angle instead of the thesis's vertical plunge
 * (straight incremental G01 X Y Z legs: the 7M's DIN 66025 interpolates arcs in the plane only, so
 * there is no helix; a plunge only for a centre-cutting tool), rounds symmetrically and always
 * writes the blank; it also mills in the direction
 * asked for ({@code fresa pocket --direction}): climb (each pass counter-clockwise, convex arcs
 * G03, with the clockwise M03 spindle) or conventional (the thesis's clockwise passes). Compat
 * always writes the thesis's conventional passes.
 *
 * <p>Compat mode also computes as the thesis's program did: the passes' offsets and junctions
 * come from {@link ThesisPasses} (Microsoft single precision, coefficients written back as
 * 7-digit text at every pass), and every number is rounded to micrometres in that precision,
 * {@code INT(v·1000 + .499)} for v > 0 and {@code INT(v·1000 - .499)} otherwise (lines
 * 8649-8709), the depth step {@code INT(ZPASSE·1000 + .499)} with {@code ZPASSE = (ZSUP -
 * ZBASE)/PROF} and {@code PROF = INT((ZSUP - ZBASE)/ZPASSE + .9999999)} (lines 3072-3080). Where
 * the single-precision junction does not exist (the thesis's program stops there), the passes
 * keep their exact junctions.
 *
 * <p>It lives beside the thesis's arithmetic rather than with the other posts because both modes
 * post the pocket module's passes ({@link PocketPlan}) directly, not a {@code model} toolpath.
 */
public final class Sinumerik7MPost {

    /** Faithful or corrected output. */
    public enum Mode {
        COMPAT,
        CORRECTED
    }

    /** Chord tolerance of a ramp leg over an arc of the pass (mm): the 7M has no helical interpolation. */
    static final double RAMP_CHORD_MM = 0.005;

    private final Mode mode;
    private final boolean climb;
    private final EntryRule entry;

    /** The thesis's direction: clockwise (conventional) passes. */
    public Sinumerik7MPost(Mode mode) {
        this(mode, false);
    }

    /**
     * @param climb climb milling (passes reversed, counter-clockwise); ignored in {@link Mode#COMPAT},
     *     which reproduces the printed programs
     */
    public Sinumerik7MPost(Mode mode, boolean climb) {
        this(mode, climb, EntryRule.DEFAULT);
    }

    /**
     * @param climb as {@link #Sinumerik7MPost(Mode, boolean)}
     * @param entry how {@link Mode#CORRECTED} enters each sub-area at each depth: a zig-zag ramp of
     *     straight G01 legs in X, Y and Z (the 7M interpolates arcs in the plane only, so a helix
     *     asked for is a ramp here), a plunge only for a centre-cutting tool; ignored in
     *     {@link Mode#COMPAT}, which keeps the thesis's vertical plunge
     */
    public Sinumerik7MPost(Mode mode, boolean climb, EntryRule entry) {
        this.mode = mode;
        this.climb = climb && mode == Mode.CORRECTED;
        this.entry = java.util.Objects.requireNonNull(entry, "entry");
    }

    private record Block(String text, int copiedFrom) {}

    /**
     * The whole program text, lines ending in LF.
     *
     * @throws ToolTooLargeException when an entry has no room for a ramp and the tool may not plunge
     */
    public String write(PocketPlan exactPlan) throws ToolTooLargeException {
        PocketPlan plan = mode == Mode.COMPAT ? ThesisPasses.of(exactPlan).orElse(exactPlan) : exactPlan;
        PocketTechnology t = plan.technology();
        List<Block> blocks = new ArrayList<>();
        add(blocks, "%");
        add(blocks, "G00 G40 G53 G90 Y150000 Z600000 B0");
        add(blocks, "G53 X450000");
        add(blocks, "G54 X 0 Y 0 Z" + str(mode == Mode.COMPAT ? basicInt(mbf(t.zTopMm()), false) : um(t.zTopMm())));
        add(blocks, "T01 M06");
        add(blocks, "M21");
        add(blocks, "G43 Z 5000 S" + str((long) Math.rint(t.spindleRpm())) + " M03");
        int passes = mode == Mode.COMPAT ? thesisDepthPasses(t) : t.depthPasses();
        long zp = mode == Mode.COMPAT ? thesisDepthStepUm(t) : um(t.depthStepMm());
        Levels lv = new Levels(zp, passes, um(t.zTopMm()) - um(t.zBottomMm()));
        long feed = (long) Math.rint(t.feedMmPerMin());
        List<PocketPass> milled = milled(plan);
        if (milled.isEmpty()) {
            return finish(blocks);
        }
        Vec2 s0 = milled.get(0).start();
        int firstRapid = blocks.size();
        add(blocks, "G00 G90 X" + str(um(s0.x())) + " Y" + str(um(s0.y())));
        if (mode == Mode.COMPAT) {
            add(blocks, "G01 G91 Z" + str(-(zp + 5000)) + "F" + str(feed));
        } else {
            enter(blocks, milled, 0, 1, lv, feed, t);
        }
        int firstCut = blocks.size();
        emitContours(blocks, plan, 1, lv, feed);
        int lastCut = blocks.size();
        for (int j = 2; j <= passes; j++) {
            if (mode == Mode.COMPAT) {
                add(blocks, "G00 G91 Z" + str(2 * zp + 20000));
                blocks.add(new Block(blocks.get(firstRapid).text(), firstRapid));
                add(blocks, "G91 Z -15000");
                add(blocks, "G01 Z -" + (2 * zp + 5000));
                for (int b = firstCut; b < lastCut; b++) {
                    blocks.add(new Block(blocks.get(b).text(), b));
                }
            } else {
                add(blocks, "G00 G91 Z" + str(lv.belowTopUm(j - 1) + 20000));
                add(blocks, "G90 X" + str(um(s0.x())) + " Y" + str(um(s0.y())));
                add(blocks, "G91 Z -15000");
                enter(blocks, milled, 0, j, lv, feed, t);
                emitContours(blocks, plan, j, lv, feed);
            }
        }
        return finish(blocks);
    }

    /**
     * The depth passes in micrometres below the top. The thesis's program steps by its rounded
     * step ({@code stepUm}); the corrected post puts pass k at k/n of the whole depth rounded to
     * the micrometre, so that the last pass lies on the floor: n rounded steps of 5/3 mm would
     * end 1 um below it.
     */
    private record Levels(long stepUm, int passes, long depthUm) {
        long belowTopUm(int pass) {
            return pass >= passes ? depthUm : Math.round((double) pass * depthUm / passes);
        }
    }

    /** The passes in milling order, each reversed for climb milling. */
    private List<PocketPass> milled(PocketPlan plan) {
        return climb ? plan.milled().stream().map(PocketPass::reversed).toList() : plan.milled();
    }

    /**
     * From 5 mm above the top (incremental Z) down to depth pass {@code depth} at the pass start:
     * a rapid to 1 mm above the floor of the depth pass above, then the entry's straight legs
     * as incremental G01 X Y Z blocks between micrometre points (no drift), the roughing feed
     * on the first; the next contour block returns to G90.
     */
    private void enter(
            List<Block> blocks, List<PocketPass> milled, int k, int depth, Levels lv, long feed, PocketTechnology t)
            throws ToolTooLargeException {
        PocketPass pass = milled.get(k);
        long top = -lv.belowTopUm(depth - 1) + 1000;
        long bottom = -lv.belowTopUm(depth);
        add(blocks, "G00 G91 Z" + str(top - 5000));
        EntryRule rule = entry.kind() == EntryRule.Kind.HELIX
                ? new EntryRule(EntryRule.Kind.RAMP, entry.angleDeg(), entry.centreCutting())
                : entry;
        Vec2 s = pass.start();
        Entry e = Entries.choose(
                        rule,
                        s,
                        chords(pass.pieces()),
                        onwards(milled, k),
                        climb,
                        Entries.Room.NONE,
                        PocketToolpath.room(milled, t.finishFraction() * t.toolDiameterMm()),
                        t.radiusMm(),
                        (top - bottom) / 1000.0)
                .orElseThrow(() -> new ToolTooLargeException(String.format(
                        java.util.Locale.ROOT,
                        "no room for a ramp to enter the pocket at X%.3f Y%.3f: a centre-cutting tool"
                                + " (--centre-cutting) may plunge there",
                        s.x(),
                        s.y())));
        long x = um(s.x());
        long y = um(s.y());
        List<Move> moves = e.moves(top / 1000.0, bottom / 1000.0, feed);
        if (e instanceof Entry.Plunge) {
            add(blocks, "G01 G91 X 0 Y 0 Z" + str(bottom - top) + " F" + str(feed));
            return;
        }
        // the legs' points in micrometres; each block descends at most floor(run x tan(angle)) um,
        // so that rounding never makes a block steeper than the entry angle; the legs are run
        // again (they start and end at the pass start) until the depth is reached
        double slope = Math.tan(Math.toRadians(rule.angleDeg()));
        long z = top;
        long sx = x;
        long sy = y;
        boolean first = true;
        boolean done = false;
        for (int round = 0; round <= Entries.MAX_STEPS && !done; round++) {
            for (Move m : moves) {
                long nx = um(m.end().x());
                long ny = um(m.end().y());
                long run = (long) Math.floor(Math.hypot(nx - x, ny - y));
                long nz = Math.max(bottom, z - (long) Math.floor(run * slope));
                if (nx == x && ny == y) {
                    continue;
                }
                add(
                        blocks,
                        (first ? "G01 G91 " : "") + "X" + str(nx - x) + " Y" + str(ny - y) + " Z" + str(nz - z)
                                + (first ? " F" + str(feed) : ""));
                x = nx;
                y = ny;
                z = nz;
                first = false;
                if (z == bottom && x == sx && y == sy) {
                    done = true;
                    break;
                }
            }
        }
        if (z > bottom) {
            throw new ToolTooLargeException("the ramp to enter the pocket at X" + s.x() + " Y" + s.y()
                    + " does not reach the depth in " + Entries.MAX_STEPS + " rounds");
        }
    }

    /**
     * What the tool follows at depth after pass k: the passes joined to it outward, each by a
     * straight link from where the one before ends (a ramp's legs may run on along it).
     */
    private static List<Curve2> onwards(List<PocketPass> milled, int k) {
        List<Curve2> out = new ArrayList<>();
        for (int i = k + 1; i < milled.size() && milled.get(i - 1).linksOutwardTo(milled.get(i)); i++) {
            List<PassPiece> before = milled.get(i - 1).pieces();
            Vec2 from = before.get(before.size() - 1).end();
            if (from.distance(milled.get(i).start()) > 1e-9) {
                out.add(new Segment2(from, milled.get(i).start()));
            }
            out.addAll(chords(milled.get(i).pieces()));
        }
        return out;
    }

    /** The pass as the 7M cuts it, its arcs as chords within {@link #RAMP_CHORD_MM} (for the ramp legs). */
    private static List<Curve2> chords(List<PassPiece> pieces) {
        List<Curve2> out = new ArrayList<>();
        for (PassPiece p : pieces) {
            double r = p.isArc() ? p.radiusMm() : 0;
            double len = p.lengthMm();
            if (!p.isArc() || r < 1e-6 || p.start().distance(p.end()) < 1e-9) {
                if (p.start().distance(p.end()) > 1e-9) {
                    out.add(new Segment2(p.start(), p.end()));
                }
                continue;
            }
            double sweep = len / p.start().distance(p.center());
            double step = 2 * Math.acos(Math.max(-1, 1 - RAMP_CHORD_MM / r));
            int n = (int) Math.max(1, Math.ceil(sweep / step));
            Vec2 a0 = p.start().minus(p.center());
            double sign = p.ccw() ? 1 : -1;
            Vec2 prev = p.start();
            for (int k = 1; k <= n; k++) {
                Vec2 q = k == n ? p.end() : p.center().plus(a0.rotated(sign * sweep * k / n));
                out.add(new Segment2(prev, q));
                prev = q;
            }
        }
        return out;
    }

    private void emitContours(List<Block> blocks, PocketPlan plan, int depth, Levels lv, long feed)
            throws ToolTooLargeException {
        PocketTechnology t = plan.technology();
        List<PocketPass> milled = milled(plan);
        String[] modal = {"G01"};
        boolean[] afterPlunge = {true};
        for (int k = 0; k < milled.size(); k++) {
            PocketPass pass = milled.get(k);
            if (k > 0) {
                PocketPass prev = milled.get(k - 1);
                if (prev.linksOutwardTo(pass)) {
                    motion(blocks, modal, afterPlunge, "G01", xy(pass.start()), "");
                } else {
                    long up = mode == Mode.COMPAT ? lv.stepUm() + 20000 : lv.belowTopUm(depth) + 20000;
                    add(blocks, "G00 G91 Z" + str(up));
                    add(
                            blocks,
                            "G90 X" + str(um(pass.start().x())) + " Y"
                                    + str(um(pass.start().y())));
                    add(blocks, "G91 Z -15000");
                    if (mode == Mode.COMPAT) {
                        add(blocks, "G01 Z -" + (lv.stepUm() + 5000));
                    } else {
                        enter(blocks, milled, k, depth, lv, feed, t);
                    }
                    modal[0] = "G01";
                    afterPlunge[0] = true;
                }
            }
            boolean first = true;
            for (PassPiece p : pass.pieces()) {
                String tail = pass.finishing() && first ? " F" + str((long) Math.rint(t.finishFeedMmPerMin())) : "";
                if (p.isArc()) {
                    long sx = um(p.start().x()), sy = um(p.start().y());
                    long cx = um(p.center().x()), cy = um(p.center().y());
                    motion(
                            blocks,
                            modal,
                            afterPlunge,
                            p.ccw() ? "G03" : "G02",
                            xy(p.end()) + " I" + str(cx - sx) + " J" + str(cy - sy),
                            tail);
                } else {
                    motion(blocks, modal, afterPlunge, "G01", xy(p.end()), tail);
                }
                first = false;
            }
        }
    }

    private void motion(
            List<Block> blocks, String[] modal, boolean[] afterPlunge, String g, String coords, String tail) {
        StringBuilder sb = new StringBuilder();
        if (afterPlunge[0]) {
            sb.append("G90 ");
            afterPlunge[0] = false;
        }
        if (!g.equals(modal[0])) {
            sb.append(g).append(' ');
            modal[0] = g;
        }
        sb.append(coords).append(tail);
        add(blocks, sb.toString());
    }

    private String xy(Vec2 p) {
        return "X" + str(um(p.x())) + " Y" + str(um(p.y()));
    }

    private String finish(List<Block> blocks) {
        add(blocks, "G00 G91 Z 200000");
        add(blocks, "G40 G53 G90 X450000 Y150000 Z600000 B0 M05");
        add(blocks, "T99 M06");
        add(blocks, "M22");
        add(blocks, "M30");
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < blocks.size(); i++) {
            int n = 5 * (i + 1);
            String num = n < 100 ? String.format(java.util.Locale.ROOT, "%02d", n) : Integer.toString(n);
            Block b = blocks.get(i);
            boolean glued = mode == Mode.COMPAT && b.copiedFrom() >= 0 && n >= 100 && 5 * (b.copiedFrom() + 1) < 100;
            out.append('N')
                    .append(num)
                    .append(glued ? "" : " ")
                    .append(b.text())
                    .append('\n');
        }
        return out.toString();
    }

    private static void add(List<Block> blocks, String text) {
        blocks.add(new Block(text, -1));
    }

    private static Mbf mbf(double v) {
        return BasicNumbers.val(Double.toString(v));
    }

    /** {@code INT(v*1000 + .499)}, or with {@code - .499} when signed and v is not positive. */
    private static long basicInt(Mbf v, boolean signed) {
        Mbf thousand = Mbf.of(1000);
        Mbf bias = BasicNumbers.val(".499");
        Mbf scaled = v.times(thousand);
        Mbf r = signed && !v.greaterThan(Mbf.ZERO) ? scaled.minus(bias) : scaled.plus(bias);
        return (long) r.floor().toDouble();
    }

    /** Lines 3072 and 3079: {@code PROF = INT((ZSUP - ZBASE)/ZPROF + .9999999)}, at least 1. */
    private static int thesisDepthPasses(PocketTechnology t) {
        Mbf depth = mbf(t.zTopMm()).minus(mbf(t.zBottomMm()));
        Mbf prof = depth.dividedBy(mbf(t.maxDepthMm()))
                .plus(BasicNumbers.val(".9999999"))
                .floor();
        return prof.isZero() ? 1 : (int) prof.toDouble();
    }

    /** Lines 3080 and 4003: {@code INT(ZPASSE*1000 + .499)}, {@code ZPASSE = (ZSUP - ZBASE)/PROF}. */
    private static long thesisDepthStepUm(PocketTechnology t) {
        Mbf depth = mbf(t.zTopMm()).minus(mbf(t.zBottomMm()));
        return basicInt(depth.dividedBy(Mbf.of(thesisDepthPasses(t))), false);
    }

    /**
     * mm to integer micrometres: the thesis's INT(v·1000 ± .499) in compat mode, else symmetric.
     * In compat mode the expression is evaluated as the BASIC program did, in Microsoft single
     * precision on the number as BASIC holds it (a 24-bit mantissa): above 2^17 µm (131.072 mm)
     * single-precision numbers are 1/64 µm apart, so {@code v·1000 + .499} already rounds up to
     * the next integer when the fraction is .4922 or more, and a vertex at ...x.4995 µm prints one
     * micrometre higher than in double; a coordinate of exactly 0 takes the {@code - .499} branch
     * and prints -1, as the program's {@code IF X > 0} test does.
     */
    long um(double mm) {
        double v = mm * 1000;
        if (mode == Mode.COMPAT) {
            return basicInt(mbf(mm), true);
        }
        return (long) Math.signum(v) * (long) Math.floor(Math.abs(v) + 0.5);
    }

    /** BASIC STR$: a blank before non-negative numbers. */
    static String str(long v) {
        return v >= 0 ? " " + v : Long.toString(v);
    }
}
