package org.fresa.check;

import org.fresa.geom.Vec3;

/**
 * No move goes below the floor the job asks for (the pocket's bottom, the hole's exit) by more
 * than its stated breakthrough. The coordinates' last written digit is allowed for.
 *
 * <p>"Below" is measured along the section's tool axis, as the entry rule's descents are: along
 * +Z the floor is the job's floor height; along another axis (a side or the underside of the part,
 * reached by a tool the robot or a turned part orients) it is the stock's face farthest along the
 * axis against the tool, the material's end on that side. Where the stock is unbounded along that
 * axis nothing is stated there and the rule has nothing to compare.
 */
public final class FloorRule extends Rule {

    /** How far from +Z an axis may be and still be read as +Z (the posts' own test). */
    static final double AXIS_TOLERANCE = 1e-9;

    public FloorRule() {
        super(
                "floor",
                "no move goes below the floor, measured along the tool axis, by more than the stated breakthrough");
    }

    @Override
    public String broken(Step s, Limits l) {
        if (Double.isNaN(l.floorZMm()) || s.path().isEmpty()) {
            return null;
        }
        if (s.axis().distance(Vec3.UNIT_Z) > AXIS_TOLERANCE) {
            return alongAxis(s, l);
        }
        double lowest = l.floorZMm() - l.breakthroughMm() - s.dialect().quantumMm();
        Vec3 deepest = null;
        for (Vec3 v : s.path()) {
            if (v.z() < lowest && (deepest == null || v.z() < deepest.z())) {
                deepest = v;
            }
        }
        if (deepest == null) {
            return null;
        }
        return "move to Z " + Num.of(deepest.z()) + " mm, " + Num.of(l.floorZMm() - deepest.z())
                + " mm below the floor Z " + Num.of(l.floorZMm()) + " mm; the breakthrough allowed is "
                + Num.of(l.breakthroughMm()) + " mm";
    }

    /**
     * The floor along a tool axis other than +Z: the least height along the axis of the stock's
     * corners (the stock's bottom raised to the job's floor), so that along +Z it is the floor
     * itself.
     */
    private static String alongAxis(Step s, Limits l) {
        Vec3 a = s.axis();
        Limits.Stock st = l.stock();
        double floor = Double.POSITIVE_INFINITY;
        double[] xs = {st.minXMm(), st.maxXMm()};
        double[] ys = {st.minYMm(), st.maxYMm()};
        double[] zs = {Math.max(st.minZMm(), l.floorZMm()), st.maxZMm()};
        for (double x : xs) {
            for (double y : ys) {
                for (double z : zs) {
                    // a side the axis does not reach adds nothing, even when unbounded
                    double h = along(x, a.x()) + along(y, a.y()) + along(z, a.z());
                    floor = Math.min(floor, h);
                }
            }
        }
        if (!Double.isFinite(floor)) {
            return null;
        }
        double quantum = s.dialect().quantumMm() * (Math.abs(a.x()) + Math.abs(a.y()) + Math.abs(a.z()));
        double lowest = floor - l.breakthroughMm() - quantum;
        Vec3 deepest = null;
        for (Vec3 v : s.path()) {
            if (v.dot(a) < lowest && (deepest == null || v.dot(a) < deepest.dot(a))) {
                deepest = v;
            }
        }
        if (deepest == null) {
            return null;
        }
        return "move to X " + Num.of(deepest.x()) + " Y " + Num.of(deepest.y()) + " Z " + Num.of(deepest.z())
                + " mm, " + Num.of(floor - deepest.dot(a)) + " mm below the floor along the tool axis ("
                + Num.of(a.x()) + ", " + Num.of(a.y()) + ", " + Num.of(a.z()) + "), the stock's far side at "
                + Num.of(floor) + " mm along it; the breakthrough allowed is " + Num.of(l.breakthroughMm()) + " mm";
    }

    private static double along(double side, double component) {
        return Math.abs(component) < AXIS_TOLERANCE ? 0 : side * component;
    }
}
