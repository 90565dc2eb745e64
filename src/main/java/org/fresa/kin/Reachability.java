package org.fresa.kin;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.function.Function;
import org.fresa.geom.Transform3;

/**
 * Which targets of a list the robot reaches, with one joint solution each: what a planner needs
 * to see while moving the part about the cell, long before the trajectory (continuity, relinks)
 * is worked out. One solution per target is enough. An arm with a closed form gets it directly:
 * the closed-form solution within the limits nearest the last target's, polished (and so
 * checked); other arms solve warm from the last target's solution, and cold
 * ({@link IkSolver#solveAll}) where that fails. A target with no solution at the tool's turn
 * about its axis is tried at the turns the trajectory solver tries first (half a turn and both
 * quarter turns). So an unreachable target costs four closed-form evaluations, not the generic
 * start configurations that make most of its time in {@link IkSolver#solveAll}; a target this
 * calls unreachable is unreachable at those four turns, and the trajectory solver tries no others
 * for a target without any solution.
 *
 * <p>Not thread-safe: one instance per thread. {@link #check} stops early, returning empty,
 * when told its result is no longer wanted.
 */
public final class Reachability {

    private final IkOptions options;
    private final ToolTurns turns;
    private final Map<Robot, Arm> arms = new IdentityHashMap<>();
    private final double[] pose = new double[Pose.SIZE];

    /** Checks with the IK method, tolerances and tool turns the trajectory will be solved with. */
    public Reachability(TrajectorySolver.Options options) {
        this(options.ik(), ToolTurns.of(options));
    }

    /**
     * @param options the IK method and tolerances (as the trajectory will be solved)
     * @param turns the turns about the tool axis allowed (as the trajectory will use them)
     */
    public Reachability(IkOptions options, ToolTurns turns) {
        this.options = Objects.requireNonNull(options, "options");
        this.turns = Objects.requireNonNull(turns, "turns");
    }

    /**
     * Solves every target: status ok with its joints and reached pose, or unreachable. No relinks,
     * no inserted points; the result has one point per target, in order.
     *
     * @param robotOfLabel the robot carrying each label's TCP (the same instance for the same tool)
     * @param stale asked between targets: true stops the check, which then returns empty
     */
    public Optional<TrajectorySolver.Result> check(
            List<ToolTarget> targets, Function<String, Robot> robotOfLabel, BooleanSupplier stale) {
        long t0 = System.nanoTime();
        List<TrajectoryPoint> points = new ArrayList<>(targets.size());
        double[] prev = null;
        double phi = 0;
        int unreachable = 0;
        int rotated = 0;
        double maxRot = 0;
        for (int k = 0; k < targets.size(); k++) {
            if ((k & 63) == 0 && stale.getAsBoolean()) {
                return Optional.empty();
            }
            ToolTarget t = targets.get(k);
            Robot robot = robotOfLabel.apply(t.label());
            Arm arm = arm(robot);
            IkSolver solver = arm.solver();
            double[] q = null;
            double at = phi;
            // the target at the last target's turn, replaced by the turn at which it is reached
            Transform3 target = t.pose(phi);
            // an arm with a closed form gets its solutions directly, the one nearest the last polished:
            // cheaper than a warm solve, which spends up to its iteration limit on an unreachable target
            if (prev != null && arm.dof() == prev.length && arm.closedForm().isEmpty()) {
                IkResult r = solver.solve(target, prev);
                if (r instanceof IkResult.Converged c) {
                    q = c.q();
                }
            }
            if (q == null) {
                for (double turn : turns.firstDeg(robot, phi)) {
                    Transform3 pose = turn == phi ? target : t.pose(turn);
                    q = cold(robot, arm, pose, prev);
                    if (q != null) {
                        at = turn;
                        target = pose;
                        break;
                    }
                }
            }
            if (q == null) {
                unreachable++;
                points.add(new TrajectoryPoint(
                        t.label(),
                        target,
                        TrajectoryPoint.Status.UNREACHABLE,
                        new double[0],
                        Optional.empty(),
                        Double.NaN,
                        Double.NaN,
                        at,
                        false));
                continue;
            }
            Transform3 reached = robot.forward(q);
            points.add(new TrajectoryPoint(
                    t.label(),
                    target,
                    TrajectoryPoint.Status.OK,
                    q,
                    Optional.of(reached),
                    reached.translationPart().distance(target.translationPart()),
                    target.rotationAngleTo(reached),
                    at,
                    false));
            if (Math.abs(at) > 1e-12) {
                rotated++;
                maxRot = Math.max(maxRot, Math.abs(at));
            }
            prev = q;
            phi = at;
        }
        return Optional.of(new TrajectorySolver.Result(
                points, unreachable, 0, 0, rotated, 0, maxRot, List.of(), System.nanoTime() - t0));
    }

    /**
     * What the check asks of a robot for every target, worked out once: a robot's joint list (and
     * so its number of joints) is built anew at each call, which cost a sixth of the check.
     */
    private record Arm(IkSolver solver, int dof, Optional<SphericalWristSeeds> closedForm) {}

    private Arm arm(Robot robot) {
        Arm a = arms.get(robot);
        if (a == null) {
            a = new Arm(
                    robot.newSolver(options),
                    robot.dof(),
                    robot instanceof SerialRobot s && options.method() == IkOptions.Method.LEVENBERG_MARQUARDT
                            ? SphericalWristSeeds.of(s.chain())
                            : Optional.empty());
            arms.put(robot, a);
        }
        return a;
    }

    /**
     * One cold solution (deg / mm), the nearest to prev when there are several; null when none. With
     * a closed form its solutions within the limits are polished (and so checked) nearest first
     * until one converges.
     */
    private double[] cold(Robot robot, Arm arm, Transform3 target, double[] prev) {
        IkSolver solver = arm.solver();
        Optional<SphericalWristSeeds> closed = arm.closedForm();
        if (closed.isEmpty()) {
            List<IkResult.Converged> all = solver.solveAll(target);
            return all.isEmpty()
                    ? null
                    : nearest(all.stream().map(IkResult.Converged::q).toList(), prev);
        }
        DenavitHartenbergChain chain = ((SerialRobot) robot).chain();
        Pose.fromTransform(target, pose, 0);
        List<double[]> inLimits = new ArrayList<>();
        // a closed-form value on a limit up to rounding is on it
        for (double[] s : closed.get().solutionsWithinLimits(pose, 1e-9)) {
            inLimits.add(chain.toUser(s));
        }
        while (!inLimits.isEmpty()) {
            double[] seed = nearest(inLimits, prev);
            if (solver.solve(target, seed) instanceof IkResult.Converged c) {
                return c.q();
            }
            inLimits.remove(seed);
        }
        return null;
    }

    private static double[] nearest(List<double[]> qs, double[] prev) {
        if (prev == null || qs.size() == 1) {
            return qs.get(0);
        }
        double[] best = null;
        double bestD = Double.POSITIVE_INFINITY;
        for (double[] q : qs) {
            double d = 0;
            for (int i = 0; i < q.length && i < prev.length; i++) {
                d = Math.max(d, Math.abs(q[i] - prev[i]));
            }
            if (d < bestD) {
                best = q;
                bestD = d;
            }
        }
        return best;
    }
}
