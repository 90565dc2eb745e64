package org.fresa.ui;

import com.formdev.flatlaf.FlatLightLaf;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.SwingUtilities;

/** Starts the desktop application. */
public final class FresaApp {
    private FresaApp() {}

    /** Whether a screen is there to show the window on. */
    public static boolean hasDisplay() {
        return !java.awt.GraphicsEnvironment.isHeadless();
    }

    /** Opens the main window on the event thread, with the job when one is given. */
    public static void launch(Optional<Path> job) {
        launch(job, w -> {});
    }

    /**
     * Opens the main window; onShown runs on the event thread once the window is on screen (the
     * start-up check uses it to measure the time to a visible window).
     */
    public static void launch(Optional<Path> job, java.util.function.Consumer<MainWindow> onShown) {
        SwingUtilities.invokeLater(() -> {
            MainWindow w = create(RecentJobs.inUserHome());
            w.addWindowListener(new java.awt.event.WindowAdapter() {
                @Override
                public void windowOpened(java.awt.event.WindowEvent e) {
                    onShown.accept(w);
                }
            });
            w.setVisible(true);
            job.ifPresent(w::openJob);
        });
    }

    /** The main window, not yet shown (tests call this on the event thread). */
    public static MainWindow create(RecentJobs recent) {
        FlatLightLaf.setup();
        return new MainWindow(new MainViewModel(recent));
    }
}
