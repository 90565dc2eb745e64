package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Transform3;

/**
 * SETUP: the setup frame, the security plane and where each workpiece sits.
 *
 * @param origin its_origin (the setup frame in the machine frame; identity when unset)
 * @param securityPlane the security plane frame in the setup frame (the plane is its z = 0)
 * @param workpieceSetups one per workpiece
 */
public record Setup(
        long instanceId,
        String id,
        Transform3 origin,
        Optional<Transform3> securityPlane,
        List<WorkpieceSetup> workpieceSetups) {
    public Setup {
        Objects.requireNonNull(id);
        Objects.requireNonNull(origin);
        Objects.requireNonNull(securityPlane);
        workpieceSetups = List.copyOf(workpieceSetups);
    }

    /**
     * WORKPIECE_SETUP.
     *
     * @param workpieceInstanceId the workpiece it places
     * @param origin the workpiece frame in the setup frame
     */
    public record WorkpieceSetup(long workpieceInstanceId, Transform3 origin) {
        public WorkpieceSetup {
            Objects.requireNonNull(origin);
        }
    }
}
