package org.fresa.grading;

import java.util.List;

/**
 * The thesis's "coordenação" (section 4.4, App. B.1): the heel part of the outline is kept the
 * same over groups of sizes (one heel, and one heel mould, per group of three), while the
 * forepart grades with every size. Heel points grade with the heel's size NBC, the others with
 * ND. Which points are heel points is either the planner's choice of elements, as the thesis
 * does (figure 4.4: the CONTORNO INFERIOR is a list of elements, the points on the boundary P5
 * and P11 belonging to it), or, without such a choice, every point at or behind a boundary line
 * across the length axis (near the ball line). Elements are rebuilt through their graded points
 * (the thesis's 3-point rule), so the outline stays closed across the boundary.
 *
 * <p>Heel factors use (NBC - NP) as in eqs. (4.8)/(4.9); App. B prints (NBC - ND) in (b.3)/(b.4),
 * which would give the pattern's own heel whenever ND = NBC and is taken as a misprint.
 *
 * @param boundaryMm the boundary line's distance from the grading origin along the length axis
 *     (mm); the boundary itself belongs to the heel
 * @param groupSize sizes per heel, in whole sizes (the thesis: 3)
 */
public record Coordination(double boundaryMm, int groupSize, java.util.SortedSet<Integer> heelElements) {

    public Coordination {
        if (!Double.isFinite(boundaryMm)) {
            throw new IllegalArgumentException("boundary must be finite");
        }
        if (groupSize < 1) {
            throw new IllegalArgumentException("group size must be >= 1: " + groupSize);
        }
        heelElements = java.util.Collections.unmodifiableSortedSet(new java.util.TreeSet<>(heelElements));
        if (!heelElements.isEmpty() && heelElements.first() < 1) {
            throw new IllegalArgumentException("heel elements are numbered from 1: " + heelElements.first());
        }
    }

    /** The heel behind a boundary line across the length axis. */
    public Coordination(double boundaryMm, int groupSize) {
        this(boundaryMm, groupSize, new java.util.TreeSet<>());
    }

    /**
     * The heel made of the elements the planner designates (the outline's elements in order, 1
     * the first; a full circle counts as two halves), the CONTORNO INFERIOR of figure 4.4.
     */
    public static Coordination ofHeelElements(java.util.Collection<Integer> heelElements, int groupSize) {
        if (heelElements.isEmpty()) {
            throw new IllegalArgumentException("designate at least one heel element");
        }
        return new Coordination(0, groupSize, new java.util.TreeSet<>(heelElements));
    }

    /**
     * Element numbers as a planner types them: {@code 1-4,18-20} (ranges and single numbers,
     * commas or blanks between).
     *
     * @throws IllegalArgumentException naming what does not read
     */
    public static java.util.SortedSet<Integer> parseElements(String text) {
        java.util.SortedSet<Integer> out = new java.util.TreeSet<>();
        for (String tok : text.trim().split("[,\\s]+")) {
            if (tok.isEmpty()) {
                continue;
            }
            String[] ab = tok.split("-", -1);
            try {
                int a = Integer.parseInt(ab[0].trim());
                int b = ab.length == 2 ? Integer.parseInt(ab[1].trim()) : a;
                if (ab.length > 2 || a < 1 || b < a || b > 100_000) {
                    throw new NumberFormatException();
                }
                for (int i = a; i <= b; i++) {
                    out.add(i);
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(
                        "heel elements: expected numbers from 1 or ranges like 1-4, found '" + tok + "'");
            }
        }
        if (out.isEmpty()) {
            throw new IllegalArgumentException("heel elements: none given");
        }
        return out;
    }

    /** Whether the heel is the planner's elements rather than what lies behind a boundary line. */
    public boolean byElements() {
        return !heelElements.isEmpty();
    }

    /**
     * Why the designated elements cannot split this pattern (an element it does not have, or no
     * forepart element left), or empty.
     */
    public java.util.Optional<String> misfit(EscomPattern p) {
        if (!byElements()) {
            return java.util.Optional.empty();
        }
        int n = p.elements().size();
        if (heelElements.last() > n) {
            return java.util.Optional.of(
                    "heel element " + heelElements.last() + " does not exist: the outline has " + n + " elements");
        }
        if (heelElements.size() == n) {
            return java.util.Optional.of("every element is a heel element: designate the forepart's (upper) elements"
                    + " by leaving them out");
        }
        return java.util.Optional.empty();
    }

    /**
     * Whether the pattern's point grades with the heel: by the designated elements, a point of
     * any heel element (so the junctions with the forepart belong to the heel, as P5 and P11 of
     * figure b.1); else by its length coordinate (from the origin, mm).
     */
    public boolean isHeelPoint(EscomPattern p, String point, double lengthCoordinateMm) {
        if (!byElements()) {
            return isHeel(lengthCoordinateMm);
        }
        List<EscomPattern.Element> els = p.elements();
        for (int i = 0; i < els.size(); i++) {
            if (heelElements.contains(i + 1) && uses(els.get(i), point)) {
                return true;
            }
        }
        return false;
    }

    private static boolean uses(EscomPattern.Element e, String point) {
        if (e instanceof EscomPattern.Line l) {
            return l.from().equals(point) || l.to().equals(point);
        }
        if (e instanceof EscomPattern.Circle3 c) {
            return c.from().equals(point) || c.via().equals(point) || c.to().equals(point);
        }
        EscomPattern.CircleR r = (EscomPattern.CircleR) e;
        return r.from().equals(point) || r.to().equals(point);
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
