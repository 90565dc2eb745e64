package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.ExplicitToolpath;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Profile;
import org.fresa.stepnc.Technology;

/**
 * The explicit toolpaths of an operation (ISO 14649-10 its_toolpath; AP238 CC1 cutter-location
 * trajectories) followed as given, in the feature frame: lines as lines, arcs as arcs, rapid
 * trajectories at rapid rate, each cutting one at its own feed (else the operation's).
 *
 * <p>Refused, with the reason: a cutter-contact trajectory (it needs the tool offset against the
 * surface), a cutting trajectory without a feed, cutting with no spindle speed, an arc traversed
 * at rapid rate. A gap between one trajectory's end and the next one's start is bridged by a
 * straight move at the next trajectory's rate, and reported.
 */
final class ExplicitPaths {

    /** Trajectory ends closer than this (mm) are the same point. */
    static final double JOIN_MM = 1e-6;

    private ExplicitPaths() {}

    static ToolpathSection section(String label, Operation op, Tooling t, List<String> problems) {
        List<ExplicitToolpath> paths = op.toolpaths();
        ExplicitToolpath first = paths.get(0);
        if (first.curve().isEmpty()) {
            throw new IllegalArgumentException(
                    "toolpath '" + first.id() + "' (#" + first.instanceId() + ") has no curve");
        }
        Vec3 start = first.curve().get(0).start();
        MoveBuilder mb = new MoveBuilder(start);
        for (ExplicitToolpath p : paths) {
            String name = "toolpath '" + p.id() + "' (#" + p.instanceId() + ")";
            if (!p.cutterLocation()) {
                throw new UnsupportedOperationException(
                        name + " is a " + p.kind() + ": only cutter-location trajectories are followed");
            }
            if (p.curve().isEmpty()) {
                continue;
            }
            double feed = 0;
            if (!p.rapid()) {
                Technology tech = p.technology().orElse(op.technology());
                feed = tech.feedMmPerMin().orElse(0);
                if (!(feed > 0)) {
                    throw new IllegalArgumentException(name + " cuts with no feed (its technology gives "
                            + tech.feedrate().orElse(0) + " " + tech.feedrateUnit() + ")");
                }
                double rpm = tech.spindleRpm().orElse(t.spindleRpm());
                if (!(rpm > 0) || !(t.spindleRpm() > 0)) {
                    throw new IllegalArgumentException(name + " cuts at " + n(feed) + " mm/min with the spindle at "
                            + n(rpm > 0 ? t.spindleRpm() : rpm) + " rpm (the file's technology): no cutting move"
                            + " without the spindle turning");
                }
            }
            Vec3 from = p.curve().get(0).start();
            if (mb.at().distance(from) > JOIN_MM) {
                problems.add("workingstep '" + label + "': " + name + " starts "
                        + String.format(java.util.Locale.ROOT, "%.4f", mb.at().distance(from))
                        + " mm from where the one before ended; joined by a straight move");
                move(mb, from, p.rapid(), feed);
            }
            for (Profile.Segment s : p.curve()) {
                if (s instanceof Profile.Arc a) {
                    if (p.rapid()) {
                        throw new UnsupportedOperationException(name + " traverses an arc at rapid rate");
                    }
                    mb.arc(a.end(), a.center(), a.ccw(), 0, feed);
                } else {
                    move(mb, s.end(), p.rapid(), feed);
                }
            }
        }
        return t.section(label, start, mb.moves());
    }

    private static String n(double d) {
        return org.fresa.model.ExactDecimal.of(Math.round(d * 1e4) / 1e4 + 0.0);
    }

    private static void move(MoveBuilder mb, Vec3 to, boolean rapid, double feed) {
        if (rapid) {
            mb.rapid(to);
        } else {
            mb.feed(to, feed);
        }
    }
}
