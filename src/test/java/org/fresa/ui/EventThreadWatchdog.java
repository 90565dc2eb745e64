package org.fresa.ui;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.awt.AWTEvent;
import java.awt.EventQueue;
import java.awt.Toolkit;
import java.awt.event.InvocationEvent;
import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;
import javax.management.Notification;
import javax.management.NotificationEmitter;
import javax.management.NotificationListener;
import javax.management.openmbean.CompositeData;

/**
 * Times every event the event thread dispatches while it is pushed on the system event queue, and
 * keeps those over a threshold with what the event thread was doing when the threshold passed (a
 * sampler thread takes its stack then, since the stack at the end of the event says nothing).
 *
 * <p>GC pauses are recorded beside the events: on a loaded 2-core CI machine a stop-the-world
 * collection alone can exceed the threshold, and it stops the event thread without the
 * application asking for it. Likewise the time the event thread was ready to run but had no core:
 * with a load of 10 on 2 cores an event of 0.2 ms CPU was seen to take 73 ms, which is the
 * machine's doing, not the application's. On Linux the kernel counts that wait per thread
 * ({@code /proc/self/task/TID/schedstat}, second field); the sampler reads it every few
 * milliseconds and an event is charged only the wait between the samples inside it (so never
 * more than it waited). Under that load the X server (Xvfb, another process) is starved too, and
 * an event that paints waits for it on its socket: events of 1 ms CPU were seen to take 280 ms.
 * So an event is charged at most its thread's CPU time plus the time it was blocked on a monitor
 * or waiting (a lock, a sleep, a Future), which the JVM counts per thread; see
 * {@link Slow#chargedMs}. What the application does on the event thread, computing or waiting
 * for its own threads, is all counted; the GC, the kernel's scheduler and the X server are not.
 */
final class EventThreadWatchdog extends EventQueue implements AutoCloseable {

    /** One event that took longer than the threshold. */
    record Slow(
            String event,
            long startMs,
            double ms,
            double gcMs,
            double runQueueMs,
            double cpuMs,
            double blockedMs,
            String running,
            List<String> stack) {
        /**
         * What the application is charged: the wall time without GC pauses and waits for a core,
         * and at most what the event thread computed or blocked (waited on a lock, slept, waited
         * for another thread) in the JVM's own per-thread counts.
         */
        double chargedMs() {
            return Math.min(ms - gcMs - runQueueMs, cpuMs + blockedMs);
        }

        /** Whether the event is over the threshold even without what is not the application's. */
        boolean isChargedOver(double thresholdMs) {
            return ms - gcMs > thresholdMs && chargedMs() > thresholdMs;
        }

        @Override
        public String toString() {
            return String.format(
                    java.util.Locale.ROOT,
                    "%.1f ms wall, charged %.1f ms (GC %.1f ms, waiting for a "
                            + "core %.1f ms, event thread's CPU %.1f ms, blocked or waiting %.1f ms) %s%n"
                            + "      runnable threads of the JVM at 50 ms: %s%n      at %s",
                    ms,
                    chargedMs(),
                    gcMs,
                    runQueueMs,
                    cpuMs,
                    blockedMs,
                    event,
                    running,
                    String.join("\n      at ", stack));
        }
    }

    /** A stop-the-world collection, in milliseconds since the JVM started. */
    private record GcPause(long startMs, long endMs) {}

    private volatile double thresholdMs;
    private final long jvmStartNanos;
    private final List<GcPause> gcPauses = new CopyOnWriteArrayList<>();
    private final List<Finished> finished = new CopyOnWriteArrayList<>();
    private final NotificationListener gcListener = this::gcNotification;
    private final Thread sampler;
    // only the event thread touches the frames: one per event being dispatched, nested ones on top
    private final java.util.ArrayDeque<Frame> frames = new java.util.ArrayDeque<>();
    private volatile Thread eventThread;
    private volatile Path schedstat;
    // (time, run-queue wait) samples of the event thread, both in ns; appended by the sampler
    private final long[][] waits = new long[2][1 << 20];
    private int waitCount;
    private volatile Segment inFlight;
    private volatile boolean recording;
    private volatile double worstMs;
    private volatile String worstEvent = "none";

    /** An event being dispatched: its segments are the stretches the event thread spends in it. */
    private static final class Frame {
        final String event;
        int segments;

        Frame(String event) {
            this.event = event;
        }
    }

    /** One stretch of an event, and the stack the sampler took once it ran past the threshold. */
    private static final class Segment {
        final long startNanos;
        final long startCpuNanos;
        final long startBlockedMs;
        volatile StackTraceElement[] stack;
        volatile String running = "(no sample)";

