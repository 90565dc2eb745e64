package org.fresa.ui;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The window's background threads (a task's worker, the chart drawer): daemons at
 * {@link Thread#MIN_PRIORITY}, so that on a machine of few cores the event thread wins a core
 * when it wakes while they compute. Java priorities reach the operating system only
 * when the JVM is asked to (on Linux {@code -XX:ThreadPriorityPolicy=1}, which the {@code fresa}
 * launcher passes for the window: then MIN_PRIORITY is nice 4); without it they are hints the
 * JVM ignores, and nothing else changes. Threads these threads create inherit the priority (the
 * robot service's output pool).
 */
final class BackgroundThreads {

    private BackgroundThreads() {}

    /** A factory of low-priority daemon threads named prefix-1, prefix-2, ... */
    static ThreadFactory lowPriority(String prefix) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, prefix + "-" + n.incrementAndGet());
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            return t;
        };
    }

    /** Low-priority threads made as needed, an idle one ending after a minute. */
    static ExecutorService pool(String prefix) {
        return Executors.newCachedThreadPool(lowPriority(prefix));
    }

    /** One low-priority thread that runs what it is given in order. */
    static ExecutorService single(String name) {
        return Executors.newSingleThreadExecutor(lowPriority(name));
    }
}
