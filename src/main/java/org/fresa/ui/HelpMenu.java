package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Window;
import javax.swing.JDialog;
import javax.swing.JEditorPane;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.WindowConstants;

/** The Help menu: the user guide (F1) in a window of its own beside the main window. */
final class HelpMenu {

    private HelpMenu() {}

    static JMenu create(Window owner) {
        JMenu help = new JMenu("Help");
        help.setMnemonic('H');
        JMenuItem guide = new JMenuItem("User guide");
        guide.setName("help-guide");
        guide.setMnemonic('U');
        guide.setAccelerator(KeyStroke.getKeyStroke("F1"));
        JDialog[] shown = new JDialog[1];
        guide.addActionListener(e -> {
            if (shown[0] == null) {
                shown[0] = window(owner);
            }
            shown[0].setVisible(true);
            shown[0].toFront();
        });
        help.add(guide);
        return help;
    }

    /** The guide's window: not modal, so the planner reads it while working in the tabs. */
    private static JDialog window(Window owner) {
        JDialog d = new JDialog(owner, "Fresa user guide");
        d.setName("user-guide");
        d.setDefaultCloseOperation(WindowConstants.HIDE_ON_CLOSE);
        JEditorPane text = new JEditorPane("text/html", UserGuide.html());
        text.setName("user-guide-text");
        text.setEditable(false);
        text.setCaretPosition(0);
        d.getContentPane().add(new JScrollPane(text), BorderLayout.CENTER);
        d.getRootPane()
                .registerKeyboardAction(
                        e -> d.setVisible(false),
                        KeyStroke.getKeyStroke("ESCAPE"),
                        javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW);
        d.setPreferredSize(new Dimension(720, 760));
        d.pack();
        d.setLocationRelativeTo(owner);
        return d;
    }
}
