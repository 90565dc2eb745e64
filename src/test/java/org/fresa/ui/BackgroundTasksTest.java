package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** The status bar's progress while a task runs (no screen needed). */
class BackgroundTasksTest {

    /** The bar's state once the message names the phase, read on the event thread. */
    private static Object[] barWhen(StatusBar bar, String phase) throws Exception {
        AtomicReference<Object[]> seen = new AtomicReference<>();
        // the worker's reports reach the event thread in their own time: wait for the phase
        for (int i = 0; i < 2000 && seen.get() == null; i++) {
            SwingUtilities.invokeAndWait(() -> {
                if (bar.message.getText().endsWith(phase)) {
                    seen.set(new Object[] {
                        bar.progress.isIndeterminate(),
                        bar.progress.isStringPainted(),
                        bar.progress.getPercentComplete()
                    });
                }
            });
            Thread.sleep(5);
        }
        assertTrue(seen.get() != null, "the bar never showed " + phase + ": " + bar.message.getText());
        return seen.get();
    }

    @Test
    void aPhaseOfUnknownLengthAfterAFinishedOneReadsNoPercentage() throws Exception {
        // Swing components are made on the event thread, as everywhere
        AtomicReference<StatusBar> made = new AtomicReference<>();
        AtomicReference<BackgroundTasks> madeTasks = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            made.set(new StatusBar());
            madeTasks.set(new BackgroundTasks(made.get(), null));
        });
        StatusBar bar = made.get();
        BackgroundTasks tasks = madeTasks.get();
        CountDownLatch planning = new CountDownLatch(1);
        CountDownLatch solving = new CountDownLatch(1);
        CountDownLatch end = new CountDownLatch(1);
        SwingUtilities.invokeAndWait(() -> tasks.start(
                "Robot",
                pm -> {
                    pm.progress(1, "read 2954 instances");
                    pm.progress(-1, "planning toolpaths");
                    planning.await(10, TimeUnit.SECONDS);
                    pm.progress(0.5, "inverse kinematics");
                    solving.await(10, TimeUnit.SECONDS);
                    return "done";
                },
                r -> end.countDown()));
        Object[] plan = barWhen(bar, "planning toolpaths");
        planning.countDown();
        Object[] ik = barWhen(bar, "inverse kinematics");
        solving.countDown();
        assertTrue(end.await(10, TimeUnit.SECONDS));
        assertAll(
                () -> assertTrue((Boolean) plan[0], "planning: the bar runs without an end"),
                () -> assertFalse((Boolean) plan[1], "planning: no percentage (the file's 100 % was shown)"),
                () -> assertFalse((Boolean) ik[0], "the inverse kinematics has an end"),
                () -> assertTrue((Boolean) ik[1], "its percentage is shown"),
                () -> assertEquals(0.5, (Double) ik[2], 1e-9));
    }
}
