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
        setBorder(BorderFactory.createCompoundBorder(
                BorderFactory.createMatteBorder(1, 0, 0, 0, javax.swing.UIManager.getColor("Separator.foreground")),
                BorderFactory.createEmptyBorder(3, 8, 3, 8)));
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

    /**
     * As high with the progress bar and Cancel shown as without them: a bar that grew when a task
     * starts (and shrank when it ends) made the whole tab above it one line shorter (longer), so
     * every component of the tab was laid out and painted again, 20 to 45 ms of the event
     * thread's time in a fresh window. Now only the status bar changes.
     */
    @Override
    public java.awt.Dimension getPreferredSize() {
        java.awt.Dimension d = super.getPreferredSize();
        java.awt.Insets in = getInsets();
        int h = Math.max(
                        message.getPreferredSize().height,
                        Math.max(progress.getPreferredSize().height, cancel.getPreferredSize().height))
                + in.top
                + in.bottom;
        return new java.awt.Dimension(d.width, Math.max(d.height, h));
    }
}
