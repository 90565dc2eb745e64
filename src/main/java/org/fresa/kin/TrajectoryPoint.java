package org.fresa.kin;

import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Transform3;

/**
 * One row of a joint trajectory.
 *
 * @param label the target's label
 * @param target the full target pose used (after any free rotation)
 * @param status ok, unreachable or relink
 * @param q joint values (deg / mm); empty when unreachable
 * @param reached forward kinematics of q; empty when unreachable
 * @param posErrMm |target - reached| (mm), NaN when unreachable
 * @param rotErrRad angle of R_target^T R_reached, NaN when unreachable
 * @param freeRotationDeg the turn about the tool axis from the preferred x direction
 * @param inserted true for points the solver added (subdivision of a long move, relinks)
 */
public record TrajectoryPoint(
        String label,
        Transform3 target,
        Status status,
        double[] q,
        Optional<Transform3> reached,
        double posErrMm,
        double rotErrRad,
        double freeRotationDeg,
        boolean inserted) {

    /** What happened at a point. */
    public enum Status {
        OK,
        UNREACHABLE,
        RELINK;

        /** As written in trajectory.csv. */
        public String csv() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    public TrajectoryPoint {
        Objects.requireNonNull(label, "label");
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(status, "status");
        Objects.requireNonNull(reached, "reached");
        q = q.clone();
    }

    @Override
    public double[] q() {
        return q.clone();
    }
}
