package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.geom.Vec2;

/**
 * The warnings of a module's last result, every one of them, each with the place in the drawing
 * it names when it names one: the planner reads them all in the tab and clicks one to see where.
 * Swing-free, the model of {@link WarningsPanel}.
 */
final class WarningList {

    /** One warning and the drawing point (mm) it names, if any. */
    record Warning(String text, Optional<Vec2> place) {
        Warning {
            Objects.requireNonNull(text, "text");
            Objects.requireNonNull(place, "place");
        }

        @Override
        public String toString() {
            return text;
        }
    }

    // the modules write a place as "(x, y)" or "at x, y" in millimetres, Locale.ROOT
    private static final Pattern PLACE = Pattern.compile("(?:\\(|\\bat )(-?\\d+(?:\\.\\d+)?), (-?\\d+(?:\\.\\d+)?)\\b");

    private final List<Warning> warnings;

    private WarningList(List<Warning> warnings) {
        this.warnings = List.copyOf(warnings);
    }

    static WarningList none() {
        return new WarningList(List.of());
    }

    /** Every text as a warning, in order, with the first place it names. */
    static WarningList of(List<String> texts) {
        List<Warning> l = new ArrayList<>();
        for (String t : texts) {
            l.add(new Warning(t, placeIn(t)));
        }
        return new WarningList(l);
    }

    /** The first drawing point a warning's text names: "(x, y)" or "at x, y" (mm). */
    static Optional<Vec2> placeIn(String text) {
        Matcher m = PLACE.matcher(text);
        if (!m.find()) {
            return Optional.empty();
        }
        return Optional.of(Vec2.of(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2))));
    }

    List<Warning> all() {
        return warnings;
    }

    int size() {
        return warnings.size();
    }

    /** The list's heading: how many warnings, and that a click shows the place of those that have one. */
    String heading() {
        if (warnings.isEmpty()) {
            return "No warnings";
        }
        long placed = warnings.stream().filter(w -> w.place().isPresent()).count();
        return String.format(
                Locale.ROOT,
                "%d warning%s%s",
                warnings.size(),
                warnings.size() == 1 ? "" : "s",
                placed == 0 ? "" : " (click one with a place to see it in the plot)");
    }
}
