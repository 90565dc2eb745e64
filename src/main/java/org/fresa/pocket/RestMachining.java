package org.fresa.pocket;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * Rest machining: a second, smaller tool cuts only what the first tool's passes left at the floor
 * and the second can reach (the corners tighter than the first tool's radius, the necks it could
 * not pass), not the whole pocket again. Units mm.
 *
 * <p>The rest material is found on a grid ({@link Coverage#rest}): the cells within the second
 * tool's radius of its own finishing offset that no pass of the first tool at the floor comes
 * within its radius of. The second tool's passes are pieces of its own offset plan of the same
 * region ({@link RegionPocket}, inside out, with its clean-up spurs): each loop is walked in
 * stretches of at most {@link #SAMPLE_MM}, a stretch is kept when the tool's disc along it meets
 * rest material, each kept run is lengthened by {@link #overlapMm} at both ends (the tool starts
 * and leaves in cleared floor rather than at the edge of the material) and runs less than
 * {@link #joinMm} apart on one loop are joined (a short feed in air at depth costs less than a
 * retract and a ramp). The pieces are cut in the plan's order, layer by layer at the first tool's
 * depths; each is entered by a ramp along itself no steeper than the entry angle, judged as into
 * stock (the program check cannot know what the first tool removed), moving the centre of a
 * cutter that does not cut at its centre by half its radius ({@link Entries}); between pieces the
 * tool retracts and rapids, or stays down where the link's disc stays in floor already cut
 * ({@link Coverage#clearedAlong}). Then the coverage of both tools is checked: a reachable cell
 * left uncut is refused with its place.
 */
public final class RestMachining {

    /** The length of the stretches a loop is judged by (mm): finer than a corner's rest. */
    static final double SAMPLE_MM = 0.25;

    /** The tool number of the rest tool: the first tool is T1. */
    public static final int TOOL_NUMBER = 2;

    /** The fastest spindle a setting may ask for (rpm), as the spindle options are bounded. */
    static final double MAX_SPINDLE_RPM = 100_000;

    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;
    /** The slack of a grid cell against the pieces' exact curves: the chords stray by half a micrometre. */
    private static final double CHORD_SLACK_MM = 1e-3;

    private RestMachining() {}

    /**
     * The rest tool's plan.
     *
     * @param section the rest tool's moves (empty when there is no rest material)
     * @param pieces the stretches cut at every layer, in order
     * @param restAreaMm2 the rest material's area at the floor (grid cells)
     * @param fullPlanLengthMm the length of the rest tool's whole offset plan at one layer, for comparison
     * @param technology the rest tool's technology (its diameter, spindle speed, feeds)
     */
    public record Plan(
            java.util.Optional<ToolpathSection> section,
            List<List<Curve2>> pieces,
            double restAreaMm2,
            double fullPlanLengthMm,
            PocketTechnology technology) {
        public Plan {
            pieces = pieces.stream().map(List::copyOf).toList();
        }

        /** Whether the rest tool has something to cut. */
        public boolean cuts() {
            return section.isPresent();
        }

        /** The pieces' length at one layer (mm). */
        public double piecesLengthMm() {
            return pieces.stream()
                    .flatMap(List::stream)
                    .mapToDouble(Curve2::length)
                    .sum();
        }
    }

    /**
     * The rest tool's technology: the first tool's with the rest tool's diameter, and the spindle
     * turning faster in the ratio of the diameters (the same cutting speed at the edge) up to
     * {@link #MAX_SPINDLE_RPM}; the same feeds (mm/min), so that each tooth takes a chip smaller
     * in the same ratio.
     */
    public static PocketTechnology technology(PocketTechnology first, double restToolDiameterMm) {
        double rpm = Math.min(MAX_SPINDLE_RPM, first.spindleRpm() * first.toolDiameterMm() / restToolDiameterMm);
        return new PocketTechnology(
                restToolDiameterMm,
                first.cutFraction(),
                first.finishFraction(),
                first.zTopMm(),
                first.zBottomMm(),
                first.maxDepthMm(),
                Math.max(first.spindleRpm(), Math.rint(rpm)),
                first.feedMmPerMin(),
                first.finishFeedMmPerMin());
    }

    /**
     * Plans the rest tool after the first tool's section.
     *
     * @param boundary the region's loops with the region on their left ({@link RegionOffsetter#oriented})
     * @param first the first tool's toolpath (its moves at the floor are what it cut)
     * @param firstRadiusMm the first tool's radius
     * @param tech the rest tool's technology ({@link #technology}), its floor the first tool's
     * @param climb climb milling
     * @param entry the entries allowed (a helix is never taken: each piece is entered by a ramp along it)
     * @throws ToolTooLargeException when the rest tool does not fit, a piece has no way down, the
     *     program would have too many moves, or both tools leave material the rest tool could reach
     */
    public static Plan plan(
            List<Contour> boundary,
            org.fresa.model.Toolpath first,
            double firstRadiusMm,
            PocketTechnology tech,
            boolean climb,
            EntryRule entry)
            throws ToolTooLargeException {
        if (!(tech.radiusMm() < firstRadiusMm)) {
            throw new IllegalArgumentException("the rest tool (" + tech.toolDiameterMm()
                    + " mm) must be smaller than the first (" + 2 * firstRadiusMm + " mm)");
        }
        RegionPocket.Plan own = RegionPocket.plan(boundary, tech, climb, entry, true, false);
        List<Contour> faces = own.levels().get(0).loops();
        List<List<Curve2>> firstPasses = new ArrayList<>();
        for (ToolpathSection s : first.sections()) {
            firstPasses.addAll(floorPasses(s, tech.zBottomMm()));
        }
        Coverage rest =
                Coverage.rest(faces, firstPasses, firstRadiusMm, tech.radiusMm(), RegionPocket.COVERAGE_CELL_MM);
        double restArea = rest.uncutAreaMm2();
        double fullLength =
                own.order().stream().mapToDouble(c -> c.loop().length()).sum();
        if (restArea == 0) {
            return new Plan(java.util.Optional.empty(), List.of(), 0, fullLength, tech);
        }
        // Where the rest tool may go straight down: every cell it can reach within its radius less
        // the program check's grid (which judges the tool's disc less 0.2 mm) plus half a diagonal
        // of this grid is cut by the first tool, taken with its radius less that half diagonal and
        // 0.03 mm (the check's chords of arcs), so that what is clear here is clear to the check.
        double halfDiagonal = rest.cellMm() / Math.sqrt(2);
        Coverage firstCleared = Coverage.rest(
                faces,
                firstPasses,
                firstRadiusMm - halfDiagonal - 0.03,
                tech.radiusMm(),
                RegionPocket.COVERAGE_CELL_MM);
        double downDiscMm = tech.radiusMm() - CHECK_CELL_MM + halfDiagonal;
        List<List<Curve2>> pieces = new ArrayList<>();
        List<List<Curve2>> leadIns = new ArrayList<>();
        List<Boolean> finishing = new ArrayList<>();
        for (RegionPocket.Cut cut : own.order()) {
            for (Piece p : cut(
                    cut.loop(),
                    rest,
                    overlapMm(tech),
                    joinMm(tech),
                    leadInMm(tech),
                    e -> downDiscMm > 0 && firstCleared.clearedDisc(e, downDiscMm))) {
                pieces.add(p.curves());
                leadIns.add(p.leadIn());
                finishing.add(cut.level() == 0);
            }
        }
        requireNothingLeft(faces, firstPasses, firstRadiusMm, pieces, tech.radiusMm());
        tech.checkMoves(pieces.stream().mapToLong(p -> 3L * p.size() + 8).sum());
        ToolpathSection section = section(pieces, leadIns, finishing, faces, rest, tech, climb, entry);
        return new Plan(java.util.Optional.of(section), pieces, restArea, fullLength, tech);
    }

    /**
     * The lengthening of a kept run at each end (mm): half a millimetre, a quarter of the rest
     * tool's diameter at most, so that the tool comes into the rest and leaves it through floor
     * already cut.
     */
    static double overlapMm(PocketTechnology tech) {
        return Math.min(0.5, 0.25 * tech.toolDiameterMm());
    }

    /**
     * Runs on one loop nearer than this are joined (mm): the rest tool's diameter. Fed across, the
     * gap costs a few seconds of air; a retract, a rapid and a ramp cost more.
     */
    static double joinMm(PocketTechnology tech) {
        return tech.toolDiameterMm();
    }

    /** The program check's grid of the material (mm): it judges a tool's disc less one cell. */
    static final double CHECK_CELL_MM = 0.2;

    /** How far beyond the rest tool's radius a lead-in starts from the rest it leads into (mm). */
    static final double ENTRY_MARGIN_MM = 0.3;

    /**
     * The shortest lead-in before a piece (mm): the rest tool's radius, the entry margin and the
     * overlap, so that where it goes down its disc is clear of the rest the piece starts into.
     */
    static double leadInMm(PocketTechnology tech) {
        return tech.radiusMm() + ENTRY_MARGIN_MM + overlapMm(tech);
    }

    /** What the section's moves at the floor follow: lines and arcs with both ends at floorZ. */
    static List<List<Curve2>> floorPasses(ToolpathSection s, double floorZ) {
        List<List<Curve2>> out = new ArrayList<>();
        List<Curve2> run = new ArrayList<>();
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            if (!m.travels()) {
                continue;
            }
            Vec3 e = m.end();
            boolean atFloor =
                    !(m instanceof Move.Rapid) && Math.abs(at.z() - floorZ) < 1e-6 && Math.abs(e.z() - floorZ) < 1e-6;
            if (atFloor) {
                Vec2 a = new Vec2(at.x(), at.y());
                Vec2 b = new Vec2(e.x(), e.y());
                if (m instanceof Move.Circular c) {
                    Vec2 ctr = new Vec2(c.center().x(), c.center().y());
                    double r = a.distance(ctr);
                    if (c.turns() > 0 || a.distance(b) < 1e-9) {
                        run.add(Arc2.circle(ctr, r, c.ccw()));
                    }
                    if (a.distance(b) >= 1e-9) {
                        run.add(new Arc2(ctr, a, b, c.ccw()));
                    }
                } else if (a.distance(b) > 0) {
                    run.add(new Segment2(a, b));
                }
            } else if (!run.isEmpty()) {
                out.add(run);
                run = new ArrayList<>();
            }
            at = e;
        }
        if (!run.isEmpty()) {
            out.add(run);
        }
        return out;
    }

    /**
     * The pieces of a closed loop whose disc meets rest material: stretches of at most
     * {@link #SAMPLE_MM} judged one by one, kept runs lengthened by overlapMm at both ends and
     * joined when less than joinMm apart (across the loop's start too); the whole loop when the
     * kept runs cover it.
     */
    static List<List<Curve2>> pieces(Contour loop, Coverage rest, double overlapMm, double joinMm) {
        return cut(loop, rest, overlapMm, joinMm, 0, p -> false).stream()
                .map(Piece::curves)
                .toList();
    }

    /**
     * A piece of a loop, and the stretch of the loop just before it (lead-in, empty when there is
     * none): the rest tool may go down in the cleared floor at the lead-in's start and feed along it
     * into the piece, instead of ramping into the piece.
     */
    record Piece(List<Curve2> curves, List<Curve2> leadIn) {}

    /**
     * {@link #pieces}, each with the shortest lead-in along the loop before it of leadInMm once or
     * twice that starts where the tool may go straight down ({@code clear}) and whose disc
     * along it meets no rest; none when there is no such one.
     */
    static List<Piece> cut(
            Contour loop,
            Coverage rest,
            double overlapMm,
            double joinMm,
            double leadInMm,
            java.util.function.Predicate<Vec2> clear) {
        double len = loop.length();
        List<double[]> kept = new ArrayList<>();
        double at = 0;
        for (Curve2 c : loop.curves()) {
            double l = c.length();
            if (l <= 0) {
                continue;
            }
            // arcs in chords of Coverage's sagitta, each chord and each line in stretches of SAMPLE_MM
            for (Vec2[] chord : Coverage.chords(List.of(c))) {
                double cl = chord[0].distance(chord[1]);
                int n = Math.max(1, (int) Math.ceil(cl / SAMPLE_MM));
                for (int k = 0; k < n; k++) {
                    Vec2 p = chord[0].interpolate(chord[1], (double) k / n);
                    Vec2 q = chord[0].interpolate(chord[1], (double) (k + 1) / n);
                    if (rest.meetsUncut(p, q)) {
                        // where on the loop, by the fraction of the curve the chord stands for
                        double s0 = at + l * along(c, p);
                        double s1 = at + l * along(c, q);
                        add(kept, Math.min(s0, s1), Math.max(s0, s1));
                    }
                }
            }
            at += l;
        }
        if (kept.isEmpty()) {
            return List.of();
        }
        // lengthen, then join neighbours (the runs are in order along the loop)
        List<double[]> runs = new ArrayList<>();
        for (double[] r : kept) {
            double a = r[0] - overlapMm;
            double b = r[1] + overlapMm;
            if (!runs.isEmpty() && a - runs.get(runs.size() - 1)[1] < joinMm) {
                runs.get(runs.size() - 1)[1] = Math.max(runs.get(runs.size() - 1)[1], b);
            } else {
                runs.add(new double[] {a, b});
            }
        }
        // across the loop's start: the last run and the first are neighbours
        if (runs.size() > 1) {
            double[] last = runs.get(runs.size() - 1);
            double[] firstRun = runs.get(0);
            if (firstRun[0] + len - last[1] < joinMm) {
                firstRun[0] = last[0] - len;
                runs.remove(runs.size() - 1);
            }
        }
        List<Piece> out = new ArrayList<>();
        for (double[] r : runs) {
            if (r[1] - r[0] >= len - 1e-9) {
                // the whole loop from its own start, as the plan cuts it
                out.add(new Piece(loop.curves(), List.of()));
            } else {
                List<Curve2> piece = stretch(loop, r[0], r[1]);
                // a run shorter than the program's resolution has no move: the check after finds what it left
                if (!piece.isEmpty()) {
                    out.add(new Piece(piece, leadIn(loop, rest, r, leadInMm, clear)));
                }
            }
        }
        return out;
    }

    private static List<Curve2> leadIn(
            Contour loop, Coverage rest, double[] run, double leadInMm, java.util.function.Predicate<Vec2> clear) {
        double len = loop.length();
        for (int k = 1; k <= 2 && leadInMm > 0; k *= 2) {
            double l = k * leadInMm;
            if (!(run[1] - run[0] + l < len - 1e-9 && run[0] - l > -len)) {
                break;
            }
            List<Curve2> lead = stretch(loop, run[0] - l, run[0]);
            if (lead.isEmpty() || !clear.test(lead.get(0).start())) {
                continue;
            }
            boolean meets = false;
            for (Vec2[] c : Coverage.chords(lead)) {
                meets = meets || rest.meetsUncut(c[0], c[1]);
            }
            if (!meets) {
                return lead;
            }
        }
        return List.of();
    }

    private static void add(List<double[]> kept, double s0, double s1) {
        if (!kept.isEmpty() && s0 <= kept.get(kept.size() - 1)[1] + 1e-9) {
            kept.get(kept.size() - 1)[1] = Math.max(kept.get(kept.size() - 1)[1], s1);
        } else {
            kept.add(new double[] {s0, s1});
        }
    }

    /** The fraction along a curve of its point nearest p (a point on it or on one of its chords). */
    private static double along(Curve2 c, Vec2 p) {
        return Math.max(0, Math.min(1, OffsetSplit.param(c, p)));
    }

    /**
     * The loop from arc length from to arc length to (mm), from in (-len, len), to - from at most
     * len: round its start when from is negative or to beyond its length.
     */
    static List<Curve2> stretch(Contour loop, double from, double to) {
        double len = loop.length();
        if (from < 0) {
            from += len;
            to += len;
        }
        List<Curve2> out = new ArrayList<>();
        double at = 0;
        for (int round = 0; round < 3 && at < to; round++) {
            for (Curve2 c : loop.curves()) {
                double l = c.length();
                double a = Math.max(from, at);
                double b = Math.min(to, at + l);
                if (l > 0 && b - a > 1e-9) {
                    if (a - at < 1e-9 && at + l - b < 1e-9) {
                        out.add(c);
                    } else {
                        Vec2 p = c.pointAt((a - at) / l);
                        Vec2 q = c.pointAt((b - at) / l);
                        if (p.distance(q) >= PocketMoves.RESOLUTION_MM) {
                            out.add(RegionPocket.piece(c, p, q));
                        }
                    }
                }
                at += l;
                if (at >= to) {
                    break;
                }
            }
        }
        return out;
    }

    /**
     * Refuses when both tools leave a cell the rest tool can reach: its centre is neither within
     * the first tool's radius of its passes nor within the rest tool's radius of a piece (on the
     * grid, then against the exact curves).
     */
    private static void requireNothingLeft(
            List<Contour> faces,
            List<List<Curve2>> firstPasses,
            double firstRadiusMm,
            List<List<Curve2>> pieces,
            double radiusMm)
            throws ToolTooLargeException {
        Coverage both = Coverage.rest(faces, firstPasses, firstRadiusMm, radiusMm, RegionPocket.COVERAGE_CELL_MM);
        for (List<Curve2> p : pieces) {
            both.cutAlong(p);
        }
        BitSet left = both.uncutCells();
        for (int i = left.nextSetBit(0); i >= 0; i = left.nextSetBit(i + 1)) {
            Vec2 c = both.cellCentre(i);
            if (!within(pieces, c, radiusMm + CHORD_SLACK_MM)) {
                throw new ToolTooLargeException(String.format(
                        Locale.ROOT,
                        "the rest tool's passes leave material it could reach at X%.3f Y%.3f: use a smaller rest"
                                + " tool or none",
                        c.x(),
                        c.y()));
            }
        }
    }

    private static boolean within(List<List<Curve2>> pieces, Vec2 p, double d) {
        for (List<Curve2> piece : pieces) {
            for (Curve2 c : piece) {
                if (c.distanceTo(p) <= d) {
                    return true;
                }
            }
        }
        return false;
    }

    private static ToolpathSection section(
            List<List<Curve2>> pieces,
            List<List<Curve2>> leadIns,
            List<Boolean> finishing,
            List<Contour> faces,
            Coverage rest,
            PocketTechnology t,
            boolean climb,
            EntryRule entry)
            throws ToolTooLargeException {
        double safe = t.zTopMm() + CLEARANCE_MM;
        Vec2 s0 = pieces.get(0).get(0).start();
        PocketMoves moves = new PocketMoves(new Vec3(s0.x(), s0.y(), safe));
        Entries.Room legRoom = (c, r) -> holds(faces, c, r);
        for (int j = 1; j <= t.depthPasses(); j++) {
            double z = t.zTopMm() - j * t.depthStepMm();
            double above = PocketToolpath.entryTop(t, j);
            Coverage cleared = rest.copy();
            Vec2 cursor = null;
            for (int k = 0; k < pieces.size(); k++) {
                List<Curve2> piece = pieces.get(k);
                Vec2 s = piece.get(0).start();
                double feed = finishing.get(k) ? t.finishFeedMmPerMin() : t.feedMmPerMin();
                // a link through cleared floor no longer than the ramp a retract would need: less feed in air
                if (cursor != null
                        && cursor.distance(s) <= RegionPocket.linkLimitMm(t, entry, above - z)
                        && cleared.clearedAlong(cursor, s, piece)) {
                    moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                } else if (!leadIns.get(k).isEmpty()) {
                    // down through what the first tool cleared beside the piece, then along into it
                    Vec2 e = leadIns.get(k).get(0).start();
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    moves.add(new Move.Rapid(at(e, safe)));
                    moves.add(new Move.Rapid(at(e, above)));
                    moves.add(new Move.Linear(at(e, z), t.feedMmPerMin()));
                    for (Curve2 c : leadIns.get(k)) {
                        RegionPocket.emit(moves, c, z, z, t.feedMmPerMin());
                    }
                } else {
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    moves.add(new Move.Rapid(at(s, safe)));
                    moves.add(new Move.Rapid(at(s, above)));
                    // no helix: the rest lies in corners and necks; a ramp along the piece, judged as into stock
                    Entry down = Entries.choose(
                                    entry,
                                    s,
                                    piece,
                                    List.of(),
                                    climb,
                                    Entries.Room.NONE,
                                    legRoom,
                                    t.radiusMm(),
                                    above - z)
                            .orElseThrow(() -> Entries.tooSmallToGoDown(s));
                    moves.addAll(down.moves(above, z, t.feedMmPerMin()));
                }
                for (Curve2 c : piece) {
                    RegionPocket.emit(moves, c, z, z, feed);
                }
                if (moves.size() > PocketTechnology.MAX_MOVES) {
                    throw new ToolTooLargeException("the program would have more than " + PocketTechnology.MAX_MOVES
                            + " moves: use a larger depth per pass, a larger entry angle or a larger rest tool");
                }
                cleared.cutAlong(piece);
                cursor = piece.get(piece.size() - 1).end();
            }
        }
        moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
        return new ToolpathSection(
                "rest",
                Z,
                t.toolDiameterMm(),
                TOOL_NUMBER,
                t.spindleRpm(),
                new Vec3(s0.x(), s0.y(), safe),
                moves.list());
    }

    /** Whether the circle of tool centres about c lies inside the finishing offset's region. */
    private static boolean holds(List<Contour> faces, Vec2 c, double r) {
        int w = 0;
        for (Contour loop : faces) {
            if (loop.distanceTo(c) < r + 1e-6) {
                return false;
            }
            w += loop.windingNumber(c);
        }
        return w == 1;
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }
}
