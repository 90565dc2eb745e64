package org.fresa.bench;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.IkBenchmark;
import org.fresa.kin.IkOptions;
import org.fresa.kin.IkResult;
import org.fresa.kin.IkSolver;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * {@code ik_us_per_point_irb140} and {@code ik_us_per_point_tricept806}: the 3131-point zig-zag
 * of {@link IkBenchmark}, warm start from the previous point; the score is microseconds per point.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 10, time = 1)
@Fork(2)
public class IkBench {

    private static final int POINTS = 3131;

    @Param({"irb140", "tricept806"})
    public String robot;

    private IkSolver solver;
    private List<Transform3> path;
    private double[] start;

    @Setup
    public void prepare() {
        Robot r = robot.equals("irb140") ? Robots.irb140() : Robots.tricept806();
        path = robot.equals("irb140") ? IkBenchmark.zigZag(new Vec3(420, -50, 300))
                : IkBenchmark.zigZag(new Vec3(150, 250, -1700));
        solver = r.newSolver(IkOptions.DEFAULT);
        if (!(solver.solveCold(path.get(0)) instanceof IkResult.Converged c)) {
            throw new IllegalStateException("the path's first point is unreachable for " + robot);
        }
        start = c.q();
    }

    @Benchmark
    @OperationsPerInvocation(POINTS)
    public int solveZigZag() {
        double[] seed = start;
        int failures = 0;
        for (Transform3 t : path) {
            IkResult r = solver.solve(t, seed);
            if (r instanceof IkResult.Converged c) {
                seed = c.q();
            } else {
                failures++;
            }
        }
        return failures;
    }
}
