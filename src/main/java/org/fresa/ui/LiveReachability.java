package org.fresa.ui;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiConsumer;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import javax.swing.SwingUtilities;
import org.fresa.cell.RobotTools;
import org.fresa.geom.Transform3;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.kin.Reachability;
import org.fresa.kin.TrajectorySolver;
import org.fresa.model.Placement;

/**
 * The Position tab's live reachability: each change of the placements, the robot or its tool
 * asks which targets the robot reaches, and the answer (one solution per target, its 3D scene and
 * its plots) is worked out on a background thread and handed to the event thread. Requests never
 * queue up: a new one makes every older one stale, a stale one stops between targets and its
 * answer is dropped, so the answer shown is always that of the latest fields, and typing never
 * waits for a computation. The STEP-NC file is read and planned once per file, robot and tool;
 * a placement change only places and solves the targets.
 */
final class LiveReachability {

    /** What the answer depends on. */
    record Inputs(
            Path stepnc,
            org.fresa.toolpath.PlanningChoices choices,
            String robot,
            RobotTools.Choice tool,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats) {
        Inputs {
            formats = List.copyOf(formats);
        }
    }

    /**
     * An answer ready to be shown in the 3D view and the reach line, everything made off the event
     * thread; its plots follow in a {@link Charted} of the same inputs.
     *
     * @param errorRows the error per axis table's rows ({@link PositionViewModel#errorRowsOf})
     * @param phases when each step of its making ended
     * @param cpuNanos the CPU time the background thread spent on it (-1 where the JVM does not count it)
     */
    record Answer(
            Inputs inputs,
            RobotTrajectoryService.Solved solved,
            Transform3 spindle,
            CellScene scene,
            List<String[]> errorRows,
            Phases phases,
            long cpuNanos) {
        /** When the change that asked for it was made ({@link System#nanoTime}). */
        long askedNanos() {
            return phases.changed();
        }
    }

    /**
     * The plots of an answer, made after the answer itself was handed over: the 3D view does not
     * wait for them.
     */
    record Charted(
            Inputs inputs,
            TrajectoryCharts charts,
            long changedNanos,
            long postedNanos,
            long madeNanos,
            long cpuNanos) {}

    /**
     * When (System.nanoTime) an answer's steps ended: the field change, the request (after the
     * event thread's own handling of the change), the worker taking it up, the targets solved, the
     * scene made and the answer handed to the event thread.
     */
    record Phases(long changed, long asked, long started, long solved, long scened, long posted) {}

    private static final java.lang.management.ThreadMXBean THREADS =
            java.lang.management.ManagementFactory.getThreadMXBean();

    /** The CPU time of the calling thread (ns), -1 where the JVM does not count it. */
    static long cpuNanos() {
        return THREADS.isCurrentThreadCpuTimeSupported() ? THREADS.getCurrentThreadCpuTime() : -1;
    }

    // one thread: the answers come in the order asked, and a stale request costs only its check
    private static final ExecutorService WORKER = BackgroundThreads.single("fresa-reachability");

    private final AtomicLong generation = new AtomicLong();
    private final Consumer<Answer> show;
    private final BiConsumer<Charted, BooleanSupplier> plots;
    private final Consumer<String> failed;
    private Inputs last;

    // the worker thread's own
    private Object plannedKey;
    private PositionViewModel.Planned planned;
    private Reachability reach;

    /**
     * @param show runs on the event thread with each answer still wanted
     * @param plots runs on the background thread, right after the answer is handed to the event
     *     thread, with the answer's plot data and whether it is no longer wanted: it makes the plots
     *     ready while the event thread shows the answer, and shows them on the event thread after it
     * @param failed runs on the event thread when the file or robot cannot be read or planned
     */
    LiveReachability(Consumer<Answer> show, BiConsumer<Charted, BooleanSupplier> plots, Consumer<String> failed) {
        this.show = show;
        this.plots = plots;
        this.failed = failed;
    }

