package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;

/** The bottom line of the window: a message, and a progress bar with Cancel while a task runs. */
final class StatusBar extends JPanel {

    private static final long serialVersionUID = 1L;

    final JLabel message = new JLabel("Ready");
    final JProgressBar progress = new JProgressBar(0, 1000);
    final JButton cancel = new JButton("Cancel");

    StatusBar() {
        super(new BorderLayout());
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createMatteBorder(1, 0, 0, 0,
                javax.swing.UIManager.getColor("Separator.foreground")), BorderFactory.createEmptyBorder(3, 8, 3, 8)));
        message.setName("status");
        progress.setName("progress");
        cancel.setName("cancel");
        progress.setStringPainted(true);
        progress.setVisible(false);
        cancel.setVisible(false);
        cancel.setMnemonic('C');
        JPanel right = new JPanel(new FlowLayout(FlowLayout.RIGHT, 6, 0));
        right.add(progress);
        right.add(cancel);
        add(message, BorderLayout.CENTER);
        add(right, BorderLayout.EAST);
    }
}
