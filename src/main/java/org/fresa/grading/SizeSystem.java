package org.fresa.grading;

import java.util.Locale;

/**
 * A shoe-size system: how a size number relates to the last length, and the default grading
 * steps per whole size.
 *
 * <p>Steps are in mm per <em>whole size</em> (the {@link #wholeSizeStep()} of the size number):
 * the length step VC and the width step VL of the thesis. Width steps that the sources do not
 * give are a quarter of the length step, the thesis's ratio (VL 1.66 = VC 6.66 / 4).
 *
 * <ul>
 *   <li>{@link #BR} Brazilian: French - 2 (thesis, table 3.2); the thesis's VC 6.66, VL 1.66 mm.
 *   <li>{@link #PARIS} Paris point (French/EU): 2/3 cm per size from zero (about 6.67 mm).
 *   <li>{@link #UK} English: 1/3 inch (about 8.47 mm) per size; size 0 is a last of 25
 *       barleycorns (8 1/3 inch), so length = (N + 25) / 3 inch.
 *   <li>{@link #US}: the English step with the zero point of the thesis's table 3.2,
 *       US = English + 1 1/2 (the usual women's convention; men's US is often English + 1).
 *   <li>{@link #MONDOPOINT}: the size is the length in mm; a whole size is 10 mm, a half size
 *       5 mm (DIN 66074-2 in practice).
 * </ul>
 */
public enum SizeSystem {
    BR("br", "Brazilian", 6.66, 1.66, 1),
    PARIS("paris", "Paris point", 20.0 / 3, 20.0 / 12, 1),
    UK("uk", "English (UK)", 25.4 / 3, 25.4 / 12, 1),
    US("us", "American (US)", 25.4 / 3, 25.4 / 12, 1),
    MONDOPOINT("mondopoint", "Mondopoint", 10, 2.5, 10);

    private final String id;
    private final String title;
    private final double lengthStepMm;
    private final double widthStepMm;
    private final double wholeSizeStep;

    SizeSystem(String id, String title, double lengthStepMm, double widthStepMm, double wholeSizeStep) {
        this.id = id;
        this.title = title;
        this.lengthStepMm = lengthStepMm;
        this.widthStepMm = widthStepMm;
        this.wholeSizeStep = wholeSizeStep;
    }

    public String id() {
        return id;
    }

    public String title() {
        return title;
    }

    /** VC: length change per whole size, mm. */
    public double lengthStepMm() {
        return lengthStepMm;
    }

    /** VL: width change per whole size, mm. */
    public double widthStepMm() {
        return widthStepMm;
    }

    /** How much the size number changes from one whole size to the next (10 for Mondopoint). */
    public double wholeSizeStep() {
        return wholeSizeStep;
    }

    /** The number of whole sizes from one size number to another (may be fractional). */
    public double sizesBetween(double fromSize, double toSize) {
        return (toSize - fromSize) / wholeSizeStep;
    }

    /**
     * The nominal last length of a size number, in mm (the system's definition; the thesis's
     * Brazilian VC 6.66 is the rounded Paris point, so this uses 20/3 mm for BR as for Paris).
     */
    public double lastLengthMm(double size) {
        switch (this) {
            case BR:
                return (size + 2) * 20.0 / 3;
            case PARIS:
                return size * 20.0 / 3;
            case UK:
                return (size + 25) * 25.4 / 3;
            case US:
                return (size - 1.5 + 25) * 25.4 / 3;
            case MONDOPOINT:
            default:
                return size;
        }
    }

    /** The size number whose nominal last length is the given one (not rounded). */
    public double sizeOfLastLength(double lengthMm) {
        switch (this) {
            case BR:
                return lengthMm * 3 / 20.0 - 2;
            case PARIS:
                return lengthMm * 3 / 20.0;
            case UK:
                return lengthMm * 3 / 25.4 - 25;
            case US:
                return lengthMm * 3 / 25.4 - 25 + 1.5;
            case MONDOPOINT:
            default:
                return lengthMm;
        }
    }

    /** The longest last a size may have (mm): beyond any foot, and it keeps graded outlines within reach. */
    public static final double MAX_LAST_LENGTH_MM = 1000;

    /** The largest size number of the system: the one whose last is {@link #MAX_LAST_LENGTH_MM} long. */
    public double maxSize() {
        return sizeOfLastLength(MAX_LAST_LENGTH_MM);
    }

    /**
     * Checks a size number: above 0 and at most {@link #maxSize()}.
     *
     * @param what how the message names it ("base size", "size")
     * @throws IllegalArgumentException with a message for the user
     */
    public double checkSize(double size, String what) {
        if (!(size > 0 && size <= maxSize())) {
            throw new IllegalArgumentException(what + " " + trim(size) + " is not a " + title + " size: expected a "
                    + "number above 0 and at most " + trim(Math.floor(maxSize() * 100) / 100) + " (a last of "
                    + trim(MAX_LAST_LENGTH_MM) + " mm)");
        }
        return size;
    }

    private static String trim(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    /** The size in another system with the same nominal last length, rounded to a half size. */
    public double convert(double size, SizeSystem to) {
        double s = to.sizeOfLastLength(lastLengthMm(size)) / to.wholeSizeStep;
        return Math.round(s * 2) / 2.0 * to.wholeSizeStep;
    }

    /** @throws IllegalArgumentException for a name that is not a system */
    @Override
    public String toString() {
        return id;
    }

    public static SizeSystem ofId(String id) {
        String s = id.trim().toLowerCase(Locale.ROOT);
        for (SizeSystem v : values()) {
            if (v.id.equals(s)) {
                return v;
            }
        }
        throw new IllegalArgumentException("expected br, paris, uk, us or mondopoint, found '" + id + "'");
    }
}
