package org.fresa.app;

import org.fresa.app.cli.FresaCommand;

/** Starts Fresa: the desktop application without arguments, a command otherwise. */
public final class Main {
    private Main() {}

    public static void main(String[] args) {
        // only no arguments and "gui" open windows; the commands draw charts into images, and
        // headless AWT neither looks for a display nor loads the X11 toolkit for them
        if (args.length > 0 && !"gui".equals(args[0]) && System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        int status = FresaCommand.execute(args);
        // the GUI keeps the JVM alive on its own threads; only commands end here
        if (status != FresaCommand.KEEP_RUNNING) {
            System.exit(status);
        }
    }
}
