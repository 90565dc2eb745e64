package org.fresa.model;

import org.fresa.geom.Transform3;

/**
 * A frame placed in its parent frame, as a planner types it: a translation in mm and rotations in
 * degrees, composed as R = Rz(rz) Ry(ry) Rx(rx) (spec/cli.md, the thesis's table 5.1).
 */
public record Placement(double xMm, double yMm, double zMm, double rxDeg, double ryDeg, double rzDeg) {

    public static final Placement ORIGIN = new Placement(0, 0, 0, 0, 0, 0);

    public Placement {
        double[] all = {xMm, yMm, zMm, rxDeg, ryDeg, rzDeg};
        for (double v : all) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("placement values must be finite: " + v);
            }
        }
    }

    public Transform3 toTransform() {
        return Transform3.ofXyzRpyDeg(xMm, yMm, zMm, rxDeg, ryDeg, rzDeg);
    }
}
