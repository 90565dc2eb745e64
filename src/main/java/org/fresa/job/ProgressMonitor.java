package org.fresa.job;

import java.util.concurrent.CancellationException;

/**
 * Where long work reports how far it has come, and learns whether it should stop. The GUI backs
 * it with a progress bar and a Cancel button, the command line with a terminal line.
 */
public interface ProgressMonitor {

    /** A monitor that shows nothing and never cancels. */
    ProgressMonitor NONE = new ProgressMonitor() {
        @Override
        public void progress(double fraction, String what) {}

        @Override
        public boolean isCancelled() {
            return false;
        }
    };

    /**
     * @param fraction how much is done, 0 to 1 (or negative when unknown)
     * @param what a few words on the current step, for the planner
     */
    void progress(double fraction, String what);

    boolean isCancelled();

    /** @throws CancellationException when the user has asked to stop */
    default void checkCancelled() {
        if (isCancelled()) {
            throw new CancellationException("cancelled");
        }
    }
}