    /** Asks for the answer of these inputs (event thread); nothing when they are those last asked. */
    void request(Inputs in) {
        request(in, System.nanoTime());
    }

    /**
     * As above, for a change made at {@code changedNanos} ({@link System#nanoTime}): the time an
     * answer takes is counted from there.
     */
    void request(Inputs in, long changedNanos) {
        if (in.equals(last)) {
            return;
        }
        last = in;
        long asked = System.nanoTime();
        long gen = generation.incrementAndGet();
        WORKER.execute(() -> run(in, gen, changedNanos, asked));
    }

    /** Drops any answer being worked out; the same inputs asked again are worked out again. */
    void forget() {
        last = null;
        generation.incrementAndGet();
    }

    /** Drops any answer being worked out and takes these inputs as answered (by Compute). */
    void answeredBy(Inputs in) {
        last = in;
        generation.incrementAndGet();
    }

    /** The inputs last asked for (event thread). */
    Optional<Inputs> lastAsked() {
        return Optional.ofNullable(last);
    }

    private boolean stale(long gen) {
        return generation.get() != gen;
    }

    private void run(Inputs in, long gen, long changed, long asked) {
        if (stale(gen)) {
            return;
        }
        long started = System.nanoTime();
        long cpu0 = cpuNanos();
        try {
            List<Object> key = List.of(
                    in.stepnc(), modified(in.stepnc()), in.choices(), in.robot(), modified(in.robot()), in.tool());
            if (!key.equals(plannedKey)) {
                planned =
                        PositionViewModel.plan(in.stepnc(), in.robot(), in.tool(), in.choices(), ProgressMonitor.NONE);
                reach = new Reachability(TrajectorySolver.Options.DEFAULT);
                plannedKey = key;
            }
            Optional<RobotTrajectoryService.Solved> solved = PositionViewModel.reach(
                    planned, in.robotTable(), in.tablePiece(), in.formats(), reach, () -> stale(gen));
            if (solved.isEmpty() || stale(gen)) {
                return;
            }
            long reached = System.nanoTime();
            RobotTrajectoryService.Solved s = solved.get();
            CellScene scene = PositionViewModel.sceneOf(s, 0, Optional.of(planned.spindle()));
            List<String[]> rows = PositionViewModel.errorRowsOf(s.result());
            long scened = System.nanoTime();
            Answer a = new Answer(
                    in,
                    s,
                    planned.spindle(),
                    scene,
                    rows,
                    new Phases(changed, asked, started, reached, scened, System.nanoTime()),
                    cpu0 < 0 ? -1 : cpuNanos() - cpu0);
            SwingUtilities.invokeLater(() -> {
                if (!stale(gen)) {
                    show.accept(a);
                }
            });
            // the plots after the view: a newer change drops them unmade
            if (stale(gen)) {
                return;
            }
            long cpu1 = cpuNanos();
            TrajectoryCharts c = TrajectoryCharts.of(s);
            Charted charted = new Charted(
                    in, c, changed, a.phases().posted(), System.nanoTime(), cpu1 < 0 ? -1 : cpuNanos() - cpu1);
            plots.accept(charted, () -> stale(gen));
        } catch (org.fresa.model.CamInputException | java.io.IOException | RuntimeException e) {
            plannedKey = null;
            String message = e.getMessage();
            SwingUtilities.invokeLater(() -> {
                if (!stale(gen)) {
                    failed.accept(message);
                }
            });
        }
    }

    /** A file's modification time (a file saved again is read again); the text itself for a built-in name. */
    private static Object modified(Object fileOrName) {
        try {
            Path p = fileOrName instanceof Path f ? f : Path.of(fileOrName.toString());
            return Files.isRegularFile(p) ? Files.getLastModifiedTime(p) : "";
        } catch (java.io.IOException | java.nio.file.InvalidPathException e) {
            return "";
        }
    }
}
