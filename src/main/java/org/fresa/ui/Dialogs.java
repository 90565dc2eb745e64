package org.fresa.ui;

import java.awt.Component;
import javax.swing.JOptionPane;

/** Message dialogs: the message for the planner, never a stack trace. */
final class Dialogs {
    private Dialogs() {}

    static void error(Component owner, String title, String message) {
        JOptionPane.showMessageDialog(owner, wrap(message), title, JOptionPane.ERROR_MESSAGE);
    }

    static void info(Component owner, String title, String message) {
        JOptionPane.showMessageDialog(owner, wrap(message), title, JOptionPane.INFORMATION_MESSAGE);
    }

    private static String wrap(String s) {
        return s == null ? "" : s;
    }
}
