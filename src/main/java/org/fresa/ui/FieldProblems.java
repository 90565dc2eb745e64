package org.fresa.ui;

import java.util.Optional;
import org.fresa.setting.SettingRange;

/**
 * What is wrong with a number typed into a field, in the planner's words: the field's label, then
 * what was expected (the range the planner accepts), never an exception's text or an option name.
 */
final class FieldProblems {

    private FieldProblems() {}

    /** The problem with the typed text as a number of the range; empty when it is one. */
    static Optional<String> number(String label, String text, SettingRange range) {
        String t = text.trim();
        double v;
        try {
            v = Double.parseDouble(t);
        } catch (NumberFormatException e) {
            return Optional.of(notANumber(label, t));
        }
        if (!range.contains(v)) {
            return Optional.of(label + ": " + range.problem(v) + ".");
        }
        return Optional.empty();
    }

    /** "Kerf (mm): '6,5' is not a number (decimals take a point: 6.5)." */
    static String notANumber(String label, String text) {
        return label + ": "
                + (text.isEmpty()
                        ? "a number is needed."
                        : "'" + text + "' is not a number"
                                + (text.contains(",")
                                        ? " (decimals take a point: " + text.replace(',', '.') + ")."
                                        : "."));
    }
}
