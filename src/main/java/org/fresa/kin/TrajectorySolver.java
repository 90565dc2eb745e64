package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * Turns a sequence of tool targets into a joint trajectory with configuration continuity.
 *
 * <p>Each point is solved warm from the previous solution. A point is accepted when the solver
 * converges and no joint moves more than {@link Options#maxJointStepDeg} (revolute) or
 * {@link Options#maxPrismaticStepMm} (prismatic) from the previous point. Otherwise, in order:
 * <ol>
 * <li>the free rotation about the tool axis is changed in small steps (it is also changed when a
 * joint comes within {@link Options#limitMargin} of a limit or the wrist near its singularity);
 * <li>a long move is subdivided into 2, 4, ... 128 straight pieces, each solved warm (the
 * inserted points lie on the straight move, status ok);
 * <li>the point is solved cold and, when that needs another configuration, the thesis's three
 * relink points (section 3.2.3.4) are inserted: the previous point B lifted off the part along
 * the tool axis in B's configuration, the lifted B in the new configuration, and B in the new
 * configuration (status relink), so that the reconfiguration happens away from the part;
 * <li>a point with no solution at all is reported unreachable (no joint values), never as a
 * wrong pose.
 * </ol>
 * Not thread-safe (it owns a solver with work buffers).
 */
public final class TrajectorySolver {

    /**
     * @param ik the inverse-kinematics method and tolerances
     * @param maxJointStepDeg largest revolute joint change between neighbouring ok points
     * @param maxPrismaticStepMm largest prismatic joint change between neighbouring ok points
     * @param liftMm how far the relink points are lifted off the part
     * @param freeRotation whether the turn about the tool axis may be changed
     * @param freeRotationStepDeg the step of such changes between neighbouring points
     * @param maxFreeRotationDeg the largest |turn| from the preferred x direction
     * @param limitMargin fraction of a joint's range kept free at each end when possible
     * @param wristMin the least |sin| of the wrist angle kept when possible
     */
    public record Options(
            IkOptions ik,
            double maxJointStepDeg,
            double maxPrismaticStepMm,
            double liftMm,
            boolean freeRotation,
            double freeRotationStepDeg,
            double maxFreeRotationDeg,
            double limitMargin,
            double wristMin) {

        public static final Options DEFAULT =
                new Options(IkOptions.DEFAULT, 20, 50, 50, true, 5, 180, 0.02, Math.sin(Math.toRadians(2)));

        public Options {
            Objects.requireNonNull(ik, "ik");
        }

        public Options withIk(IkOptions o) {
            return new Options(
                    o,
                    maxJointStepDeg,
                    maxPrismaticStepMm,
                    liftMm,
                    freeRotation,
                    freeRotationStepDeg,
                    maxFreeRotationDeg,
                    limitMargin,
                    wristMin);
        }

        public Options withFreeRotation(boolean on) {
            return new Options(
                    ik,
                    maxJointStepDeg,
                    maxPrismaticStepMm,
                    liftMm,
                    on,
                    freeRotationStepDeg,
                    maxFreeRotationDeg,
                    limitMargin,
                    wristMin);
        }
    }

    /**
     * The trajectory and what it took.
     *
     * @param points the rows, in order
     * @param unreachable rows with status unreachable
     * @param relinks rows with status relink
     * @param subdividedMoves moves split into pieces for continuity
     * @param rotatedPoints ok rows whose tool is turned away from the preferred x direction
     * @param rotationChanges how often the free rotation was changed
     * @param maxFreeRotationDeg largest |turn| used
     * @param notes one sentence each, for the planner
     * @param ikNanos time spent in inverse kinematics
     */
    public record Result(
            List<TrajectoryPoint> points,
            int unreachable,
            int relinks,
            int subdividedMoves,
            int rotatedPoints,
            int rotationChanges,
            double maxFreeRotationDeg,
            List<String> notes,
            long ikNanos) {
        public Result {
            points = List.copyOf(points);
            notes = List.copyOf(notes);
        }
    }

    /** Told after each target; may throw to cancel (e.g. CancellationException). */
    @FunctionalInterface
    public interface Listener {
        void done(int targetsDone, int total);
    }

    private final Options options;
    private final ToolTurns turns;
    /** The robot with the TCP of the current tool, and its solver: a tool change changes both. */
    private Robot robot;

    private IkSolver solver;
    private final List<JointLimit> limits;
    private final java.util.Map<Robot, IkSolver> solvers = new java.util.IdentityHashMap<>();

    private final List<TrajectoryPoint> rows = new ArrayList<>();
    private final List<String> notes = new ArrayList<>();
    private long ikNanos;
    private int subdivided;
    private int rotationChanges;

    public TrajectorySolver(Robot robot, Options options) {
        this.robot = Objects.requireNonNull(robot, "robot");
        this.options = Objects.requireNonNull(options, "options");
        this.turns = ToolTurns.of(options);
        this.solver = robot.newSolver(options.ik());
        this.limits = robot.joints();
        solvers.put(robot, solver);
    }

    private void use(Robot r) {
        if (r.dof() != limits.size()) {
            throw new IllegalArgumentException(
                    "a tool change cannot change the robot: " + r.dof() + " joints for " + limits.size());
        }
        robot = r;
        solver = solvers.computeIfAbsent(r, x -> x.newSolver(options.ik()));
    }

    /** A solved pose: joints and the free rotation used. */
    private record Sol(double[] q, double phi) {}

    public Result solve(List<ToolTarget> targets, Listener listener) {
        return solve(targets, null, listener);
    }

    /**
     * As {@link #solve(List, Listener)}, each target with the robot (the same joints, its own tool
     * frame) that {@code robotOfLabel} gives for its label. Where the robot changes (a tool change)
     * the point is solved cold, in the configuration nearest the previous point's, with no relink:
     * the robot leaves the part to change the tool.
     *
     * @param robotOfLabel the robot carrying the TCP of each label's tool; null keeps the
     *     constructor's robot; must return the same instance for the same tool
     */
    public Result solve(
            List<ToolTarget> targets, java.util.function.Function<String, Robot> robotOfLabel, Listener listener) {
        rows.clear();
        notes.clear();
        ikNanos = 0;
        subdivided = 0;
        rotationChanges = 0;
        Sol prev = null;
        ToolTarget prevTarget = null;
        boolean lastOk = false;
        double phi = 0;
        for (int k = 0; k < targets.size(); k++) {
            ToolTarget t = targets.get(k);
            boolean toolChange = false;
            if (robotOfLabel != null) {
                Robot r = robotOfLabel.apply(t.label());
                if (r != robot) {
                    use(r);
                    toolChange = prev != null;
                }
            }
            Sol s;
            if (prev == null || toolChange) {
                s = cold(t, phi, prev == null ? null : prev.q);
            } else {
                s = next(prevTarget, prev, t);
                if (s == null) {
                    Sol c = cold(t, prev.phi, prev.q);
                    if (c != null && lastOk && !smooth(prev.q, c.q)) {
                        List<Piece> turned = c.phi != prev.phi ? pieces(prevTarget, prev, t, c.phi) : null;
                        if (turned != null) {
                            // the new turn about the tool axis, taken gradually along the move
                            for (int i = 0; i < turned.size() - 1; i++) {
                                add(turned.get(i).target(), turned.get(i).sol(), TrajectoryPoint.Status.OK, true);
                            }
                            subdivided++;
                            c = turned.get(turned.size() - 1).sol();
                        } else {
                            c = relink(prevTarget, prev, t, c);
                        }
                    }
                    s = c;
                }
            }
            if (s == null) {
                rows.add(new TrajectoryPoint(
                        t.label(),
                        t.pose(phi),
                        TrajectoryPoint.Status.UNREACHABLE,
                        new double[0],
                        Optional.empty(),
                        Double.NaN,
                        Double.NaN,
                        phi,
                        false));
                lastOk = false;
            } else {
                add(t, s, TrajectoryPoint.Status.OK, false);
                if (prev != null && s.phi != prev.phi) {
                    rotationChanges++;
                }
                prev = s;
                prevTarget = t;
                phi = s.phi;
                lastOk = true;
            }
            if (listener != null) {
                listener.done(k + 1, targets.size());
            }
        }
        int unreachable = 0;
        int relinks = 0;
        int rotated = 0;
        double maxRot = 0;
        for (TrajectoryPoint p : rows) {
            switch (p.status()) {
                case UNREACHABLE -> unreachable++;
                case RELINK -> relinks++;
                case OK -> {
                    if (Math.abs(p.freeRotationDeg()) > 1e-12) {
                        rotated++;
                    }
                    maxRot = Math.max(maxRot, Math.abs(p.freeRotationDeg()));
                }
            }
        }
        return new Result(rows, unreachable, relinks, subdivided, rotated, rotationChanges, maxRot, notes, ikNanos);
    }

    private void add(ToolTarget t, Sol s, TrajectoryPoint.Status status, boolean inserted) {
        Transform3 target = t.pose(s.phi);
        Transform3 reached = robot.forward(s.q);
        rows.add(new TrajectoryPoint(
                t.label(),
                target,
                status,
                s.q,
                Optional.of(reached),
                reached.translationPart().distance(target.translationPart()),
                target.rotationAngleTo(reached),
                s.phi,
                inserted));
    }

    /** The next point warm from prev, or null when it needs a reconfiguration (or is unreachable). */
    private Sol next(ToolTarget prevTarget, Sol prev, ToolTarget t) {
        Sol direct = warm(t, prev.phi, prev.q);
        if (direct != null && smooth(prev.q, direct.q) && comfortable(direct.q)) {
            return direct;
        }
        if (options.freeRotation()) {
            Sol best = null;
            double bestScore = Double.NEGATIVE_INFINITY;
            for (int step = 1; step <= 3; step++) {
                for (int sign = -1; sign <= 1; sign += 2) {
                    double phi = prev.phi + sign * step * options.freeRotationStepDeg();
                    if (Math.abs(phi) > options.maxFreeRotationDeg()) {
                        continue;
                    }
                    Sol s = warm(t, phi, prev.q);
                    if (s != null && smooth(prev.q, s.q) && comfortable(s.q) && score(s.q) > bestScore) {
                        best = s;
                        bestScore = score(s.q);
                    }
                }
            }
            if (best != null) {
                return best;
            }
        }
        if (direct != null && smooth(prev.q, direct.q)) {
            return direct; // close to a limit or the wrist singularity, but continuous and exact
        }
        return subdivide(prevTarget, prev, t);
    }

    /** A solved target of a subdivided move. */
    private record Piece(ToolTarget target, Sol sol) {}

    /** Subdivides the move and adds the inserted points; the end's solution, or null. */
    private Sol subdivide(ToolTarget a, Sol sa, ToolTarget b) {
        List<Piece> pieces = pieces(a, sa, b);
        if (pieces == null) {
            return null;
        }
        for (int i = 0; i < pieces.size() - 1; i++) {
            add(pieces.get(i).target(), pieces.get(i).sol(), TrajectoryPoint.Status.OK, true);
        }
        if (pieces.size() > 1) {
            subdivided++;
        }
        return pieces.get(pieces.size() - 1).sol();
    }

    /**
     * The straight move from a to b split into 1, 2, 4, ... 128 pieces solved warm in turn, the
     * first split that is continuous; null when none is.
     */
    private List<Piece> pieces(ToolTarget a, Sol sa, ToolTarget b) {
        return pieces(a, sa, b, sa.phi);
    }

    /** As {@link #pieces(ToolTarget, Sol, ToolTarget)}, turning the tool from sa.phi to phiB on the way. */
    private List<Piece> pieces(ToolTarget a, Sol sa, ToolTarget b, double phiB) {
        if (a.toolAxis().dot(b.toolAxis()) < -0.5) {
            return null;
        }
        for (int k = 0; k <= 7; k++) {
            int pieces = 1 << k;
            List<Piece> out = new ArrayList<>();
            Sol cur = sa;
            boolean ok = true;
            for (int i = 1; i <= pieces && ok; i++) {
                double f = (double) i / pieces;
                ToolTarget m = i == pieces ? b : interpolate(a, b, f);
                Sol s = warm(m, sa.phi + (phiB - sa.phi) * f, cur.q);
                ok = s != null && smooth(cur.q, s.q);
                if (ok) {
                    out.add(new Piece(m, s));
                    cur = s;
                } else if (s == null && i == pieces && k >= 2) {
                    return null; // the target itself fails from a quarter of the move away: not a matter of steps
                }
            }
            if (ok) {
                return out;
            }
        }
        return null;
    }

    private static ToolTarget interpolate(ToolTarget a, ToolTarget b, double f) {
        Vec3 axis = a.toolAxis().interpolate(b.toolAxis(), f);
        Vec3 x = a.preferredX().interpolate(b.preferredX(), f);
        if (x.norm() < 1e-9) {
            x = a.preferredX();
        }
        return new ToolTarget(b.label(), a.positionMm().interpolate(b.positionMm(), f), axis, x);
    }

    /**
     * The thesis's three relink points between B (solved as sb) and the new configuration c of
     * target t, then the move from B to t in the new configuration; the solution of t to use.
     */
    private Sol relink(ToolTarget b, Sol sb, ToolTarget t, Sol c) {
        for (double lift = options.liftMm(); lift >= options.liftMm() / 8; lift /= 2) {
            ToolTarget up = b.lifted(lift);
            Sol r1 = warm(up, sb.phi, sb.q);
            Sol r2 = warm(up, c.phi, c.q);
            Sol r3 = warm(b, c.phi, c.q);
            if (r1 == null || r2 == null || r3 == null) {
                continue;
            }
            List<Piece> onward = pieces(b, r3, t);
            if (onward == null) {
                continue;
            }
            add(up, r1, TrajectoryPoint.Status.RELINK, true);
            add(up, r2, TrajectoryPoint.Status.RELINK, true);
            add(b, r3, TrajectoryPoint.Status.RELINK, true);
            for (int i = 0; i < onward.size() - 1; i++) {
                add(onward.get(i).target(), onward.get(i).sol(), TrajectoryPoint.Status.OK, true);
            }
            return onward.get(onward.size() - 1).sol();
        }
        // no continuous way down onto B in the new configuration: change it in the air above B and
        // come down onto the next target instead (B lifted in the old configuration, the next target
        // lifted in the new one), so the reconfiguration still happens away from the part
        for (double lift = options.liftMm(); lift >= options.liftMm() / 8; lift /= 2) {
            ToolTarget upB = b.lifted(lift);
            ToolTarget upT = t.lifted(lift);
            Sol r1 = warm(upB, sb.phi, sb.q);
            Sol r2 = warm(upT, c.phi, c.q);
            if (r1 == null || r2 == null || !smooth(r2.q, c.q)) {
                continue;
            }
            add(upB, r1, TrajectoryPoint.Status.RELINK, true);
            add(upT, r2, TrajectoryPoint.Status.RELINK, true);
            notes.add("configuration change at row " + (rows.size() + 1) + " (" + b.label() + "): relinked in the air"
                    + " above the previous point and came down onto the next one");
            return c;
        }
        notes.add("configuration change at row " + (rows.size() + 1) + " (" + b.label() + ") without relink points:"
                + " no continuous move into the new configuration was found, the joints jump there");
        return c;
    }

    /**
     * Cold solve at the free rotation phi, then (if allowed) at half and quarter turns from it;
     * when some turn has solutions but none clear of limits and singularity, every 20 degrees.
     */
    private Sol cold(ToolTarget t, double phi, double[] reference) {
        Sol[] fallback = new Sol[1];
        double[] fallbackScore = {Double.NEGATIVE_INFINITY};
        Sol nearest = null;
        double nearestDistance = Double.POSITIVE_INFINITY;
        for (double p : turns.firstDeg(robot, phi)) {
            for (Sol s : coldAt(t, p, fallback, fallbackScore)) {
                if (reference == null) {
                    return s;
                }
                double d = distance(reference, s.q);
                if (d < nearestDistance) {
                    nearest = s;
                    nearestDistance = d;
                }
            }
        }
        if (nearest != null) {
            return nearest;
        }
        if (fallback[0] != null && options.freeRotation()) {
            int steps = (int) Math.floor(options.maxFreeRotationDeg() / 20);
            for (int i = 1; i <= 2 * steps; i++) {
                double p = phi + (i % 2 == 1 ? 1 : -1) * ((i + 1) / 2) * 20.0;
                List<Sol> s = coldAt(t, turns.wrapDeg(p), fallback, fallbackScore);
                if (!s.isEmpty()) {
                    return s.get(0);
                }
            }
        }
        return fallback[0];
    }

    /** The largest joint change, revolute in degrees and prismatic scaled to the step limits. */
    private double distance(double[] a, double[] b) {
        double m = 0;
        for (int i = 0; i < a.length; i++) {
            double scale = limits.get(i).type() == JointType.REVOLUTE
                    ? 1
                    : options.maxJointStepDeg() / options.maxPrismaticStepMm();
            m = Math.max(m, Math.abs(a[i] - b[i]) * scale);
        }
        return m;
    }

    /** The comfortable cold solutions at turn p (remembering the best other one). */
    private List<Sol> coldAt(ToolTarget t, double p, Sol[] fallback, double[] fallbackScore) {
        long t0 = System.nanoTime();
        List<IkResult.Converged> all = solver.solveAll(t.pose(p));
        ikNanos += System.nanoTime() - t0;
        List<Sol> out = new ArrayList<>();
        for (IkResult.Converged c : all) {
            if (comfortable(c.q())) {
                out.add(new Sol(c.q(), p));
                continue;
            }
            double sc = score(c.q());
            if (sc > fallbackScore[0]) {
                fallback[0] = new Sol(c.q(), p);
                fallbackScore[0] = sc;
            }
        }
        return out;
    }

    private Sol warm(ToolTarget t, double phi, double[] seed) {
        long t0 = System.nanoTime();
        IkResult r = solver.solve(t.pose(phi), seed);
        ikNanos += System.nanoTime() - t0;
        return r instanceof IkResult.Converged c ? new Sol(c.q(), phi) : null;
    }

    private boolean smooth(double[] a, double[] b) {
        for (int i = 0; i < a.length; i++) {
            double max = limits.get(i).type() == JointType.REVOLUTE
                    ? options.maxJointStepDeg()
                    : options.maxPrismaticStepMm();
            if (Math.abs(a[i] - b[i]) > max) {
                return false;
            }
        }
        return true;
    }

    private double margin(double[] q) {
        double m = Double.POSITIVE_INFINITY;
        for (int i = 0; i < q.length; i++) {
            m = Math.min(m, limits.get(i).margin(q[i]));
        }
        return m;
    }

    private boolean comfortable(double[] q) {
        return margin(q) >= options.limitMargin() && robot.wristConditioning(q) >= options.wristMin();
    }

    private double score(double[] q) {
        return margin(q) + 0.2 * Math.min(robot.wristConditioning(q), 0.3);
    }
}
