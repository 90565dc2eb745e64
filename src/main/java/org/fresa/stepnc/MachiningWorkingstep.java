package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Transform3;

/**
 * MACHINING_WORKINGSTEP: one operation on one feature.
 *
 * @param securityPlane its_secplane's frame in the workpiece frame (z up; the plane is z = 0)
 * @param setup the setup of the innermost workplan that runs this workingstep (empty for a
 *              skipped workingstep or a workplan without setup)
 * @param workpieceToSetup the workpiece frame in the setup frame: setup origin, then the
 *                         workpiece setup's origin (identity when absent)
 */
public record MachiningWorkingstep(
        long instanceId,
        String id,
        Optional<Transform3> securityPlane,
        Feature feature,
        Operation operation,
        Optional<Setup> setup,
        Transform3 workpieceToSetup)
        implements Executable {
    public MachiningWorkingstep {
        Objects.requireNonNull(id);
        Objects.requireNonNull(securityPlane);
        Objects.requireNonNull(feature);
        Objects.requireNonNull(operation);
        Objects.requireNonNull(setup);
        Objects.requireNonNull(workpieceToSetup);
    }

    /** The feature frame in the setup frame. */
    public Transform3 featureToSetup() {
        return workpieceToSetup.times(feature.placement());
    }
}
