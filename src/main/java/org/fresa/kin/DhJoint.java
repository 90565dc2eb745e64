package org.fresa.kin;

import java.util.Objects;

/**
 * One row of a standard Denavit-Hartenberg table, A = Rz(theta) Tz(d) Tx(a) Rx(alpha).
 *
 * <p>For a revolute joint theta = q + {@code thetaDeg} and d = {@code dMm}; for a prismatic joint
 * d = q + {@code dMm} and theta = {@code thetaDeg}. So the parameter that carries the variable
 * holds its offset, the other one its constant value.
 *
 * @param type revolute or prismatic
 * @param aMm link length a (mm)
 * @param alphaDeg link twist alpha (degrees)
 * @param dMm link offset d (mm), or the offset of q for a prismatic joint
 * @param thetaDeg joint angle theta (degrees), or the offset of q for a revolute joint
 * @param qMin lower joint limit in the joint's unit (deg or mm)
 * @param qMax upper joint limit, > qMin
 */
public record DhJoint(
        JointType type, double aMm, double alphaDeg, double dMm, double thetaDeg, double qMin, double qMax) {

    public DhJoint {
        Objects.requireNonNull(type, "type");
        double[] all = {aMm, alphaDeg, dMm, thetaDeg, qMin, qMax};
        for (double v : all) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("DH values must be finite: " + v);
            }
        }
        if (!(qMax > qMin)) {
            throw new IllegalArgumentException("joint limits must have max > min: " + qMin + " .. " + qMax);
        }
    }

    public static DhJoint revolute(
            double aMm, double alphaDeg, double dMm, double offsetDeg, double minDeg, double maxDeg) {
        return new DhJoint(JointType.REVOLUTE, aMm, alphaDeg, dMm, offsetDeg, minDeg, maxDeg);
    }

    public static DhJoint prismatic(
            double aMm, double alphaDeg, double offsetMm, double thetaDeg, double minMm, double maxMm) {
        return new DhJoint(JointType.PRISMATIC, aMm, alphaDeg, offsetMm, thetaDeg, minMm, maxMm);
    }

    /** The offset added to q: thetaDeg (revolute) or dMm (prismatic). */
    public double offset() {
        return type == JointType.REVOLUTE ? thetaDeg : dMm;
    }
}
