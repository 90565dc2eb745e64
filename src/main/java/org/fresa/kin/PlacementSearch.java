package org.fresa.kin;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.function.Function;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * Where to put the table so that the robot reaches every target of a part: the search behind
 * {@code fresa robot --place auto}. It moves the table (x, y, z in the robot base frame and a turn
 * about the vertical) and keeps the placement that reaches every target with the largest
 * joint-limit margin: the least, over the targets, of the best margin a solution of that target
 * has (each joint's distance to its nearer limit as a fraction of its range).
 *
 * <p>A target counts as reached when a cold solve finds a solution within the limits at one of
 * the turns about the tool axis the trajectory solver tries first (0, 180, 90 and -90 degrees
 * for a robot that controls the full orientation). The search is coarse to fine, each step on a
 * sample of the targets (per workingstep its extreme points, and an even spread of the rest):
 * <ol>
 * <li>a grid over the robot's workspace (its box from the forward kinematics of random joint
 * values) times eight turns of the table, the sample's centre put on each grid point;
 * <li>a pattern search from the best few, halving its steps down to 5 mm and 2 degrees;
 * <li>every target for the best placements found.
 * </ol>
 * A candidate stops being solved as soon as it cannot beat the placements kept, and the target
 * that stopped it is solved first for the next one. When no placement tried reaches everything,
 * each workingstep left out is searched alone: the result says which stay out of reach from every
 * placement tried and which are reachable alone but not together with the rest. Never a partial
 * placement as an answer: {@link Result#found()} is empty then.
 *
 * <p>Pure computation; not thread-safe (it owns solvers).
 */
public final class PlacementSearch {

    /** The turns of the table about the vertical tried on the grid (deg). */
    private static final int GRID_TURNS = 8;
    /** Grid points per axis of the workspace box. */
    private static final int GRID_STEPS = 7;
    /** Where the pattern search stops refining. */
    private static final double FINEST_MM = 5;

    private static final double FINEST_DEG = 2;
    /** How many grid placements the pattern search starts from. */
    private static final int REFINED = 3;
    /** Targets of the even spread in the sample, besides each workingstep's extreme points. */
    private static final int SPREAD = 48;
    /** Random joint configurations whose tool positions give the workspace box. */
    private static final int WORKSPACE_SAMPLES = 4000;

    /**
     * The table origin in the robot base frame: a position and a turn about the vertical (the
     * {@code --robot-table X,Y,Z,RZ} of the command line).
     */
    public record TablePlacement(double xMm, double yMm, double zMm, double rzDeg) {
        public TablePlacement {
            if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !Double.isFinite(zMm) || !Double.isFinite(rzDeg)) {
                throw new IllegalArgumentException("a placement is finite");
            }
        }

        public Transform3 toTransform() {
            return Transform3.ofXyzRpyDeg(xMm, yMm, zMm, 0, 0, rzDeg);
        }
    }

    /**
     * What the search found.
     *
     * @param found the placement reaching every target, empty when none tried does
     * @param best the best placement tried (the found one, or the one reaching the most targets)
     * @param targets the number of targets
     * @param reached targets reached from {@code best}
     * @param minMargin the least joint-limit margin (fraction of a range) over the targets reached from best
     * @param outOfReachEverywhere workingsteps (labels) that no placement tried reaches whole, in
     *     the order of the targets
     * @param notTogether workingsteps left out at {@code best} that some placement reaches alone
     * @param placementsTried placements whose targets (or a sample of them) were solved
     * @param notes why, in a sentence each (a robot whose tool axis cannot turn)
     */
    public record Result(
            Optional<TablePlacement> found,
            TablePlacement best,
            int targets,
            int reached,
            double minMargin,
            List<String> outOfReachEverywhere,
            List<String> notTogether,
            int placementsTried,
            List<String> notes) {
        public Result {
            Objects.requireNonNull(found, "found");
            Objects.requireNonNull(best, "best");
            outOfReachEverywhere = List.copyOf(outOfReachEverywhere);
            notTogether = List.copyOf(notTogether);
            notes = List.copyOf(notes);
        }
    }

    /** Told how far the search is; may throw (a CancellationException) to stop it. */
    @FunctionalInterface
    public interface Progress {
        void at(double fraction, String what);
    }

    /**
     * @param cellMm each coordinate of a placement stays within +-cellMm
     */
    public record Bounds(double cellMm) {
        public Bounds {
            if (!(cellMm > 0)) {
                throw new IllegalArgumentException("the cell size must be > 0: " + cellMm);
            }
        }
    }

    private final Robot robot;
    private final Function<String, Robot> robotOfLabel;
    private final Bounds bounds;
    private final Map<Robot, IkSolver> solvers = new IdentityHashMap<>();
    private final double[] turnsDeg;
    private int tried;
    /** Told again now and then while a long step runs, so that it may be cancelled. */
    private Progress progress = (f, w) -> {};

    private double fraction;
    private String what = "";
    private int ticks;

    /**
     * @param robot the robot (with the tool frame of workingsteps not in robotOfLabel)
     * @param robotOfLabel the robot carrying each workingstep's tool frame
     */
    public PlacementSearch(Robot robot, Function<String, Robot> robotOfLabel, Bounds bounds) {
        this(robot, robotOfLabel, bounds, ToolTurns.of(TrajectorySolver.Options.DEFAULT));
    }

    /**
     * @param robot the robot (with the tool frame of workingsteps not in robotOfLabel)
     * @param robotOfLabel the robot carrying each workingstep's tool frame
     * @param turns the turns about the tool axis the trajectory will try (the search tries the same)
     */
    public PlacementSearch(Robot robot, Function<String, Robot> robotOfLabel, Bounds bounds, ToolTurns turns) {
        this.robot = Objects.requireNonNull(robot, "robot");
        this.robotOfLabel = Objects.requireNonNull(robotOfLabel, "robotOfLabel");
        this.bounds = Objects.requireNonNull(bounds, "bounds");
        turnsDeg = turns.firstDeg(robot, 0).stream()
                .mapToDouble(Double::doubleValue)
                .toArray();
    }

    /** The score of a placement on some targets: fewer failures first, then the larger margin. */
    private record Score(int failures, double margin, boolean complete) {
        boolean betterThan(Score o) {
            return failures < o.failures || failures == o.failures && margin > o.margin;
        }
    }

    private record Candidate(TablePlacement placement, Score score) {}

    /** One target in the table frame with its solver, for placing again and again. */
    private final class Target {
        final ToolTarget inTable;
        final IkSolver solver;
        final List<JointLimit> limits;

        Target(ToolTarget t) {
            inTable = t;
            Robot r = robotOfLabel.apply(t.label());
            solver = solvers.computeIfAbsent(r, x -> x.newSolver(IkOptions.DEFAULT));
            limits = r.joints();
        }

        /** The best margin of a solution from this placement, or NaN when out of reach. */
        double margin(Transform3 table) {
            ToolTarget placed = new ToolTarget(
                    inTable.label(),
                    table.applyToPoint(inTable.positionMm()),
                    table.applyToDirection(inTable.toolAxis()),
                    table.applyToDirection(inTable.preferredX()));
            double best = Double.NaN;
            for (double turn : turnsDeg) {
                List<IkResult.Converged> all = solver.solveAllQuickly(placed.pose(turn));
                for (IkResult.Converged c : all) {
                    double m = Double.POSITIVE_INFINITY;
                    for (int i = 0; i < limits.size(); i++) {
                        m = Math.min(m, limits.get(i).margin(c.q()[i]));
                    }
                    if (!(m <= best)) {
                        best = m;
                    }
                }
            }
            return best;
        }
    }

    /** The targets in an order that is moved: the one that stopped a candidate comes first next time. */
    private static final class Ordered {
        final List<Target> targets;

        Ordered(List<Target> targets) {
            this.targets = new ArrayList<>(targets);
        }

        void first(int index) {
            if (index > 0) {
                targets.add(0, targets.remove(index));
            }
        }
    }

    /**
     * Searches.
     *
     * @param inTable the part's targets in the table frame (the table-to-piece placement applied)
     */
    public Result search(List<ToolTarget> inTable, Progress told) {
        if (inTable.isEmpty()) {
            throw new IllegalArgumentException("no targets to place");
        }
        tried = 0;
        this.progress = (f, w) -> {
            fraction = f;
            what = w;
            told.at(f, w);
        };
        Progress progress = this.progress;
        progress.at(0, "placement search: the robot's workspace");
        Workspace ws = workspace();
        // a target whose tool axis the robot never takes (a SCARA's is vertical) is out of reach
        // from every placement: a turn of the table about the vertical keeps a vertical axis vertical
        List<Target> all = new ArrayList<>();
        Set<String> wrongAxis = new LinkedHashSet<>();
        for (ToolTarget t : inTable) {
            if (ws.axisTaken(t.toolAxis())) {
                all.add(new Target(t));
            } else {
                wrongAxis.add(t.label());
            }
        }
        List<String> notes = new ArrayList<>();
        if (!wrongAxis.isEmpty()) {
            Vec3 a = ws.axes.get(0);
            notes.add(String.format(
                    java.util.Locale.ROOT,
                    "the tool axis of %s is always (%.3g, %.3g, %.3g)%s: %d" + " workingsteps need another",
                    robot.name(),
                    a.x(),
                    a.y(),
                    a.z(),
                    ws.axes.size() > 1 ? " or the" + " opposite" : "",
                    wrongAxis.size()));
        }
        if (all.isEmpty()) {
            TablePlacement origin = new TablePlacement(0, 0, 0, 0);
            return new Result(
                    Optional.empty(),
                    origin,
                    inTable.size(),
                    0,
                    Double.NaN,
                    List.copyOf(wrongAxis),
                    List.of(),
                    0,
                    notes);
        }
        Ordered sample = new Ordered(sample(all));
        double[][] box = ws.box;
        Vec3 centre = centre(sample.targets);
        List<TablePlacement> grid = grid(box, centre);
        // 1. the grid, keeping the best few
        List<Candidate> kept = new ArrayList<>();
        for (int k = 0; k < grid.size(); k++) {
            if ((k & 63) == 0) {
                progress.at(0.6 * k / grid.size(), "placement search: " + k + " of " + grid.size() + " placements");
            }
            Score bound =
                    kept.size() < REFINED ? null : kept.get(kept.size() - 1).score();
            Score s = evaluate(grid.get(k), sample, bound);
            if (s.complete() && (bound == null || s.betterThan(bound))) {
                kept.add(new Candidate(grid.get(k), s));
                kept.sort(Comparator.comparing(Candidate::score, PlacementSearch::compare));
                if (kept.size() > REFINED) {
                    kept.remove(kept.size() - 1);
                }
            }
        }
        // 2. the pattern search from each of them
        double stepMm = Math.max(FINEST_MM, (box[1][0] - box[0][0]) / (GRID_STEPS - 1) / 2);
        List<Candidate> refined = new ArrayList<>();
        for (int k = 0; k < kept.size(); k++) {
            progress.at(0.6 + 0.2 * k / kept.size(), "placement search: refining");
            refined.add(refine(kept.get(k), sample, stepMm));
        }
        refined.addAll(kept);
        refined.sort(Comparator.comparing(Candidate::score, PlacementSearch::compare));
        // 3. every target for the best
        progress.at(0.8, "placement search: every target");
        Ordered every = new Ordered(all);
        Candidate best = null;
        for (Candidate c : refined) {
            Score s = evaluate(c.placement(), every, best == null ? null : best.score());
            if (s.complete() && (best == null || s.betterThan(best.score()))) {
                best = new Candidate(c.placement(), s);
            }
        }
        if (best == null) {
            // nothing came out of the grid with a complete score (no candidate at all): say so plainly
            TablePlacement origin = new TablePlacement(0, 0, 0, 0);
            best = new Candidate(origin, evaluate(origin, every, null));
        }
        if (best.score().failures() == 0 && wrongAxis.isEmpty()) {
            return new Result(
                    Optional.of(best.placement()),
                    best.placement(),
                    all.size(),
                    all.size(),
                    best.score().margin(),
                    List.of(),
                    List.of(),
                    tried,
                    notes);
        }
        // the workingsteps left out at the best placement, each searched alone
        progress.at(0.9, "placement search: the workingsteps out of reach");
        Transform3 bt = best.placement().toTransform();
        Set<String> leftOut = new LinkedHashSet<>();
        for (Target t : all) {
            if (Double.isNaN(t.margin(bt))) {
                leftOut.add(t.inTable.label());
            }
        }
        List<String> nowhere = new ArrayList<>(wrongAxis);
        List<String> alone = new ArrayList<>();
        Map<String, List<Target>> byLabel = new LinkedHashMap<>();
        for (Target t : all) {
            byLabel.computeIfAbsent(t.inTable.label(), x -> new ArrayList<>()).add(t);
        }
        List<TablePlacement> everyTried = new ArrayList<>(grid);
        for (Candidate c : refined) {
            everyTried.add(c.placement());
        }
        for (String label : leftOut) {
            if (wrongAxis.contains(label)) {
                continue;
            }
            progress.at(0.9, "placement search: " + label + " alone");
            if (reachableAlone(byLabel.get(label), everyTried)) {
                alone.add(label);
            } else {
                nowhere.add(label);
            }
        }
        // in the order of the targets
        List<String> order = new ArrayList<>();
        for (ToolTarget t : inTable) {
            if ((nowhere.contains(t.label())) && !order.contains(t.label())) {
                order.add(t.label());
            }
        }
        return new Result(
                Optional.empty(),
                best.placement(),
                inTable.size(),
                all.size() - best.score().failures(),
                best.score().margin(),
                order,
                alone,
                tried,
                notes);
    }

    /** Every target solved from one placement: found when all are reached. */
    public Result check(List<ToolTarget> inTable, TablePlacement p) {
        List<Target> all = new ArrayList<>();
        for (ToolTarget t : inTable) {
            all.add(new Target(t));
        }
        Score s = evaluate(p, new Ordered(all), null);
        return new Result(
                s.failures() == 0 ? Optional.of(p) : Optional.empty(),
                p,
                all.size(),
                all.size() - s.failures(),
                s.margin(),
                List.of(),
                List.of(),
                1,
                List.of());
    }

    private static int compare(Score a, Score b) {
        return a.betterThan(b) ? -1 : b.betterThan(a) ? 1 : 0;
    }

    /** Whether some placement reaches every target of one workingstep (its sample first). */
    private boolean reachableAlone(List<Target> targets, List<TablePlacement> placements) {
        Ordered sample = new Ordered(sample(targets));
        Ordered every = new Ordered(targets);
        Score none = new Score(0, Double.NEGATIVE_INFINITY, true);
        for (TablePlacement p : placements) {
            if (evaluate(p, sample, none).complete() && evaluate(p, every, none).complete()) {
                return true;
            }
        }
        return false;
    }

    /**
     * The score of a placement on the targets, solved in their order; stops (incomplete) as soon
     * as it cannot beat {@code bound}, and moves the target that stopped it to the front.
     */
    private Score evaluate(TablePlacement p, Ordered targets, Score bound) {
        tried++;
        Transform3 table = p.toTransform();
        int failures = 0;
        double margin = Double.POSITIVE_INFINITY;
        List<Target> list = targets.targets;
        for (int i = 0; i < list.size(); i++) {
            if ((++ticks & 255) == 0) {
                progress.at(fraction, what);
            }
            double m = list.get(i).margin(table);
            if (Double.isNaN(m)) {
                failures++;
            } else if (m < margin) {
                margin = m;
            } else {
                continue;
            }
            if (bound != null
                    && (failures > bound.failures() || failures == bound.failures() && margin <= bound.margin())) {
                targets.first(i);
                return new Score(failures, margin, false);
            }
        }
        return new Score(failures, margin, true);
    }

    /** A pattern search: each coordinate moved by a step either way while that improves, then half the steps. */
    private Candidate refine(Candidate start, Ordered sample, double stepMm) {
        Candidate cur = start;
        double mm = stepMm;
        double deg = 360.0 / GRID_TURNS / 2;
        while (mm >= FINEST_MM || deg >= FINEST_DEG) {
            boolean moved = false;
            for (int axis = 0; axis < 4; axis++) {
                for (int sign = -1; sign <= 1; sign += 2) {
                    TablePlacement p = cur.placement();
                    double dm = axis < 3 && mm >= FINEST_MM ? sign * mm : 0;
                    double dd = axis == 3 && deg >= FINEST_DEG ? sign * deg : 0;
                    if (dm == 0 && dd == 0) {
                        continue;
                    }
                    TablePlacement q = new TablePlacement(
                            p.xMm() + (axis == 0 ? dm : 0),
                            p.yMm() + (axis == 1 ? dm : 0),
                            p.zMm() + (axis == 2 ? dm : 0),
                            halfTurn(p.rzDeg() + dd));
                    if (!inCell(q)) {
                        continue;
                    }
                    Score s = evaluate(q, sample, cur.score());
                    if (s.complete() && s.betterThan(cur.score())) {
                        cur = new Candidate(q, s);
                        moved = true;
                    }
                }
            }
            if (!moved) {
                mm /= 2;
                deg /= 2;
            }
        }
        return cur;
    }

    /** The angle in (-180, 180]. */
    private static double halfTurn(double deg) {
        double d = deg % 360;
        return d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
    }

    private boolean inCell(TablePlacement p) {
        double c = bounds.cellMm();
        return Math.abs(p.xMm()) <= c && Math.abs(p.yMm()) <= c && Math.abs(p.zMm()) <= c;
    }

    /** Each workingstep's extreme points along +-x, +-y, +-z, then an even spread of the rest. */
    private static List<Target> sample(List<Target> all) {
        Map<String, Target[]> extremes = new LinkedHashMap<>();
        for (Target t : all) {
            Target[] e = extremes.computeIfAbsent(t.inTable.label(), x -> new Target[6]);
            Vec3 p = t.inTable.positionMm();
            double[] v = {p.x(), -p.x(), p.y(), -p.y(), p.z(), -p.z()};
            for (int i = 0; i < 6; i++) {
                if (e[i] == null) {
                    e[i] = t;
                } else {
                    Vec3 o = e[i].inTable.positionMm();
                    double[] w = {o.x(), -o.x(), o.y(), -o.y(), o.z(), -o.z()};
                    if (v[i] > w[i]) {
                        e[i] = t;
                    }
                }
            }
        }
        Set<Target> out = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
        List<Target> ordered = new ArrayList<>();
        for (Target[] e : extremes.values()) {
            for (Target t : e) {
                if (out.add(t)) {
                    ordered.add(t);
                }
            }
        }
        int stride = Math.max(1, all.size() / SPREAD);
        for (int i = stride / 2; i < all.size(); i += stride) {
            if (out.add(all.get(i))) {
                ordered.add(all.get(i));
            }
        }
        return ordered;
    }

    private static Vec3 centre(List<Target> targets) {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (Target t : targets) {
            Vec3 p = t.inTable.positionMm();
            double[] v = {p.x(), p.y(), p.z()};
            for (int i = 0; i < 3; i++) {
                lo[i] = Math.min(lo[i], v[i]);
                hi[i] = Math.max(hi[i], v[i]);
            }
        }
        return new Vec3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    }

    /**
     * The robot's workspace from the forward kinematics of random joint values within the limits.
     *
     * @param box the box (min, max corners) of the tool positions
     * @param axes the tool axes when the robot takes one or two opposite ones only (and that axis
     *     is vertical), else empty
     */
    private record Workspace(double[][] box, List<Vec3> axes) {
        boolean axisTaken(Vec3 axis) {
            if (axes.isEmpty()) {
                return true;
            }
            for (Vec3 a : axes) {
                if (a.distance(axis) <= FIXED_AXIS) {
                    return true;
                }
            }
            return false;
        }
    }

    /** Tool axes this close (unit vectors) are the same; a SCARA's differ by rounding only. */
    private static final double FIXED_AXIS = 1e-6;

    private Workspace workspace() {
        SplittableRandom rnd = new SplittableRandom(20161027L);
        List<JointLimit> js = robot.joints();
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double[] q = new double[js.size()];
        List<Vec3> axes = new ArrayList<>();
        boolean fixed = true;
        for (int k = 0; k < WORKSPACE_SAMPLES; k++) {
            for (int i = 0; i < q.length; i++) {
                q[i] = js.get(i).min()
                        + rnd.nextDouble() * (js.get(i).max() - js.get(i).min());
            }
            Transform3 pose;
            try {
                pose = robot.forward(q);
            } catch (IllegalArgumentException e) {
                continue; // joint values without an assembly (a parallel robot's legs)
            }
            Vec3 p = pose.translationPart();
            double[] v = {p.x(), p.y(), p.z()};
            for (int i = 0; i < 3; i++) {
                lo[i] = Math.min(lo[i], v[i]);
                hi[i] = Math.max(hi[i], v[i]);
            }
            Vec3 z = pose.zAxis();
            if (fixed && axes.stream().noneMatch(a -> a.distance(z) <= FIXED_AXIS)) {
                axes.add(z);
                fixed = axes.size() <= 2;
            }
        }
        if (!(lo[0] <= hi[0])) {
            throw new IllegalStateException("no joint values of " + robot.name() + " have a pose");
        }
        boolean vertical = fixed && axes.stream().allMatch(a -> Math.abs(Math.abs(a.z()) - 1) <= FIXED_AXIS);
        return new Workspace(new double[][] {lo, hi}, vertical ? axes : List.of());
    }

    /** The grid: the sample's centre on each point of the workspace box, at each table turn. */
    private List<TablePlacement> grid(double[][] box, Vec3 centre) {
        List<TablePlacement> out = new ArrayList<>();
        for (int turn = 0; turn < GRID_TURNS; turn++) {
            double rz = turn * 360.0 / GRID_TURNS;
            Vec3 c = Transform3.rotZ(rz).applyToDirection(centre);
            for (int ix = 0; ix < GRID_STEPS; ix++) {
                for (int iy = 0; iy < GRID_STEPS; iy++) {
                    for (int iz = 0; iz < GRID_STEPS; iz++) {
                        double[] w = new double[3];
                        int[] idx = {ix, iy, iz};
                        for (int i = 0; i < 3; i++) {
                            w[i] = box[0][i] + (box[1][i] - box[0][i]) * idx[i] / (GRID_STEPS - 1);
                        }
                        TablePlacement p =
                                new TablePlacement(w[0] - c.x(), w[1] - c.y(), w[2] - c.z(), rz > 180 ? rz - 360 : rz);
                        if (inCell(p)) {
                            out.add(p);
                        }
                    }
                }
            }
        }
        return out;
    }
}
