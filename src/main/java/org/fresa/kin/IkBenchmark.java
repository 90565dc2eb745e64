package org.fresa.kin;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * A short inverse-kinematics benchmark: a bidirectional zig-zag of 3131 points over
 * 60 x 100 mm with the tool pointing down, solved warm from the previous point to 1e-7 mm and
 * 1e-9 rad (full 6-D). Reports the median time per point over repeated rounds, after warm-up
 * rounds for the JIT. No output of its own: {@code fresa bench} and the test harness print.
 */
public final class IkBenchmark {

    private IkBenchmark() {}

    /**
     * @param usPerPoint median wall-clock microseconds per point
     * @param cpuUsPerPoint median thread CPU microseconds per point (on a loaded machine the
     *     wall clock also counts time the thread waited for a core)
     * @param points points per round
     * @param failures points that did not converge in the last round
     * @param maxPosErrMm largest position residual of the last round
     * @param maxRotErrRad largest orientation residual of the last round
     * @param meanIterations mean solver iterations per point (last round)
     */
    public record Figure(
            double usPerPoint,
            double cpuUsPerPoint,
            int points,
            int failures,
            double maxPosErrMm,
            double maxRotErrRad,
            double meanIterations) {}

    /** The zig-zag path: rows 2 mm apart along y, 0.1 mm point spacing along x, in a plane. */
    public static List<Transform3> zigZag(Vec3 corner) {
        List<Transform3> out = new ArrayList<>();
        int rows = 31;
        int perRow = 101;
        for (int r = 0; r < rows; r++) {
            for (int k = 0; k < perRow; k++) {
                double x = (r % 2 == 0 ? k : perRow - 1 - k) * 0.6;
                double y = r * 100.0 / (rows - 1);
                out.add(new Transform3(1, 0, 0, 0, -1, 0, 0, 0, -1, corner.x() + x, corner.y() + y, corner.z()));
            }
        }
        return out.subList(0, Math.min(out.size(), 3131));
    }

    public static Figure irb140(int rounds) {
        return run(Robots.irb140(), zigZag(new Vec3(420, -50, 300)), rounds);
    }

    public static Figure tricept806(int rounds) {
        return run(Robots.tricept806(), zigZag(new Vec3(150, 250, -1700)), rounds);
    }

    /**
     * Cold solves (every solution branch, no seed) of the IRB-140 zig-zag's points, one in seven:
     * the median CPU microseconds per pose over the rounds, after a warm-up of at least 2 s.
     */
    public static double irb140ColdCpuUsPerPose(int rounds) {
        IkSolver solver = Robots.irb140().newSolver(IkOptions.DEFAULT);
        List<Transform3> all = zigZag(new Vec3(420, -50, 300));
        List<Transform3> path = new ArrayList<>();
        for (int i = 0; i < all.size(); i += 7) {
            path.add(all.get(i));
        }
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        double[] cpu = new double[rounds];
        long warmStart = System.nanoTime();
        int found = 0;
        for (int round = -Math.max(3, rounds / 2); round < rounds; round++) {
            if (round == -1 && System.nanoTime() - warmStart < 2_000_000_000L) {
                round = -2;
            }
            long c0 = mx.getCurrentThreadCpuTime();
            found = 0;
            for (Transform3 t : path) {
                found += solver.solveAll(t).isEmpty() ? 0 : 1;
            }
            if (round >= 0) {
                cpu[round] = (mx.getCurrentThreadCpuTime() - c0) / 1e3 / path.size();
            }
        }
        if (found != path.size()) {
            throw new IllegalStateException("cold IK found no solution for " + (path.size() - found) + " poses");
        }
        Arrays.sort(cpu);
        return cpu[rounds / 2];
    }

    /** Warm-start solves along the path; the first point is solved cold (not timed). */
    public static Figure run(Robot robot, List<Transform3> path, int rounds) {
        IkSolver solver = robot.newSolver(IkOptions.DEFAULT);
        IkResult first = solver.solveCold(path.get(0));
        if (!(first instanceof IkResult.Converged c0)) {
            throw new IllegalArgumentException("the benchmark path's first point is unreachable for " + robot.name());
        }
        double[] start = c0.q();
        int warmup = Math.max(3, rounds / 2);
        double[] times = new double[rounds];
        double[] cpu = new double[rounds];
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        int failures = 0;
        double maxPos = 0;
        double maxRot = 0;
        long iterations = 0;
        // warm-up: at least that many rounds and 2 s, so that the JIT has compiled the solver even
        // when other processes starve its compiler threads
        long warmStart = System.nanoTime();
        for (int round = -warmup; round < rounds; round++) {
            if (round == -1 && System.nanoTime() - warmStart < 2_000_000_000L) {
                round = -2;
            }
            double[] seed = start;
            failures = 0;
            maxPos = 0;
            maxRot = 0;
            iterations = 0;
            long cpu0 = mx.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            for (Transform3 t : path) {
                IkResult r = solver.solve(t, seed);
                iterations += r.iterations();
                if (r instanceof IkResult.Converged c) {
                    seed = c.q();
                    maxPos = Math.max(maxPos, c.posErrMm());
                    maxRot = Math.max(maxRot, c.rotErrRad());
                } else {
                    failures++;
                }
            }
            long dt = System.nanoTime() - t0;
            long dc = mx.getCurrentThreadCpuTime() - cpu0;
            if (round >= 0) {
                times[round] = dt / 1e3 / path.size();
                cpu[round] = dc / 1e3 / path.size();
            }
        }
        Arrays.sort(times);
        Arrays.sort(cpu);
        return new Figure(
                times[rounds / 2],
                cpu[rounds / 2],
                path.size(),
                failures,
                maxPos,
                maxRot,
                (double) iterations / path.size());
    }
}
