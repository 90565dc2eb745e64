package org.fresa.kin;

import java.util.List;
import java.util.Objects;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * A Tricept-like hybrid robot (3-UPS parallel part with a central passive leg, then a spherical
 * wrist), as spec/robots.md defines the COMAU Tricept 806 from the thesis's eqs. 27-40.
 *
 * <p>Base origin O at the centre of the fixed base, z up, the robot working below it. Leg base
 * joints A_k on a circle of radius {@code baseRadiusMm} in z = 0 at 90, 210 and 330 degrees. The
 * wrist centre W, the platform centre C = (|OW| - d_eff) OW/|OW|, the platform joints B_k on the
 * circle of radius {@code platformRadiusMm} about C normal to OC, coplanar with O, C and A_k, on
 * A_k's side. Joints q1..q3 are the leg lengths |B_k - A_k| (mm); q4..q6 the wrist (deg), whose
 * base frame at W has z = OC/|OC| and x = (B_1 - C)/|B_1 - C|, then the DH rows
 * (0, 0, -90, q4 + 90), (0, 0, 90, q5 - 90), (0, e_ffl, 0, q6 + 180).
 *
 * @param name command-line name
 * @param description one line for people
 * @param baseRadiusMm r_b
 * @param platformRadiusMm r_p
 * @param centreOffsetMm d_eff, from platform centre C to wrist centre W
 * @param effectorLengthMm e_ffl, from W to the tool tip
 * @param legs the three leg limits (mm)
 * @param wrist the three wrist limits (deg)
 * @param tool the tool frame (TCP) in the flange frame, the flange being e_ffl beyond W
 */
public record TriceptRobot(
        String name,
        String description,
        double baseRadiusMm,
        double platformRadiusMm,
        double centreOffsetMm,
        double effectorLengthMm,
        List<JointLimit> legs,
        List<JointLimit> wrist,
        Transform3 tool)
        implements Robot {

    public TriceptRobot {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(description, "description");
        legs = List.copyOf(legs);
        wrist = List.copyOf(wrist);
        Objects.requireNonNull(tool, "tool");
        if (legs.size() != 3 || wrist.size() != 3) {
            throw new IllegalArgumentException("a Tricept has 3 legs and a 3-joint wrist");
        }
        if (!(baseRadiusMm > 0) || !(platformRadiusMm > 0) || !(centreOffsetMm >= 0) || !(effectorLengthMm >= 0)) {
            throw new IllegalArgumentException("Tricept dimensions must be positive");
        }
    }

    /** A Tricept whose TCP is its flange. */
    public TriceptRobot(
            String name,
            String description,
            double baseRadiusMm,
            double platformRadiusMm,
            double centreOffsetMm,
            double effectorLengthMm,
            List<JointLimit> legs,
            List<JointLimit> wrist) {
        this(
                name,
                description,
                baseRadiusMm,
                platformRadiusMm,
                centreOffsetMm,
                effectorLengthMm,
                legs,
                wrist,
                Transform3.IDENTITY);
    }

    @Override
    public TriceptRobot withTool(Transform3 newTool) {
        return new TriceptRobot(
                name,
                description,
                baseRadiusMm,
                platformRadiusMm,
                centreOffsetMm,
                effectorLengthMm,
                legs,
                wrist,
                newTool);
    }

    @Override
    public List<JointLimit> joints() {
        return List.of(legs.get(0), legs.get(1), legs.get(2), wrist.get(0), wrist.get(1), wrist.get(2));
    }

    /** The leg base joint A_k (k = 0, 1, 2) in the base frame. */
    public Vec3 legBase(int k) {
        double ang = Math.toRadians(90 + 120 * k);
        return new Vec3(baseRadiusMm * Math.cos(ang), baseRadiusMm * Math.sin(ang), 0);
    }

    /** The wrist as a DH chain whose base is the wrist frame at W (identity: frame at origin). */
    public DenavitHartenbergChain wristChain(Transform3 wristFrame) {
        return new DenavitHartenbergChain(
                List.of(
                        DhJoint.revolute(
                                0, -90, 0, 90, wrist.get(0).min(), wrist.get(0).max()),
                        DhJoint.revolute(
                                0, 90, 0, -90, wrist.get(1).min(), wrist.get(1).max()),
                        DhJoint.revolute(
                                0,
                                0,
                                effectorLengthMm,
                                180,
                                wrist.get(2).min(),
                                wrist.get(2).max())),
                wristFrame,
                Transform3.IDENTITY);
    }

    @Override
    public Transform3 forward(double... q) {
        if (q.length != 6) {
            throw new IllegalArgumentException("expected 6 joint values, got " + q.length);
        }
        TriceptGeometry geo = new TriceptGeometry(this);
        double[] w = new double[3];
        if (!geo.wristCentre(q[0], q[1], q[2], null, w)) {
            throw new IllegalArgumentException("leg lengths without an assembly: " + q[0] + ", " + q[1] + ", " + q[2]);
        }
        double[] pose = new double[Pose.SIZE];
        geo.pose(w, Math.toRadians(q[3]), Math.toRadians(q[4]), Math.toRadians(q[5]), pose);
        return Pose.toTransform(pose, 0).times(tool);
    }

    /** The wrist centre W (mm, base frame) for leg lengths (mm); numerical (Newton). */
    public Vec3 wristCentre(double leg1Mm, double leg2Mm, double leg3Mm) {
        double[] w = new double[3];
        if (!new TriceptGeometry(this).wristCentre(leg1Mm, leg2Mm, leg3Mm, null, w)) {
            throw new IllegalArgumentException("leg lengths without an assembly");
        }
        return new Vec3(w[0], w[1], w[2]);
    }

    @Override
    public IkSolver newSolver(IkOptions options) {
        return new TriceptIkSolver(this, options);
    }

    @Override
    public double wristConditioning(double[] q) {
        // singular where the q4 and q6 axes align: theta5 = q5 - 90 = 0 (mod 180)
        return Math.abs(Math.cos(Math.toRadians(q[4])));
    }
}
