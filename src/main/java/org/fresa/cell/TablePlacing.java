package org.fresa.cell;

import java.util.Locale;
import org.fresa.model.CamInputException;
import org.fresa.model.EnumWords;

/**
 * Where the table of a robot cell comes from: the placement the planner typed, or the placement
 * search ({@code --place auto}, the job's {@code place="auto"}), which replaces the robot -> table
 * placement by the one reaching every target with the largest joint-limit margin.
 */
public enum TablePlacing {
    /** The robot -> table placement as given. */
    GIVEN,
    /** The robot -> table placement searched. */
    AUTO;

    /** The name on the command line and in the job file. */
    public String id() {
        return EnumWords.of(this);
    }

    /**
     * Reads {@code --place}.
     *
     * @throws CamInputException naming the option for anything but {@code auto} or {@code given}
     */
    public static TablePlacing parse(String option, String text) throws CamInputException {
        return EnumWords.parse(TablePlacing.class, TablePlacing::id, text.trim().toLowerCase(Locale.ROOT))
                .orElseThrow(() -> new CamInputException(option, "expected auto or given, got '" + text + "'"));
    }
}
