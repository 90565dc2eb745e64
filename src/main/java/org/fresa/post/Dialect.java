package org.fresa.post;

import java.util.Locale;
import java.util.Optional;
import org.fresa.model.EnumWords;

/**
 * The NC dialects Fresa writes, with the words each control reads the same whatever the process
 * (milling or sheet cutting): block numbers, comments, the dwell block and its time unit, the
 * spindle words, the tool change, the turn word of a helix and the length unit of a coordinate
 * word. The posts keep only what belongs to their process (the milling posts' safe start and end,
 * the jet codes of sheet cutting) and the number format of their coordinates.
 *
 * <p>Dwells are in seconds on every control here, but not behind the same address: LinuxCNC reads
 * {@code G4 P} in seconds, the 840D {@code G4 F} in seconds (F after G4 is a time, not a feed),
 * and the Fanuc-like ISO controls {@code G04 X} in seconds only with a decimal point: without one
 * a Fanuc reads X in the least input increment (ms), and P is an integer count of milliseconds.
 */
public enum Dialect {
    /** LinuxCNC RS274/NGC: no block numbers, parenthesised comments, P on G02/G03 is the number of turns. */
    LINUXCNC("linuxcnc", false, "G4 P", false, "P", 1),
    /** Plain ISO 6983: N numbers, G04 X seconds with the point, one block per extra helix turn. */
    ISO("iso", true, "G04 X", true, null, 1),
    /** Fanuc 0i/30i: N numbers, two-digit M words, G04 X seconds with the point, one block per extra turn. */
    FANUC("fanuc", true, "G04 X", true, null, 1),
    /** Siemens Sinumerik 840D in Siemens mode: N numbers, {@code ;} comments, G4 F seconds, {@code TURN=}. */
    SIEMENS_840D("840d", true, "G4 F", false, "TURN", 1),
    /**
     * The 1988 thesis's Siemens Sinumerik 7M (DIN 66025): integer micrometres, blocks N05, N10, ...
     * written by its own post; it writes no dwell and no helix.
     */
    SINUMERIK_7M("7m", true, null, false, null, 0.001);

    private final String id;
    private final boolean numbered;
    private final String dwellWord;
    private final boolean dwellNeedsPoint;
    private final String turnAddress;
    private final double mmPerUnit;

    Dialect(
            String id,
            boolean numbered,
            String dwellWord,
            boolean dwellNeedsPoint,
            String turnAddress,
            double mmPerUnit) {
        this.id = id;
        this.numbered = numbered;
        this.dwellWord = dwellWord;
        this.dwellNeedsPoint = dwellNeedsPoint;
        this.turnAddress = turnAddress;
        this.mmPerUnit = mmPerUnit;
    }

    /** The name the command line and job files give it ({@code --post 840d}). */
    public String id() {
        return id;
    }

    @Override
    public String toString() {
        return id;
    }

    /** The dialect of a name, ignoring case and surrounding blanks. */
    public static Optional<Dialect> byName(String name) {
        return EnumWords.parse(Dialect.class, Dialect::id, name.trim().toLowerCase(Locale.ROOT));
    }

    /** Whether blocks carry N numbers. */
    public boolean numbered() {
        return numbered;
    }

    /** A whole comment block around text already safe for it: {@code ; text} on the 840D, else {@code (text)}. */
    public String comment(String safeText) {
        return this == SIEMENS_840D ? "; " + safeText : "(" + safeText + ")";
    }

    /**
     * The dwell block, the time written in seconds by the caller ({@code G4 P1.5}, {@code G04 X2.000},
     * {@code G4 F0.5}).
     *
     * @throws IllegalStateException on the 7M, whose posts write no dwell
     */
    public String dwell(String seconds) {
        if (dwellWord == null) {
            throw new IllegalStateException("the " + id + " posts write no dwell");
        }
        return dwellWord + seconds;
    }

    /** Whether the dwell time must carry a decimal point to mean seconds (the Fanuc-like ISO controls). */
    public boolean dwellNeedsPoint() {
        return dwellNeedsPoint;
    }

    /** The blocks' M words with two digits ({@code M03}, {@code M05}, {@code M06}), as Fanuc writes them. */
    private boolean twoDigitM() {
        return this == FANUC;
    }

    /** The block that starts the spindle at the speed, clockwise (M3) or counter-clockwise (M4). */
    public String spindleOn(long rpm, boolean clockwise) {
        String m = clockwise ? "M3" : "M4";
        return "S" + rpm + " " + (twoDigitM() ? "M0" + m.substring(1) : m);
    }

    /** The block that stops the spindle. */
    public String spindleOff() {
        return twoDigitM() ? "M05" : "M5";
    }

    /**
     * The blocks that stop the spindle, load tool {@code tool} and apply its length offset where the
     * program must ask for it (G43 H on LinuxCNC and Fanuc, D1 on the 840D; plain ISO leaves it to
     * the control's tool data).
     */
    public java.util.List<String> toolChange(int tool) {
        return switch (this) {
            case LINUXCNC -> java.util.List.of("M5", "T" + tool + " M6", "G43 H" + tool);
            case ISO -> java.util.List.of("M5", "T" + tool + " M6");
            case FANUC -> java.util.List.of("M05", "T" + tool + " M06", "G43 H" + tool);
            case SIEMENS_840D -> java.util.List.of("M5", "T" + tool + " D1", "M6");
            case SINUMERIK_7M -> java.util.List.of("T" + String.format(Locale.ROOT, "%02d", tool) + " M06");
        };
    }

    /** The address of the word that asks an arc block for extra full turns, or empty. */
    public Optional<String> turnAddress() {
        return Optional.ofNullable(turnAddress);
    }

    /**
     * The word that asks an arc block for {@code extraTurns} more full turns, or empty when the
     * dialect has none (each turn is then its own block): LinuxCNC's P counts the turns (P1 is none
     * extra), the 840D's TURN= the extra ones.
     */
    public Optional<String> turnsWord(int extraTurns) {
        return switch (this) {
            case LINUXCNC -> Optional.of("P" + (extraTurns + 1));
            case SIEMENS_840D -> Optional.of("TURN=" + extraTurns);
            default -> Optional.empty();
        };
    }

    /** Millimetres per unit of a coordinate word (the 7M writes integer micrometres). */
    public double mmPerUnit() {
        return mmPerUnit;
    }
}
