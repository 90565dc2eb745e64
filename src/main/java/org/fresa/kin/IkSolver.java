package org.fresa.kin;

import java.util.List;
import org.fresa.geom.Transform3;

/**
 * Inverse kinematics of one robot with reused work buffers: cheap per call, not thread-safe
 * (make one per thread with {@link Robot#newSolver}).
 */
public interface IkSolver {

    /**
     * Solves from one start configuration (warm start, e.g. the previous point's solution).
     *
     * @param target the tool (TCP) pose in the robot base frame
     * @param seed joint values (deg / mm) to start from
     */
    IkResult solve(Transform3 target, double[] seed);

    /**
     * Solves from many start configurations (cold start) and returns the distinct converged
     * solutions, best limit margin first; empty when the target is unreachable.
     */
    List<IkResult.Converged> solveAll(Transform3 target);

    /**
     * {@link #solveAll}'s cheapest path, for screening many poses (a placement search): an arm
     * with a closed form gives the closed form's solutions and no others, so that a pose at the
     * very edge of the workspace may count as out of reach here and be reached by solveAll.
     */
    default List<IkResult.Converged> solveAllQuickly(Transform3 target) {
        return solveAll(target);
    }

    /** The best of {@link #solveAll}, or an {@link IkResult.Unreachable} saying why. */
    default IkResult solveCold(Transform3 target) {
        List<IkResult.Converged> all = solveAll(target);
        if (all.isEmpty()) {
            return new IkResult.Unreachable(
                    "no start configuration converges within the joint limits", Double.NaN, Double.NaN, 0);
        }
        return all.get(0);
    }
}
