package org.fresa.ui;

import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;
import javax.swing.SwingWorker;
import org.fresa.io.ErrorLog;
import org.fresa.job.ProgressMonitor;
import org.fresa.model.CamInputException;

/**
 * Runs long work off the event thread with the status bar's progress bar and Cancel button: one
 * task at a time. Results and errors come back on the event thread; bad input is shown as a
 * dialog with its message, a bug as a short dialog with the trace in the log file.
 */
final class BackgroundTasks {

    /** Work that reports progress and may be cancelled. */
    @FunctionalInterface
    interface Work<T> {
        T run(ProgressMonitor progress) throws Exception;
    }

    // below the event thread's priority (see BackgroundThreads); a pool, as SwingWorker's own, so
    // that a cancelled task still running to its next check does not hold up the next one
    private static final java.util.concurrent.ExecutorService WORKER = BackgroundThreads.pool("fresa-task");

    private final StatusBar bar;
    private final java.awt.Component owner;
    private SwingWorker<?, ?> current;

    BackgroundTasks(StatusBar bar, java.awt.Component owner) {
        this.bar = bar;
        this.owner = owner;
        bar.cancel.addActionListener(e -> cancel());
    }

    boolean isBusy() {
        return current != null && !current.isDone();
    }

    void cancel() {
        if (current != null) {
            current.cancel(true);
        }
    }

    /** Says in the status bar that a task, which ended without an exception, could not do its work. */
    void failed(String title) {
        bar.message.setText(title + ": failed");
    }

    /** Starts the work unless another task runs; onDone gets the result on the event thread. */
    <T> void start(String title, Work<T> work, Consumer<T> onDone) {
        if (isBusy()) {
            bar.message.setText("Busy: " + title + " waits until the current task ends or is cancelled");
            return;
        }
        bar.message.setText(title + "...");
        bar.progress.setValue(0);
        bar.progress.setIndeterminate(true);
        bar.progress.setStringPainted(false);
        bar.progress.setVisible(true);
        bar.cancel.setVisible(true);
        SwingWorker<T, Object[]> worker = new SwingWorker<>() {
            @Override
            protected T doInBackground() throws Exception {
                ProgressMonitor pm = new ProgressMonitor() {
                    @Override
                    public void progress(double fraction, String what) {
                        publish(new Object[] {fraction, what});
                    }

                    @Override
                    public boolean isCancelled() {
                        return isCancelled0();
                    }
                };
                return work.run(pm);
            }

            private boolean isCancelled0() {
                return isCancelled() || Thread.currentThread().isInterrupted();
            }

            @Override
            protected void process(List<Object[]> chunks) {
                if (isCancelled()) {
                    // the worker runs on to its next check: its progress must not cover "cancelled"
                    return;
                }
                Object[] last = chunks.get(chunks.size() - 1);
                double f = (Double) last[0];
                bar.progress.setIndeterminate(f < 0);
                // a phase of unknown length shows no percentage: the 100 % of the phase before
                // (a file read) stood on the toolpath planning and the inverse kinematics after it
                bar.progress.setStringPainted(f >= 0);
                if (f >= 0) {
                    bar.progress.setValue((int) Math.round(f * 1000));
                }
                bar.message.setText(title + ": " + last[1]);
            }

            @Override
            protected void done() {
                bar.progress.setVisible(false);
                bar.cancel.setVisible(false);
                try {
                    T result = get();
                    bar.message.setText(title + ": done");
                    onDone.accept(result);
                } catch (CancellationException e) {
                    bar.message.setText(title + ": cancelled");
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                } catch (ExecutionException e) {
                    Throwable c = e.getCause();
                    if (c instanceof CancellationException) {
                        bar.message.setText(title + ": cancelled");
                    } else if (c instanceof CamInputException || c instanceof java.io.IOException) {
                        bar.message.setText(title + ": failed");
                        Dialogs.error(owner, title, c.getMessage());
                    } else {
                        bar.message.setText(title + ": failed");
                        java.nio.file.Path log = ErrorLog.record(c);
                        Dialogs.error(
                                owner,
                                title,
                                "Something went wrong inside Fresa: " + c
                                        + (log != null ? "\n\nDetails are in " + log : ""));
                    }
                }
            }
        };
        current = worker;
        // a worker is a Runnable: run on our low-priority thread instead of SwingWorker's pool
        WORKER.execute(worker);
    }
}
