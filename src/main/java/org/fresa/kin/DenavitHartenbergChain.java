package org.fresa.kin;

import java.util.List;
import java.util.Objects;
import org.fresa.geom.Transform3;

/**
 * A serial chain from a standard Denavit-Hartenberg table (thesis eq. 5): A_i = Rz(theta_i)
 * Tz(d_i) Tx(a_i) Rx(alpha_i), the pose of the tool being base * A_1 ... A_n * tool.
 *
 * <p>Joint values at the public boundary are in the joints' own units: degrees for revolute
 * joints, mm for prismatic ones. The geometric Jacobian (thesis eqs. 6-8, Spong) is expressed in
 * the base frame, rows (vx, vy, vz) in mm and (wx, wy, wz) in rad, per radian of a revolute joint
 * or per mm of a prismatic one. Immutable; the hot-loop kernels work on caller-owned buffers.
 */
public final class DenavitHartenbergChain {

    private final List<DhJoint> joints;
    private final Transform3 base;
    private final Transform3 tool;

    final int n;
    final boolean[] revolute;
    final double[] a;
    final double[] ca;
    final double[] sa;
    /** Constant d (revolute) or offset of d (prismatic), mm. */
    final double[] d;
    /** Constant theta (prismatic) or offset of theta (revolute), rad. */
    final double[] theta;
    /** Limits in internal units (rad, mm). */
    final double[] qMin;

    final double[] qMax;
    final double[] base12 = new double[Pose.SIZE];
    final double[] tool12 = new double[Pose.SIZE];

    /**
     * @param joints the DH rows from base to flange, at least one
     * @param base the chain's base frame in the robot base frame (usually the identity)
     * @param tool the tool frame (TCP) in the last DH frame; its z points from flange to tip
     */
    public DenavitHartenbergChain(List<DhJoint> joints, Transform3 base, Transform3 tool) {
        this.joints = List.copyOf(joints);
        if (this.joints.isEmpty()) {
            throw new IllegalArgumentException("a chain needs at least one joint");
        }
        this.base = Objects.requireNonNull(base, "base");
        this.tool = Objects.requireNonNull(tool, "tool");
        n = this.joints.size();
        revolute = new boolean[n];
        a = new double[n];
        ca = new double[n];
        sa = new double[n];
        d = new double[n];
        theta = new double[n];
        qMin = new double[n];
        qMax = new double[n];
        for (int i = 0; i < n; i++) {
            DhJoint j = this.joints.get(i);
            revolute[i] = j.type() == JointType.REVOLUTE;
            a[i] = j.aMm();
            ca[i] = cosDeg(j.alphaDeg());
            sa[i] = sinDeg(j.alphaDeg());
            d[i] = j.dMm();
            theta[i] = Math.toRadians(j.thetaDeg());
            qMin[i] = revolute[i] ? Math.toRadians(j.qMin()) : j.qMin();
            qMax[i] = revolute[i] ? Math.toRadians(j.qMax()) : j.qMax();
        }
        Pose.fromTransform(base, base12, 0);
        Pose.fromTransform(tool, tool12, 0);
    }

    public DenavitHartenbergChain(List<DhJoint> joints) {
        this(joints, Transform3.IDENTITY, Transform3.IDENTITY);
    }

    public List<DhJoint> joints() {
        return joints;
    }

    public Transform3 base() {
        return base;
    }

    public Transform3 tool() {
        return tool;
    }

    public int dof() {
        return n;
    }

    /** The same table with another base frame. */
    public DenavitHartenbergChain withBase(Transform3 newBase) {
        return new DenavitHartenbergChain(joints, newBase, tool);
    }

    /** The same table with another tool frame. */
    public DenavitHartenbergChain withTool(Transform3 newTool) {
        return new DenavitHartenbergChain(joints, base, newTool);
    }

    /** Pose of the tool (TCP) for joint values in deg / mm. */
    public Transform3 forward(double... qUser) {
        double[] f = new double[frameBufferSize()];
        frames(toInternal(qUser), f);
        return Pose.toTransform(f, (n + 1) * Pose.SIZE);
    }

    /** Pose of DH frame i (0 = base, n = flange) for joint values in deg / mm. */
    public Transform3 frame(int i, double... qUser) {
        if (i < 0 || i > n) {
            throw new IllegalArgumentException("frame index out of 0.." + n + ": " + i);
        }
        double[] f = new double[frameBufferSize()];
        frames(toInternal(qUser), f);
        return Pose.toTransform(f, i * Pose.SIZE);
    }