        Segment(long startNanos, long startCpuNanos, long startBlockedMs) {
            this.startNanos = startNanos;
            this.startCpuNanos = startCpuNanos;
            this.startBlockedMs = startBlockedMs;
        }
    }

    // the CPU time says whether a slow event computed or waited for a core (reported, not excused)
    private record Finished(
            String event,
            long startNanos,
            long endNanos,
            long cpuNanos,
            long blockedMs,
            String running,
            StackTraceElement[] stack) {}

    private static final java.lang.management.ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private EventThreadWatchdog(double thresholdMs) {
        this.thresholdMs = thresholdMs;
        this.jvmStartNanos =
                System.nanoTime() - ManagementFactory.getRuntimeMXBean().getUptime() * 1_000_000L;
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            if (gc instanceof NotificationEmitter e) {
                e.addNotificationListener(gcListener, null, null);
            }
        }
        sampler = new Thread(this::sample, "event-thread-watchdog");
        sampler.setDaemon(true);
        sampler.start();
    }

    /*
     * One watchdog per JVM, pushed once and never popped. AssertJ Swing's window monitor keeps
     * every event queue it has seen a window on and waits for each of them to go idle; a popped
     * queue has no thread dispatching it, so every later wait for idle ran into the robot's 10 s
     * idle timeout (the responsiveness tests took 14 min instead of 2). When not recording, the
     * watchdog only passes events through.
     */
    private static EventThreadWatchdog installed;

    /** The watchdog on the system event queue (pushed on first use); it records nothing until {@link #record}. */
    static synchronized EventThreadWatchdog install(double thresholdMs) throws Exception {
        if (installed != null) {
            installed.thresholdMs = thresholdMs;
            installed.recording = false;
            return installed;
        }
        if (THREADS.isThreadContentionMonitoringSupported()) {
            THREADS.setThreadContentionMonitoringEnabled(true);
        }
        EventThreadWatchdog w = new EventThreadWatchdog(thresholdMs);
        Toolkit.getDefaultToolkit().getSystemEventQueue().push(w);
        // the push may hand dispatching to a new thread: take the one that now dispatches for us
        EventQueue.invokeAndWait(() -> w.eventThread = Thread.currentThread());
        w.schedstat = schedstatOf(w.eventThread);
        installed = w;
        return w;
    }

    /** A thread of this JVM as the kernel sees it: name, state, nice value, CPU time so far (ms). */
    private record Task(String tid, String name, char state, int nice, long cpuMs) {}

    private static final long TICK_MS = 10;
    private java.util.Map<String, Task> atRecord = java.util.Map.of();
    private String loadAtRecord = "";
    private List<Task> atPause = List.of();

    /** Every thread of this JVM, read from /proc/self/task (empty where there is none). */
    static List<Task> tasks() {
        List<Task> out = new ArrayList<>();
        try (var ds = Files.list(Path.of("/proc/self/task"))) {
            for (Path d : (Iterable<Path>) ds::iterator) {
                try {
                    String st = Files.readString(d.resolve("stat"));
                    int close = st.lastIndexOf(')');
                    String[] f = st.substring(close + 2).split(" ");
                    // fields after the name: state(0) ... utime(11) stime(12) ... nice(16)
                    out.add(new Task(
                            d.getFileName().toString(),
                            st.substring(st.indexOf('(') + 1, close),
                            f[0].charAt(0),
                            Integer.parseInt(f[16]),
                            (Long.parseLong(f[11]) + Long.parseLong(f[12])) * TICK_MS));
                } catch (IOException | RuntimeException e) {
                    // the thread ended meanwhile
                }
            }
        } catch (IOException | RuntimeException e) {
            return out;
        }
        return out;
    }

    /** The runnable threads (state R, the event thread left out), or all of them, with their nice values. */
    private static String describe(List<Task> ts, boolean runnableOnly) {
        String s = ts.stream()
                .filter(t -> !runnableOnly || t.state() == 'R')
                .filter(t -> !runnableOnly || !t.name().startsWith("AWT-EventQueue"))
                .map(t -> t.name() + " (nice " + t.nice() + ")")
                .collect(Collectors.joining(", "));
        return s.isEmpty() ? "none" : s;
    }

    /**
     * The CPU time each thread of the JVM used from {@link #record} to {@link #pause} (the busiest first, those
     * over 50 ms), with its nice value, and the machine's load average then.
     */
    String threadsSinceRecord() {
        List<String> out = new ArrayList<>();
        atPause.stream()
                .map(t -> {
                    Task before = atRecord.get(t.tid());
                    return new Task(
                            t.tid(), t.name(), t.state(), t.nice(), t.cpuMs() - (before == null ? 0 : before.cpuMs()));
                })
                .filter(t -> t.cpuMs() >= 50)
                .sorted((a, b) -> Long.compare(b.cpuMs(), a.cpuMs()))
                .forEach(t -> out.add(t.name() + " " + t.cpuMs() + " ms (nice " + t.nice() + ")"));
        return "load average at the start " + loadAtRecord + "; CPU of the JVM's threads during the job: "
                + (out.isEmpty() ? "none over 50 ms" : String.join(", ", out));
    }

    /** The CPU time the JIT's compiler threads have used so far, in ms. */
    static long compilerCpuMs() {
        return tasks().stream()
                .filter(t -> t.name().startsWith("C1 Compiler") || t.name().startsWith("C2 Compiler"))
                .mapToLong(Task::cpuMs)
                .sum();
    }

    /** Forgets what was recorded and records from now on. */
    void record() {
        atRecord = tasks().stream().collect(Collectors.toMap(Task::tid, t -> t, (a, b) -> a));
        try {
            loadAtRecord = String.join(
                    " ",
                    Arrays.asList(Files.readString(Path.of("/proc/loadavg")).split(" "))
                            .subList(0, 3));
        } catch (IOException | RuntimeException e) {
            loadAtRecord = "unknown";
        }
        synchronized (waits) {
            waitCount = 0;
        }
        finished.clear();
        worstMs = 0;
        worstEvent = "none";
        recording = true;
    }

    /** Stops recording. */
    void pause() {
        recording = false;
        atPause = tasks();
    }

    /*
     * A modal dialog (a file chooser, a message) runs a loop of its own inside the event that
     * opened it, waiting for the user between its events. Timing the outer event whole would count
     * that waiting, so each event is timed in segments: a segment ends when the event thread asks
     * for the next event (it is then idle, not in the application's code) and a new one starts
     * when the nested event returns to the outer one. Every segment must stay under the threshold.
     */
    @Override
    protected void dispatchEvent(AWTEvent event) {
        if (!recording && frames.isEmpty()) {
            // between recordings (the watchdog stays on the queue for the JVM) events only pass
            super.dispatchEvent(event);
            return;
        }
        Frame f = new Frame(describe(event));
        frames.push(f);
        openSegment();
        try {
            super.dispatchEvent(event);
        } finally {
            closeSegment();
            frames.pop();
            if (!frames.isEmpty()) {
                openSegment();
            }
        }
    }

    @Override
    public AWTEvent getNextEvent() throws InterruptedException {
        if (!frames.isEmpty() && Thread.currentThread() == eventThread) {
            closeSegment();
        }
        return super.getNextEvent();
    }

    /** The ms this thread was blocked on monitors or waiting, as the JVM counts them (-1: not counted). */
    private static long blockedMs() {
        java.lang.management.ThreadInfo i =
                THREADS.getThreadInfo(Thread.currentThread().getId());
        return i == null || i.getBlockedTime() < 0 ? 0 : i.getBlockedTime() + i.getWaitedTime();
    }

    private void openSegment() {
        inFlight = new Segment(System.nanoTime(), THREADS.getCurrentThreadCpuTime(), blockedMs());
    }

    private void closeSegment() {
        Segment s = inFlight;
        if (s == null) {
            return;
        }
        inFlight = null;
        long t1 = System.nanoTime();
        if (!recording) {
            return;
        }
        Frame f = frames.peek();
        f.segments++;
        String event = f.segments == 1 ? f.event : f.event + " (part " + f.segments + ", after a nested loop)";
        double ms = (t1 - s.startNanos) / 1e6;
        if (ms > worstMs) {
            worstMs = ms;
            worstEvent = event;
        }
        if (ms > thresholdMs) {
            finished.add(new Finished(
                    event,
                    s.startNanos,
                    t1,
                    THREADS.getCurrentThreadCpuTime() - s.startCpuNanos,
                    blockedMs() - s.startBlockedMs,
                    s.running,
                    s.stack));
        }
    }

    /** The slow events recorded so far, each with the GC pauses that fell within it. */
    List<Slow> slowEvents() {
        // GC notifications arrive after the collection: give the last ones time to come in
        try {
            Thread.sleep(200);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        List<Slow> out = new ArrayList<>();
        for (Finished f : finished) {
            long sMs = (f.startNanos() - jvmStartNanos) / 1_000_000L;
            long eMs = (f.endNanos() - jvmStartNanos) / 1_000_000L;
            double gc = 0;
            for (GcPause p : gcPauses) {
                // a pause is in ms since JVM start: widen the event by the rounding either side
                long o = Math.min(eMs + 1, p.endMs()) - Math.max(sMs - 1, p.startMs());
                if (o > 0) {
                    gc += o;
                }
            }
            double runQueue = runQueueWaitNanos(f.startNanos(), f.endNanos()) / 1e6;
            List<String> stack = f.stack() == null
                    ? List.of("(no sample)")
                    : Arrays.stream(f.stack()).limit(40).map(String::valueOf).collect(Collectors.toList());
            out.add(new Slow(
                    f.event(),
                    sMs,
                    (f.endNanos() - f.startNanos()) / 1e6,
                    gc,
                    runQueue,
                    f.cpuNanos() / 1e6,
                    f.blockedMs(),
                    f.running(),
                    stack));
        }
        return out;
    }

    /** The slow events the GC does not explain. */
    List<Slow> overruns() {
        return slowEvents().stream().filter(s -> s.isChargedOver(thresholdMs)).collect(Collectors.toList());
    }

    /** The longest event recorded, in ms, GC included (the figure docs/performance-log.md reports). */
    double worstMs() {
        return worstMs;
    }

    String worstEvent() {
        return worstEvent;
    }

    private static String describe(AWTEvent e) {
        if (e instanceof InvocationEvent) {
            // paramString names the runnable: a lambda's class names the class that made it
            return e.getClass().getSimpleName() + " " + e.paramString().replaceAll(",when=.*", "");
        }
        return e.getClass().getSimpleName() + " " + e.paramString().replaceAll(",when=.*", "") + " on "
                + (e.getSource() == null ? "null" : e.getSource().getClass().getName());
    }

    /** The kernel's scheduling counters of the thread: Linux names a thread's task as Java names the thread. */
    private static Path schedstatOf(Thread t) {
        String name = t.getName().length() > 15 ? t.getName().substring(0, 15) : t.getName();
        try (var tasks = Files.list(Path.of("/proc/self/task"))) {
            List<Path> found = tasks.filter(d -> {
                        try {
                            return Files.readString(d.resolve("comm")).strip().equals(name);
                        } catch (IOException e) {
                            return false;
                        }
                    })
                    .toList();
            return found.size() == 1 ? found.get(0).resolve("schedstat") : null;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    private void sampleRunQueue() {
        Path p = schedstat;
        if (p == null) {
            return;
        }
        try {
            String[] f = Files.readString(p).trim().split("\\s+");
            long now = System.nanoTime();
            synchronized (waits) {
                if (waitCount < waits[0].length) {
                    waits[0][waitCount] = now;
                    waits[1][waitCount] = Long.parseLong(f[1]);
                    waitCount++;
                }
            }
        } catch (IOException | RuntimeException e) {
            schedstat = null;
        }
    }

    /** The run-queue wait between the first sample after start and the last before end. */
    private long runQueueWaitNanos(long start, long end) {
        synchronized (waits) {
            int first = -1;
            int last = -1;
            for (int i = 0; i < waitCount; i++) {
                long t = waits[0][i];
                if (t >= start && first < 0) {
                    first = i;
                }
                if (t <= end) {
                    last = i;
                }
            }
            return first >= 0 && last > first ? waits[1][last] - waits[1][first] : 0;
        }
    }

    private void sample() {
        while (!Thread.currentThread().isInterrupted()) {
            if (recording) {
                sampleRunQueue();
            }
            Segment s = inFlight;
            if (recording && s != null && s.stack == null && System.nanoTime() - s.startNanos > thresholdMs * 1e6) {
                Thread t = eventThread;
                StackTraceElement[] st = t == null ? null : t.getStackTrace();
                String running = describe(tasks(), true);
                if (inFlight == s) {
                    s.stack = st;
                    s.running = running;
                }
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private void gcNotification(Notification n, Object handback) {
        if (!GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(n.getType())) {
            return;
        }
        GarbageCollectionNotificationInfo info =
                GarbageCollectionNotificationInfo.from((CompositeData) n.getUserData());
        // concurrent cycles do not stop the event thread; their beans say so in the action
        if (info.getGcAction().contains("concurrent") || info.getGcName().contains("Concurrent")) {
            return;
        }
        var gi = info.getGcInfo();
        gcPauses.add(new GcPause(gi.getStartTime(), gi.getEndTime()));
    }

    /** Stops recording; the watchdog stays on the queue for the JVM's later tests (see {@link #install}). */
    @Override
    public void close() {
        pause();
    }
}
