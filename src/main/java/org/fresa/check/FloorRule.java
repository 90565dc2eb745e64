package org.fresa.check;

import org.fresa.geom.Vec3;

/**
 * No move goes below the floor the job asks for (the pocket's bottom, the hole's exit) by more
 * than its stated breakthrough. The coordinates' last written digit is allowed for.
 */
public record FloorRule() implements Rule {

    @Override
    public String name() {
        return "floor";
    }

    @Override
    public String statement() {
        return "no move goes below the floor by more than the stated breakthrough";
    }

    @Override
    public String broken(Step s, Limits l) {
        if (Double.isNaN(l.floorZMm()) || s.path().isEmpty()) {
            return null;
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
}
