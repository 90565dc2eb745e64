package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.Locale;
import org.fresa.job.ProgressMonitor;

/**
 * Progress on stderr when the program runs in a terminal, nothing otherwise (spec/cli.md). Java
 * cannot ask whether stderr alone is a terminal; a console (stdin and stdout on a terminal) and
 * a TERM other than "dumb" are taken as the sign.
 */
final class TerminalProgress implements ProgressMonitor {

    private final PrintWriter err;
    private long lastNanos;
    private boolean shown;

    private TerminalProgress(PrintWriter err) {
        this.err = err;
    }

    static ProgressMonitor forStderr(PrintWriter err) {
        String term = System.getenv("TERM");
        boolean terminal =
                System.console() != null && term != null && !"dumb".equals(term) && System.getenv("CI") == null;
        return terminal ? new TerminalProgress(err) : ProgressMonitor.NONE;
    }

    static void clear(ProgressMonitor p) {
        if (p instanceof TerminalProgress t && t.shown) {
            t.err.print("\r\033[K");
            t.err.flush();
        }
    }

    @Override
    public void progress(double fraction, String what) {
        long now = System.nanoTime();
        if (now - lastNanos < 100_000_000L && fraction < 1) {
            return;
        }
        lastNanos = now;
        shown = true;
        String pct = fraction >= 0 ? String.format(Locale.ROOT, "%3d%% ", (int) Math.round(fraction * 100)) : "";
        err.print("\r\033[K" + pct + what);
        err.flush();
    }

    @Override
    public boolean isCancelled() {
        return false;
    }
}
