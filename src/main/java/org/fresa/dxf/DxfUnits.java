package org.fresa.dxf;

import java.util.Locale;
import java.util.Optional;

/**
 * Drawing units of a DXF file ({@code $INSUNITS}) and their size in millimetres. UNITLESS
 * drawings carry no unit: the reader scales them by the unit the caller chooses.
 */
public enum DxfUnits {
    UNITLESS(0, 1.0),
    INCH(1, 25.4),
    FOOT(2, 304.8),
    MM(4, 1.0),
    CM(5, 10.0),
    M(6, 1000.0),
    MICRON(13, 0.001),
    DM(14, 100.0),
    MIL(9, 0.0254),
    YARD(10, 914.4);

    private final int code;
    private final double mm;

    DxfUnits(int code, double mm) {
        this.code = code;
        this.mm = mm;
    }

    /** The {@code $INSUNITS} value. */
    public int code() {
        return code;
    }

    /** One drawing unit in millimetres (1 for UNITLESS: the caller decides). */
    public double mm() {
        return mm;
    }

    /** The unit of an {@code $INSUNITS} code, empty for codes Fresa does not scale. */
    public static Optional<DxfUnits> ofCode(int code) {
        for (DxfUnits u : values()) {
            if (u.code == code) {
                return Optional.of(u);
            }
        }
        return Optional.empty();
    }

    /** Parses {@code mm}, {@code inch}, {@code cm}, {@code m} (case-insensitive). */
    public static Optional<DxfUnits> ofName(String name) {
        return switch (name.toLowerCase(Locale.ROOT)) {
            case "mm" -> Optional.of(MM);
            case "inch", "in" -> Optional.of(INCH);
            case "cm" -> Optional.of(CM);
            case "m" -> Optional.of(M);
            case "ft", "foot" -> Optional.of(FOOT);
            default -> Optional.empty();
        };
    }
}
