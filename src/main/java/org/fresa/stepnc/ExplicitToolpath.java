package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * An explicit toolpath of an operation (ISO 14649-10 toolpath; AP238 MACHINING_TOOLPATH, a
 * cutter-location trajectory): a curve the tool centre point follows as given, in the feature
 * frame, lengths in mm. Lines stay lines and circular arcs stay arcs.
 *
 * @param instanceId the toolpath's instance
 * @param id its_id
 * @param kind the trajectory's kind as written ("cutter location trajectory", ...)
 * @param rapid its speed profile is rapid: traversed at rapid rate, not cutting
 * @param technology its own technology (feed, spindle), when it has one
 * @param curve the basic curve: lines and arcs, each starting where the one before ends
 */
public record ExplicitToolpath(
        long instanceId,
        String id,
        String kind,
        boolean rapid,
        Optional<Technology> technology,
        List<Profile.Segment> curve) {
    public ExplicitToolpath {
        Objects.requireNonNull(id);
        Objects.requireNonNull(kind);
        Objects.requireNonNull(technology);
        curve = List.copyOf(curve);
    }

    /** A cutter-location trajectory: the curve is where the tool's centre point goes. */
    public boolean cutterLocation() {
        return kind.toLowerCase(java.util.Locale.ROOT).contains("location");
    }
}
