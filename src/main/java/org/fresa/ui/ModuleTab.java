package org.fresa.ui;

import java.util.Optional;
import javax.swing.JComponent;

/** One tab of the main window: its title, its component, and the plot Export applies to. */
public interface ModuleTab {

    String title();

    JComponent component();

    /** The plot shown in this tab, if it has one (Export PNG/SVG uses it). */
    default Optional<PlotPanel> plot() {
        return Optional.empty();
    }
}
