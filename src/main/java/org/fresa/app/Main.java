package org.fresa.app;

import org.fresa.app.cli.FresaCommand;

/** Starts Fresa: the desktop application without arguments, a command otherwise. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        int status = FresaCommand.execute(args);
        // the GUI keeps the JVM alive on its own threads; only commands end here
        if (status != FresaCommand.KEEP_RUNNING) {
            System.exit(status);
        }
    }
}
