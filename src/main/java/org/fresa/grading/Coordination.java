package org.fresa.grading;

/**
 * The thesis's "coordenação" (section 4.4, App. B.1): the heel part of the outline is kept the
 * same over groups of sizes (one heel, and one heel mould, per group of three), while the
 * forepart grades with every size. Points at or behind the boundary line (across the length axis,
 * near the ball line) are heel points and grade with the heel's size NBC; the others with ND.
 * Elements are rebuilt through their graded points (the thesis's 3-point rule), so the outline
 * stays closed across the boundary.
 *
 * <p>Heel factors use (NBC - NP) as in eqs. (4.8)/(4.9); App. B prints (NBC - ND) in (b.3)/(b.4),
 * which would give the pattern's own heel whenever ND = NBC and is taken as a misprint.
 *
 * @param boundaryMm the boundary line's distance from the grading origin along the length axis
 *     (mm); the boundary itself belongs to the heel
 * @param groupSize sizes per heel, in whole sizes (the thesis: 3)
 */
public record Coordination(double boundaryMm, int groupSize) {

    public Coordination {
        if (!Double.isFinite(boundaryMm)) {
            throw new IllegalArgumentException("boundary must be finite");
        }
        if (groupSize < 1) {
            throw new IllegalArgumentException("group size must be >= 1: " + groupSize);
        }
    }

    /**
     * NBC: the size whose heel size ND gets. Groups are centred on the pattern size: with NP 35
     * and groups of 3, sizes 34, 35, 36 take the heel of 35 and 37, 38, 39 that of 38.
     */
    public double heelSize(double size, double baseSize, SizeSystem system) {
        double n = system.sizesBetween(baseSize, size);
        double k = Math.floor(n / groupSize + 0.5 + 1e-9);
        return baseSize + k * groupSize * system.wholeSizeStep();
    }

    /** True when a point with this length coordinate (from the origin, mm) is a heel point. */
    public boolean isHeel(double lengthCoordinateMm) {
        return lengthCoordinateMm <= boundaryMm + 1e-9;
    }
}
