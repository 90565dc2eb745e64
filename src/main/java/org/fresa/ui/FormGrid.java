package org.fresa.ui;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * A tab's settings form, row under row: a label with its keyboard mnemonic, the field and what
 * goes beside it; lines as wide as the form (the problem line, totals); the rest of the height
 * left empty below.
 */
final class FormGrid {

    private final JPanel form = new JPanel(new GridBagLayout());
    private final int gap;
    private int row;

    /** @param gap the space around each label and field, in pixels */
    FormGrid(int gap) {
        this.gap = gap;
        form.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
    }

    /** The form's panel. */
    JPanel panel() {
        return form;
    }

    /**
     * A labelled row.
     *
     * @param mnemonic the label's mnemonic, or 0 for none
     * @param extra what stands beside the field, or null
     */
    void row(String label, char mnemonic, JComponent field, JComponent extra) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = row++;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(gap, gap, gap, gap);
        JLabel l = new JLabel(label);
        if (mnemonic != 0) {
            l.setDisplayedMnemonic(mnemonic);
            l.setLabelFor(field);
        }
        c.gridx = 0;
        form.add(l, c);
        c.gridx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        form.add(field, c);
        if (extra != null) {
            c.gridx = 2;
            form.add(extra, c);
        }
    }

    /** A line as wide as the form, the given space above it. */
    void wide(JComponent line, int above) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.gridy = row++;
        c.gridwidth = 3;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.insets = new Insets(above, gap, gap, gap);
        form.add(line, c);
    }

    /** Takes the rest of the height, so that the rows stay at the top. */
    void end() {
        GridBagConstraints filler = new GridBagConstraints();
        filler.gridy = row;
        filler.weighty = 1;
        form.add(new JPanel(), filler);
    }
}
