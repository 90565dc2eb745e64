package org.fresa.check;

import java.util.Locale;
import java.util.Optional;
import org.fresa.post.Dialect;

/**
 * How the check reads the program text of one of Fresa's NC dialects: the posts' own
 * {@link Dialect} (its length unit and the word that asks a G02/G03 block for extra full turns),
 * or APT / CL data, which is statements rather than address words; and the smallest step of the
 * coordinates as written (a rounding the entry-angle and floor rules must not count).
 *
 * <p>What every dialect shares: parenthesised and {@code ;} comments, tape marks and
 * {@code %_N_} headers, an O program number, N block numbers, G04 blocks whose address words are
 * a time (X, P, and F on the 840D), G90/G91, G17/G18/G19, incremental I/J/K centres.
 */
public enum NcDialect {
    LINUXCNC(Dialect.LINUXCNC),
    ISO(Dialect.ISO),
    FANUC(Dialect.FANUC),
    SINUMERIK_840D(Dialect.SIEMENS_840D),
    /** G54 with coordinates sets the zero. */
    SINUMERIK_7M(Dialect.SINUMERIK_7M),
    /** APT / CL data: statements, not address words; read by {@link AptStatements}. */
    APT(null);

    private final String id;
    private final double mmPerUnit;
    private final String turnWord;

    NcDialect(Dialect gcode) {
        this.id = gcode == null ? "apt" : gcode.id();
        this.mmPerUnit = gcode == null ? 1 : gcode.mmPerUnit();
        this.turnWord = gcode == null ? null : gcode.turnAddress().orElse(null);
    }

    public String id() {
        return id;
    }

    /** Millimetres per unit of a coordinate word. */
    public double mmPerUnit() {
        return mmPerUnit;
    }

    /** The word of extra turns on an arc block, or null. */
    String turnWord() {
        return turnWord;
    }

    /** The smallest coordinate step the posts write: 0.001 mm (three decimals, or 1 µm). */
    double quantumMm() {
        return 0.001;
    }

    /**
     * The dialect of a post's name: linuxcnc, iso, fanuc, 840d, 7m, 7m-compat (the 7M dialect), apt,
     * ignoring case.
     */
    public static Optional<NcDialect> byPost(String post) {
        String p = post.trim().toLowerCase(Locale.ROOT);
        if (p.equals("7m-compat")) {
            return Optional.of(SINUMERIK_7M);
        }
        for (NcDialect d : values()) {
            if (d.id.equals(p)) {
                return Optional.of(d);
            }
        }
        return Optional.empty();
    }
}
