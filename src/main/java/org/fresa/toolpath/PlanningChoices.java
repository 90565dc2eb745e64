package org.fresa.toolpath;

import org.fresa.pocket.EntryRule;

/**
 * What the planner is told where a STEP-NC file is silent or contradicts itself: the user's
 * choices of {@code fresa toolpath}, {@code fresa robot} and the job's {@code <stepnc>}.
 *
 * @param trustCuttingSpeed plan a workingstep whose spindle and cutting speed disagree
 *     ({@link CuttingData}) from the cutting speed, instead of refusing it
 * @param breakthroughMm how far the full diameter of a drill, or the bottom of a milling cutter,
 *     passes the exit of a through hole (mm), 0 to {@value #MAX_BREAKTHROUGH_MM}
 * @param entry how pockets are entered and holes milled on a helix ({@code --entry},
 *     {@code --entry-angle}, {@code --centre-cutting}): with {@code auto} a file's own ramp or
 *     helix keeps its kind, any other kind replaces the file's; no entry is steeper than the angle
 * @param paths whose path conventions: Fresa's own, or the 2016 robot thesis's ({@link ThesisPaths})
 */
public record PlanningChoices(boolean trustCuttingSpeed, double breakthroughMm, EntryRule entry, PathConvention paths) {

    /** Breakthrough of through holes when none is asked (mm). */
    public static final double DEFAULT_BREAKTHROUGH_MM = 1;
    /** Largest breakthrough (mm): more is a unit or typing mistake. */
    public static final double MAX_BREAKTHROUGH_MM = 100;

    /** The file's spindle speeds, 1 mm breakthrough. */
    public static final PlanningChoices DEFAULT = new PlanningChoices(false, DEFAULT_BREAKTHROUGH_MM);

    /** The choices with the default entries ({@link EntryRule#DEFAULT}) and Fresa's own paths. */
    public PlanningChoices(boolean trustCuttingSpeed, double breakthroughMm) {
        this(trustCuttingSpeed, breakthroughMm, EntryRule.DEFAULT, PathConvention.FRESA);
    }

    /** The choices with these entries and Fresa's own paths. */
    public PlanningChoices(boolean trustCuttingSpeed, double breakthroughMm, EntryRule entry) {
        this(trustCuttingSpeed, breakthroughMm, entry, PathConvention.FRESA);
    }

    public PlanningChoices {
        java.util.Objects.requireNonNull(entry, "entry");
        java.util.Objects.requireNonNull(paths, "paths");
        if (!(breakthroughMm >= 0 && breakthroughMm <= MAX_BREAKTHROUGH_MM)) {
            throw new IllegalArgumentException(
                    "breakthrough must be 0 to " + MAX_BREAKTHROUGH_MM + " mm: " + breakthroughMm);
        }
    }

    /** The same choices with these path conventions. */
    public PlanningChoices withPaths(PathConvention p) {
        return new PlanningChoices(trustCuttingSpeed, breakthroughMm, entry, p);
    }
}
