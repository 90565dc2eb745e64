package org.fresa.kin;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/** The built-in robots, exactly as spec/robots.md defines them. */
public final class Robots {
    private Robots() {}

    /** ABB IRB-140 (6R), d1 = 352 mm; at q = 0 the flange is at (515, 0, 712) with z_e = +x. */
    public static SerialRobot irb140() {
        return new SerialRobot(
                "irb140",
                "ABB IRB-140, 6R anthropomorphic arm (thesis table 4.3, d1 = 352 mm)",
                new DenavitHartenbergChain(List.of(
                        DhJoint.revolute(70, -90, 352, 0, -180, 180),
                        DhJoint.revolute(360, 0, 0, -90, -90, 110),
                        DhJoint.revolute(0, -90, 0, 0, -230, 50),
                        DhJoint.revolute(0, 90, 380, 0, -200, 200),
                        DhJoint.revolute(0, 90, 0, 180, -120, 120),
                        DhJoint.revolute(0, 0, 65, 0, -400, 400))),
                4);
    }

    /** Adept One SCARA (RRPR); the tool tip height is 1060.45 - q3 - 183.642 mm. */
    public static SerialRobot adeptOne() {
        return new SerialRobot(
                "adept-one",
                "Adept One SCARA, RRPR (thesis table 4.2); tool axis always vertical",
                new DenavitHartenbergChain(List.of(
                        DhJoint.revolute(424.942, 0, 1060.45, 0, -150, 150),
                        DhJoint.revolute(374.904, 180, 0, 0, -147, 147),
                        DhJoint.prismatic(0, 0, 0, 0, 0, 195),
                        DhJoint.revolute(0, 0, 183.642, 0, -277, 277))),
                -1);
    }

    /** COMAU Tricept 806 with the project's dimensions (r_b 500, r_p 200, d_eff 400, e_ffl 250). */
    public static TriceptRobot tricept806() {
        return new TriceptRobot(
                "tricept806",
                "COMAU Tricept 806, 3 prismatic legs + spherical wrist (thesis eqs. 27-40, table 4.4)",
                500,
                200,
                400,
                250,
                List.of(
                        new JointLimit("q1", JointType.PRISMATIC, 900, 1800),
                        new JointLimit("q2", JointType.PRISMATIC, 900, 1800),
                        new JointLimit("q3", JointType.PRISMATIC, 900, 1800)),
                List.of(
                        new JointLimit("q4", JointType.REVOLUTE, -180, 180),
                        new JointLimit("q5", JointType.REVOLUTE, -120, 120),
                        new JointLimit("q6", JointType.REVOLUTE, -360, 360)));
    }

    public static List<Robot> all() {
        return List.of(irb140(), adeptOne(), tricept806());
    }

    /** The built-in robot of that name (case-insensitive), if any. */
    public static Optional<Robot> byName(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        for (Robot r : all()) {
            if (r.name().equals(n)) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }
}
