package org.fresa.ui;

import java.awt.BorderLayout;
import java.util.Objects;
import java.util.Optional;
import javax.swing.JComponent;
import javax.swing.JPanel;

/**
 * A tab whose result is drawn on a plot: the whole tab's panel, its title and the plot that
 * Export PNG/SVG applies to.
 */
abstract class PlotTab implements ModuleTab {

    /** The whole tab, laid out by the tab (a form on the left, the plot in the centre). */
    final JPanel panel = new JPanel(new BorderLayout());

    final PlotPanel plot = new PlotPanel();
    private final String title;

    PlotTab(String title) {
        this.title = Objects.requireNonNull(title, "title");
    }

    @Override
    public final String title() {
        return title;
    }

    @Override
    public final JComponent component() {
        return panel;
    }

    @Override
    public final Optional<PlotPanel> plot() {
        return Optional.of(plot);
    }
}
