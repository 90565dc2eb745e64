package org.fresa.kin;

import org.fresa.geom.Transform3;

/** Orientation angles of the thesis's eq. 1 and of trajectory.csv. */
public final class Orientation {
    private Orientation() {}

    /**
     * {roll, pitch, yaw} in degrees with R = Rz(roll) Ry(pitch) Rx(yaw), pitch in [-90, 90]. At
     * pitch = +-90 (gimbal lock) roll is set to 0 and yaw carries the whole turn.
     */
    public static double[] rollPitchYawDeg(Transform3 t) {
        double cp = Math.hypot(t.r00(), t.r10());
        double pitch = Math.atan2(-t.r20(), cp);
        double roll;
        double yaw;
        if (cp > 1e-12) {
            roll = Math.atan2(t.r10(), t.r00());
            yaw = Math.atan2(t.r21(), t.r22());
        } else {
            roll = 0;
            yaw = Math.atan2(-t.r12(), t.r11());
        }
        return new double[] {Math.toDegrees(roll), Math.toDegrees(pitch), Math.toDegrees(yaw)};
    }
}
