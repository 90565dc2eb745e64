package org.fresa.dxf;

import java.util.Locale;
import java.util.Optional;
import org.fresa.model.EnumWords;

/**
 * The units a drawing is read in: {@link #AUTO} (the default: the drawing's {@code $INSUNITS}),
 * or the units given (the command line also takes {@code in} and {@code ft}).
 */
public enum DrawingUnits {
    MM(DxfUnits.MM),
    INCH(DxfUnits.INCH),
    AUTO(null),
    CM(DxfUnits.CM),
    M(DxfUnits.M),
    FOOT(DxfUnits.FOOT);

    private final DxfUnits units;

    DrawingUnits(DxfUnits units) {
        this.units = units;
    }

    /** The name as written: {@code mm}, {@code inch}, {@code auto}, ... */
    public String word() {
        return EnumWords.of(this);
    }

    /** The units asked for, empty for the drawing's own. */
    public Optional<DxfUnits> units() {
        return Optional.ofNullable(units);
    }

    /** The units of a name ({@link #word()}, {@code in} or {@code ft}; ignoring case and blanks), or empty. */
    public static Optional<DrawingUnits> of(String name) {
        String n = name.trim().toLowerCase(Locale.ROOT);
        if (n.equals("auto")) {
            return Optional.of(AUTO);
        }
        return DxfUnits.ofName(n).flatMap(u -> {
            for (DrawingUnits d : values()) {
                if (d.units == u) {
                    return Optional.of(d);
                }
            }
            return Optional.empty();
        });
    }

    @Override
    public String toString() {
        return word();
    }
}
