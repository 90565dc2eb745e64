package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Font;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingConstants;
import org.fresa.job.Module;

/** The tab of a module that is not built yet: says so plainly, offers nothing fake. */
final class UnavailableTab implements ModuleTab {

    private final String title;
    private final JPanel panel = new JPanel(new BorderLayout());

    UnavailableTab(String title, Module module) {
        this.title = title;
        String name = Character.toUpperCase(module.title().charAt(0)) + module.title().substring(1);
        JLabel text = new JLabel("<html><div style='text-align:center'><b>" + name
                + "</b> is not available yet.<br><br>It is being built under issue " + module.issue()
                + ".</div></html>", SwingConstants.CENTER);
        text.setFont(text.getFont().deriveFont(Font.PLAIN, 15f));
        text.setName("unavailable-" + module.name().toLowerCase(java.util.Locale.ROOT));
        panel.setBorder(BorderFactory.createEmptyBorder(40, 40, 40, 40));
        panel.add(text, BorderLayout.CENTER);
    }

    @Override
    public String title() {
        return title;
    }

    @Override
    public JComponent component() {
        return panel;
    }
}
