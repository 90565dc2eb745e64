package org.fresa.ui;

import javax.swing.JButton;

/** The tabs' buttons: a name for the GUI tests, a mnemonic for the keyboard, one action. */
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
}