    /**
     * The geometric Jacobian at the TCP (6 rows, n columns), see the class comment for units.
     */
    public double[][] jacobian(double... qUser) {
        double[] f = new double[frameBufferSize()];
        frames(toInternal(qUser), f);
        double[] j = new double[6 * n];
        jacobian(f, j, 1);
        double[][] out = new double[6][n];
        for (int r = 0; r < 6; r++) {
            System.arraycopy(j, r * n, out[r], 0, n);
        }
        return out;
    }

    /** Joint values in deg/mm to internal rad/mm. */
    public double[] toInternal(double[] qUser) {
        if (qUser.length != n) {
            throw new IllegalArgumentException("expected " + n + " joint values, got " + qUser.length);
        }
        double[] q = new double[n];
        for (int i = 0; i < n; i++) {
            q[i] = revolute[i] ? Math.toRadians(qUser[i]) : qUser[i];
        }
        return q;
    }

    /** Internal rad/mm to deg/mm. */
    public double[] toUser(double[] q) {
        double[] u = new double[n];
        for (int i = 0; i < n; i++) {
            u[i] = revolute[i] ? Math.toDegrees(q[i]) : q[i];
        }
        return u;
    }

    int frameBufferSize() {
        return (n + 2) * Pose.SIZE;
    }

    /**
     * Fills f with the base (slot 0), the cumulative DH frames 1..n and the TCP (slot n+1).
     * q in internal units. No allocation.
     */
    void frames(double[] q, double[] f) {
        frames(q, f, n);
        Pose.mul(f, n * Pose.SIZE, tool12, 0, f, (n + 1) * Pose.SIZE);
    }

    /**
     * Fills f with the base (slot 0) and the cumulative DH frames 1..upTo only, as {@link #frames}
     * computes them: the closed form needs the arm's frame 3 for each of its candidates, not the wrist's.
     */
    void frames(double[] q, double[] f, int upTo) {
        System.arraycopy(base12, 0, f, 0, Pose.SIZE);
        for (int i = 0; i < upTo; i++) {
            double th = revolute[i] ? q[i] + theta[i] : theta[i];
            double di = revolute[i] ? d[i] : q[i] + d[i];
            double ct = Math.cos(th);
            double st = Math.sin(th);
            double c = ca[i];
            double s = sa[i];
            double ai = a[i];
            // A = [[ct, -st c, st s, a ct], [st, ct c, -ct s, a st], [0, s, c, d]]
            int p = i * Pose.SIZE;
            int o = p + Pose.SIZE;
            for (int r = 0; r < 3; r++) {
                double m0 = f[p + 4 * r];
                double m1 = f[p + 4 * r + 1];
                double m2 = f[p + 4 * r + 2];
                f[o + 4 * r] = m0 * ct + m1 * st;
                f[o + 4 * r + 1] = -m0 * st * c + m1 * ct * c + m2 * s;
                f[o + 4 * r + 2] = m0 * st * s - m1 * ct * s + m2 * c;
                f[o + 4 * r + 3] = m0 * ai * ct + m1 * ai * st + m2 * di + f[p + 4 * r + 3];
            }
        }
    }

    /**
     * The geometric Jacobian from frames computed by {@link #frames}, into j (6 x n, row-major),
     * the angular rows multiplied by rotWeight (a length, so that all rows share a unit).
     */
    void jacobian(double[] f, double[] j, double rotWeight) {
        int t = (n + 1) * Pose.SIZE;
        double px = f[t + 3];
        double py = f[t + 7];
        double pz = f[t + 11];
        for (int i = 0; i < n; i++) {
            int p = i * Pose.SIZE;
            double zx = f[p + 2];
            double zy = f[p + 6];
            double zz = f[p + 10];
            if (revolute[i]) {
                double rx = px - f[p + 3];
                double ry = py - f[p + 7];
                double rz = pz - f[p + 11];
                j[i] = zy * rz - zz * ry;
                j[n + i] = zz * rx - zx * rz;
                j[2 * n + i] = zx * ry - zy * rx;
                j[3 * n + i] = zx * rotWeight;
                j[4 * n + i] = zy * rotWeight;
                j[5 * n + i] = zz * rotWeight;
            } else {
                j[i] = zx;
                j[n + i] = zy;
                j[2 * n + i] = zz;
                j[3 * n + i] = 0;
                j[4 * n + i] = 0;
                j[5 * n + i] = 0;
            }
        }
    }

    // exact at multiples of 90 degrees, so that alpha = -90 gives exact zeros
    static double cosDeg(double deg) {
        return Transform3.rotX(deg).r11();
    }

    static double sinDeg(double deg) {
        return Transform3.rotX(deg).r21();
    }
}
