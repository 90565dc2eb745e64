package org.fresa.kin;

/**
 * The outcome of an inverse-kinematics solve. Never a wrong pose: {@link Converged} only when
 * the forward kinematics of q is within the tolerances and q within the joint limits.
 */
public sealed interface IkResult permits IkResult.Converged, IkResult.Unreachable {

    /** Iterations spent (all starts together). */
    int iterations();

    /**
     * @param q joint values (deg / mm), within the limits
     * @param posErrMm |p_target - p_reached|
     * @param rotErrRad angle of R_target^T R_reached
     * @param iterations solver iterations spent
     */
    record Converged(double[] q, double posErrMm, double rotErrRad, int iterations) implements IkResult {
        public Converged {
            q = q.clone();
        }

        @Override
        public double[] q() {
            return q.clone();
        }
    }

    /**
     * @param reason why, for the planner
     * @param posErrMm best position residual reached (mm)
     * @param rotErrRad best orientation residual reached (rad)
     * @param iterations solver iterations spent
     */
    record Unreachable(String reason, double posErrMm, double rotErrRad, int iterations) implements IkResult {}
}
