package org.fresa.ui;

import java.awt.Color;
import java.util.Map;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JTextField;

/**
 * How a settings form shows what is wrong with the typed settings: each refused field marked with
 * its problem as tooltip, the action disabled with the reason, and the first problem said on the
 * line under the action (a long one wrapped within the form, whole in the tooltip).
 */
final class ProblemMarks {

    /** The background of a field whose value is refused. */
    static final Color BAD_FIELD = new Color(255, 220, 220);

    /** The colour of a problem said under the action. */
    static final Color PROBLEM = new Color(180, 0, 0);

    private ProblemMarks() {}

    /**
     * Marks one field: refused, its problem as tooltip; good, its meaning in the tab again.
     *
     * @param problem the field's problem, or null when its value is good
     */
    static void mark(JComponent field, String problem, String tab) {
        field.setBackground(problem == null ? (field instanceof JTextField ? Color.WHITE : null) : BAD_FIELD);
        field.setToolTipText(problem != null ? problem : Tooltips.meaning(tab, field));
    }

    /**
     * The action runs only on good settings; its tooltip says what it does, or what comes first: the
     * input file when that is all that is missing, else the marked fields.
     */
    static void enable(JButton action, Map<String, String> problems, String does, String input, String openFirst) {
        action.setEnabled(problems.isEmpty());
        action.setToolTipText(
                problems.isEmpty()
                        ? does
                        : problems.size() == 1 && problems.containsKey(input)
                                ? openFirst
                                : "Correct the marked field first");
    }

    /** The first problem and how many more there are ("... (and 2 more)"); a blank for none. */
    static String first(Map<String, String> problems) {
        return problems.isEmpty()
                ? " "
                : problems.values().iterator().next()
                        + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : "");
    }

    /**
     * Says the text on the line under the action: as it is up to the given length, else wrapped
     * (Swing's HTML) within the given width, and whole in the tooltip.
     */
    static void say(JLabel line, String text, int shortLength, int widthPx) {
        line.setText(
                text.length() <= shortLength
                        ? text
                        : "<html><div style='width:" + widthPx + "px'>"
                                + text.replace("&", "&amp;").replace("<", "&lt;") + "</div></html>");
        line.setToolTipText(text.isBlank() ? null : text);
    }
}
