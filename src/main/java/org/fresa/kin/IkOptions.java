package org.fresa.kin;

import java.util.Objects;

/**
 * How inverse kinematics is solved.
 *
 * @param method the default Levenberg-Marquardt solver or the 2016 thesis's damped least squares
 * @param posTolMm convergence: |position error| <= this (mm)
 * @param rotTolRad convergence: orientation error angle <= this (rad)
 * @param maxIterations per start configuration
 */
public record IkOptions(Method method, double posTolMm, double rotTolRad, int maxIterations) {

    /** The solvers. */
    public enum Method {
        /**
         * Levenberg-Marquardt with adaptive damping (lambda = E + mu, Sugihara 2011), warm start,
         * steps projected onto the joint limits; many starts when there is no warm start.
         */
        LEVENBERG_MARQUARDT,
        /**
         * The thesis's section 3.2.3.1: dq = (J^T J + D^2)^-1 J^T e with the joint-limit damping of
         * eq. 19 (c = 0.5, p = 8), the error halved while above tolerance (eq. 26), the five start
         * configurations and the 75 % rule for a joint beyond a limit. (Eq. 18 as printed is not
         * conformable for n != 6; this is the corrected form.)
         */
        THESIS_DLS
    }

    /** The project's default: LM, 1e-7 mm, 1e-9 rad, 100 iterations. */
    public static final IkOptions DEFAULT = new IkOptions(Method.LEVENBERG_MARQUARDT, 1e-7, 1e-9, 100);

    /** The thesis's method with the project's tolerances. */
    public static final IkOptions THESIS = new IkOptions(Method.THESIS_DLS, 1e-7, 1e-9, 100);

    public IkOptions {
        Objects.requireNonNull(method, "method");
        if (!(posTolMm > 0) || !(rotTolRad > 0) || maxIterations < 1) {
            throw new IllegalArgumentException("tolerances must be > 0 and iterations >= 1");
        }
    }
}
