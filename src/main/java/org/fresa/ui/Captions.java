package org.fresa.ui;

import java.awt.BorderLayout;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/** The tabs' captioned views: a caption above a view, its mnemonic focusing the component it names. */
final class Captions {
    private Captions() {}

    /**
     * @param mnemonic a {@code KeyEvent.VK_*} code
     * @param named the component the caption names and its mnemonic focuses (the view or inside it)
     */
    static JPanel above(String caption, int mnemonic, JComponent named, JComponent view) {
        JLabel label = new JLabel(caption);
        label.setDisplayedMnemonic(mnemonic);
        label.setLabelFor(named);
        JPanel p = new JPanel(new BorderLayout());
        p.add(label, BorderLayout.NORTH);
        p.add(view, BorderLayout.CENTER);
        return p;
    }
}
