package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.util.function.Consumer;
import javax.swing.DefaultListModel;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ListSelectionModel;

/**
 * Every warning of a module's last result in a list under a heading with their number; selecting
 * one (click or keys) hands it to the tab, which shows its place.
 */
final class WarningsPanel extends JPanel {

    private static final long serialVersionUID = 1L;

    private final DefaultListModel<WarningList.Warning> items = new DefaultListModel<>();
    private final JList<WarningList.Warning> list = new JList<>(items);
    private final JLabel heading = new JLabel("No warnings");
    private transient Consumer<WarningList.Warning> onSelect = w -> {};

    /** name: the list's component name (tests find it), e.g. "cutting-warnings". */
    WarningsPanel(String name, int visibleRows) {
        super(new BorderLayout());
        list.setName(name);
        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        list.setVisibleRowCount(visibleRows);
        list.setToolTipText("Every warning of the last result; select one that names a place to see it in the plot");
        list.addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && list.getSelectedValue() != null) {
                onSelect.accept(list.getSelectedValue());
            }
        });
        // the warning's full text as the row's tooltip: long warnings are cut at the list's width
        list.setCellRenderer(new javax.swing.DefaultListCellRenderer() {
            private static final long serialVersionUID = 1L;

            @Override
            public java.awt.Component getListCellRendererComponent(
                    JList<?> l, Object value, int index, boolean selected, boolean focus) {
                java.awt.Component c = super.getListCellRendererComponent(l, value, index, selected, focus);
                if (value instanceof WarningList.Warning w) {
                    setText((w.place().isPresent() ? "\u25CE " : "") + w.text());
                    setToolTipText(w.text());
                }
                return c;
            }
        });
        heading.setName(name + "-heading");
        heading.setLabelFor(list);
        add(heading, BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(list);
        scroll.setPreferredSize(new Dimension(200, list.getPreferredScrollableViewportSize().height + 4));
        add(scroll, BorderLayout.CENTER);
    }

    void onSelect(Consumer<WarningList.Warning> action) {
        onSelect = action;
    }

    /** Shows every warning of the list. Call on the event thread. */
    void show(WarningList warnings) {
        items.clear();
        warnings.all().forEach(items::addElement);
        heading.setText(warnings.heading());
    }
}
