package org.fresa.ui;

import java.awt.FlowLayout;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JPanel;

/** The tabs' buttons: a name for the GUI tests, a mnemonic for the keyboard, one action; and their rows. */
final class Buttons {
    private Buttons() {}

    /**
     * @param name the component name, or null for none
     * @param mnemonic a {@code KeyEvent.VK_*} code, or 0 for none
     */
    static JButton of(String text, String name, int mnemonic, Runnable action) {
        JButton b = new JButton(text);
        if (name != null) {
            b.setName(name);
        }
        if (mnemonic != 0) {
            b.setMnemonic(mnemonic);
        }
        b.addActionListener(e -> action.run());
        return b;
    }

    /** A left-aligned row of a tab's buttons with the labels and fields that go with them. */
    static JPanel row(JComponent... controls) {
        JPanel p = new JPanel(new FlowLayout(FlowLayout.LEFT));
        for (JComponent c : controls) {
            p.add(c);
        }
        return p;
    }
}
