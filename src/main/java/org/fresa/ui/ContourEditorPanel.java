package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import javax.swing.AbstractAction;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.KeyStroke;
import javax.swing.ListSelectionModel;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;
import org.fresa.ui.PocketContourEditor.Column;

/**
 * The Pocket tab's contour editor: one row per element of the contour as its {@code .dad} file
 * holds it. Keys: Insert adds an element after the selected one, Shift+Insert inserts one before
 * it, Delete removes it, Alt+Up and Alt+Down move it. A bad cell is pink with the reason in its
 * tooltip and under the table; the element a refused contour is refused at is marked too.
 */
final class ContourEditorPanel {

    private static final Color BAD = new Color(255, 220, 220);

    private final PocketContourEditor editor;
    private final Runnable edited;
    private final Runnable selected;
    private final JPanel panel = new JPanel(new BorderLayout());
    private final Model model = new Model();
    private final JTable table = new JTable(model);
    private final JLabel status = new JLabel(" ");
    private boolean filling;

    /**
     * @param editor the view model the table shows
     * @param edited called after every change of the contour (a cell, a row added, moved, deleted)
     * @param selected called when another element is selected
     * @param save writes the contour to a .dad file
     */
    ContourEditorPanel(PocketContourEditor editor, Runnable edited, Runnable selected, Runnable save) {
        this.editor = editor;
        this.edited = edited;
        this.selected = selected;
        table.setName("pocket-contour-table");
        table.getAccessibleContext().setAccessibleName("Contour elements");
        table.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        table.setSurrendersFocusOnKeystroke(true);
        table.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        table.setDefaultRenderer(Object.class, new Renderer());
        table.getColumnModel().getColumn(0).setMaxWidth(40);
        table.getSelectionModel().addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && !filling) {
                int row = table.getSelectedRow();
                if (row != editor.selected() && row < editor.rows()) {
                    editor.select(row);
                    selected.run();
                }
            }
        });
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 2));
        buttons.add(button(
                "pocket-element-add",
                "Add",
                "Add an element after the selected one (Insert)",
                KeyStroke.getKeyStroke(KeyEvent.VK_INSERT, 0),
                editor::add));
        buttons.add(button(
                "pocket-element-insert",
                "Insert before",
                "Insert an element before the selected one (Shift+Insert)",
                KeyStroke.getKeyStroke(KeyEvent.VK_INSERT, InputEvent.SHIFT_DOWN_MASK),
                editor::insert));
        buttons.add(button(
                "pocket-element-delete",
                "Delete",
                "Delete the selected element (Delete)",
                KeyStroke.getKeyStroke(KeyEvent.VK_DELETE, 0),
                editor::delete));
        buttons.add(button(
                "pocket-element-up",
                "Up",
                "Move the selected element one place earlier (Alt+Up)",
                KeyStroke.getKeyStroke(KeyEvent.VK_UP, InputEvent.ALT_DOWN_MASK),
                editor::moveUp));
        buttons.add(button(
                "pocket-element-down",
                "Down",
                "Move the selected element one place later (Alt+Down)",
                KeyStroke.getKeyStroke(KeyEvent.VK_DOWN, InputEvent.ALT_DOWN_MASK),
                editor::moveDown));
        JButton saveDad = new JButton("Save contour as .dad...");
        saveDad.setName("pocket-save-contour");
        saveDad.setToolTipText("Write the typed contour in the 1988 program's .dad records");
        saveDad.addActionListener(e -> save.run());
        buttons.add(saveDad);
        status.setName("pocket-contour-status");
        panel.add(buttons, BorderLayout.NORTH);
        panel.add(new JScrollPane(table), BorderLayout.CENTER);
        panel.add(status, BorderLayout.SOUTH);
    }

    private JButton button(String name, String text, String tip, KeyStroke key, BooleanSupplier action) {
        AbstractAction a = new AbstractAction(text) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                if (table.isEditing() && !table.getCellEditor().stopCellEditing()) {
                    return;
                }
                if (action.getAsBoolean()) {
                    rowsChanged();
                    edited.run();
                }
            }
        };
        table.getInputMap(JComponent.WHEN_FOCUSED).put(key, name);
        table.getActionMap().put(name, a);
        JButton b = new JButton(a);
        b.setName(name);
        b.setToolTipText(tip);
        b.setFocusable(false);
        return b;
    }

    JComponent component() {
        return panel;
    }

    JTable table() {
        return table;
    }

    /** Shows the editor's rows again (a new contour, a row added or moved) with its selection. */
    void rowsChanged() {
        filling = true;
        try {
            model.fireTableDataChanged();
            if (editor.selected() >= 0) {
                table.getSelectionModel().setSelectionInterval(editor.selected(), editor.selected());
                table.scrollRectToVisible(table.getCellRect(editor.selected(), 0, true));
            }
        } finally {
            filling = false;
        }
        showStatus();
    }

    private void showStatus() {
        Optional<String> note = editor.note();
        Optional<String> r = note.isPresent() ? Optional.empty() : editor.refusal();
        status.setForeground(r.isPresent() ? new Color(180, 0, 0) : Color.BLACK);
        status.setText(r.orElse(note.orElse(editor.rows() + " elements, closed")));
        status.setToolTipText(r.orElse(note.orElse(null)));
        table.repaint();
    }

    private final class Model extends AbstractTableModel {
        private static final long serialVersionUID = 1L;

        @Override
        public int getRowCount() {
            return editor.rows();
        }

        @Override
        public int getColumnCount() {
            return Column.values().length + 1;
        }

        @Override
        public String getColumnName(int c) {
            return c == 0 ? "No." : Column.values()[c - 1].title();
        }

        @Override
        public Object getValueAt(int row, int c) {
            return c == 0 ? Integer.toString(row + 1) : editor.text(row, Column.values()[c - 1]);
        }

        @Override
        public boolean isCellEditable(int row, int c) {
            return c > 0;
        }

        @Override
        public void setValueAt(Object value, int row, int c) {
            if (row >= editor.rows()) {
                return;
            }
            boolean changed = editor.type(row, Column.values()[c - 1], String.valueOf(value));
            fireTableRowsUpdated(row, row);
            showStatus();
            if (changed) {
                edited.run();
            }
        }
    }

    private final class Renderer extends DefaultTableCellRenderer {
        private static final long serialVersionUID = 1L;

        @Override
        public Component getTableCellRendererComponent(
                JTable t, Object value, boolean isSelected, boolean hasFocus, int row, int column) {
            Component c = super.getTableCellRendererComponent(t, value, isSelected, hasFocus, row, column);
            Optional<String> problem =
                    column == 0 ? Optional.empty() : editor.problem(row, Column.values()[column - 1]);
            boolean refused = column == 0 && editor.refusedRow().orElse(-1) == row;
            if (problem.isPresent() || refused) {
                c.setBackground(BAD);
                c.setForeground(Color.BLACK);
            } else if (!isSelected) {
                c.setBackground(Color.WHITE);
                c.setForeground(Color.BLACK);
            }
            setToolTipText(problem.orElse(refused ? editor.refusal().orElse(null) : null));
            return c;
        }
    }
}
