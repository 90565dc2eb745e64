package org.fresa.grading;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * The last girths of the thesis's table 3.1 (Ahrens 1986): the last's perimeter in mm for each
 * French size 29 to 42 and width fitting A to H, copied as data. Each fitting adds 5 mm of girth;
 * from size to size the girth grows by 3.5 to 4.5 mm. A Brazilian size is the French one less 2
 * (table 3.2), so Brazilian 27 to 40 are covered too; the other systems have no equivalent here.
 */
public final class LastGirths {

    /** The width fittings, narrowest first. */
    public static final List<String> FITTINGS = List.of("A", "B", "C", "D", "E", "F", "G", "H");
    /** The smallest and largest French size of the table. */
    public static final int FIRST_FRENCH = 29;

    public static final int LAST_FRENCH = 42;
    /** What each fitting letter adds to the girth (mm). */
    public static final double FITTING_STEP_MM = 5.0;

    /** Fitting A's girth for French sizes 29 to 42 (mm); the others add 5 mm a letter. */
    private static final double[] GIRTH_A_MM = {
        160.0, 163.5, 167.5, 171.0, 175.0, 178.5, 182.5, 186.5, 191.0, 195.0, 199.5, 203.5, 208.0, 212.0
    };

    private LastGirths() {}

    /** The girth of a French size and fitting (mm), or empty outside the table (whole sizes 29 to 42). */
    public static OptionalDouble girthMm(double frenchSize, String fitting) {
        int f = FITTINGS.indexOf(fitting);
        if (f < 0) {
            throw new IllegalArgumentException("width fitting must be one of " + FITTINGS + ": " + fitting);
        }
        if (frenchSize != Math.rint(frenchSize) || frenchSize < FIRST_FRENCH || frenchSize > LAST_FRENCH) {
            return OptionalDouble.empty();
        }
        return OptionalDouble.of(GIRTH_A_MM[(int) frenchSize - FIRST_FRENCH] + f * FITTING_STEP_MM);
    }

    /** The French size of a size in the system (Paris point: itself; Brazilian: + 2), or empty. */
    public static OptionalDouble frenchSize(SizeSystem system, double size) {
        return switch (system) {
            case PARIS -> OptionalDouble.of(size);
            case BR -> OptionalDouble.of(size + 2);
            default -> OptionalDouble.empty();
        };
    }

    /**
     * The fitting whose girth is nearest a measured one for the French size, when it is within
     * half a fitting step (2.5 mm) of it: how a last's width is chosen from its girth.
     */
    public static Optional<String> fittingOf(double frenchSize, double girthMm) {
        for (String f : FITTINGS) {
            OptionalDouble g = girthMm(frenchSize, f);
            if (g.isEmpty()) {
                return Optional.empty();
            }
            if (Math.abs(g.getAsDouble() - girthMm) <= FITTING_STEP_MM / 2) {
                return Optional.of(f);
            }
        }
        return Optional.empty();
    }
}
