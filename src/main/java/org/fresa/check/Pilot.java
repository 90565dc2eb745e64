package org.fresa.check;

import org.fresa.geom.Vec3;

/**
 * A hole the program has already gone straight down its tool axis with a tool that may plunge (a
 * drill, or a centre-cutting cutter asked to plunge). A cutter that does not cut at its centre may
 * then go straight down into it when the hole is at least half the cutter's diameter and the
 * cutter's axis stays no further from the hole's axis than the hole's radius less a quarter of the
 * cutter's diameter: the core of the end face that does not cut (taken as half the cutter's
 * diameter at most) is over the void the first tool left, and only the cutting part of the end
 * face meets material. The descent must end no deeper than the first tool's tip went: below its
 * full diameter a drill leaves the cone of its point, whose material under the cutter's core is
 * the small cone a counterbore to the pilot's depth always meets, as in practice (ISO 14649-11's
 * holes counterbored after a pilot drill).
 *
 * @param tipMm where the first tool's tip went, program frame
 * @param axis the tool axis it went down, from the tip towards the spindle (unit)
 * @param radiusMm the radius of the tool that made it
 */
public record Pilot(Vec3 tipMm, Vec3 axis, double radiusMm) {

    public Pilot {
        java.util.Objects.requireNonNull(tipMm, "tipMm");
        java.util.Objects.requireNonNull(axis, "axis");
        if (!(Double.isFinite(tipMm.x() + tipMm.y() + tipMm.z())
                && radiusMm > 0
                && Double.isFinite(radiusMm)
                && Math.abs(axis.norm() - 1) < 1e-9)) {
            throw new IllegalArgumentException("a pilot hole needs a finite tip, a unit axis and a radius > 0");
        }
    }

    /**
     * True when a cutter of the radius may go straight down its axis from a to b into this hole,
     * within {@code clearMm} (the program's last written digit).
     */
    public boolean admits(Vec3 a, Vec3 b, Vec3 cutterAxis, double cutterRadiusMm, double clearMm) {
        if (!(cutterRadiusMm > 0) || radiusMm < cutterRadiusMm / 2 - 1e-9 || cutterAxis.dot(axis) < 1 - 1e-9) {
            return false;
        }
        double reach = radiusMm - cutterRadiusMm / 2 + clearMm;
        return off(a) <= reach && off(b) <= reach && b.minus(tipMm).dot(axis) >= -clearMm;
    }

    /** How far the point is from the hole's axis. */
    private double off(Vec3 p) {
        Vec3 d = p.minus(tipMm);
        return d.minus(axis.times(d.dot(axis))).norm();
    }
}
