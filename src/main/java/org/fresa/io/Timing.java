package org.fresa.io;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import java.time.Instant;

/**
 * An opt-in phase timer for finding where a command's time goes (docs/performance.md):
 * with {@code -Dfresa.timing=true} (e.g. through {@code FRESA_JAVA_OPTS}) each phase's end is
 * logged (System.Logger {@code fresa.timing}, by default on standard error) with the wall time
 * since the JVM started and the thread's CPU time. Off, a phase costs one boolean test.
 */
public final class Timing {
    public static final boolean ON = Boolean.getBoolean("fresa.timing");

    private Timing() {}

    /** The phase that just ended on this thread. */
    public static void mark(String phase) {
        if (ON) {
            Print.mark(phase);
        }
    }

    /** Loaded only when timing is on: the management classes cost start-up time. */
    private static final class Print {
        private static final Instant START =
                ProcessHandle.current().info().startInstant().orElse(Instant.now());
        private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
        private static final System.Logger LOG = System.getLogger("fresa.timing");

        static synchronized void mark(String phase) {
            long wall = Duration.between(START, Instant.now()).toMillis();
            long cpu = THREADS.getCurrentThreadCpuTime() / 1_000_000;
            LOG.log(
                    System.Logger.Level.INFO,
                    String.format(
                            java.util.Locale.ROOT,
                            "%6d ms  %-28s %s, thread CPU %d ms",
                            wall,
                            phase,
                            Thread.currentThread().getName(),
                            cpu));
        }
    }
}
