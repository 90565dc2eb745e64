package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Transform3;

/**
 * A serial robot: a {@link DenavitHartenbergChain} with a name.
 *
 * @param name command-line name
 * @param description one line for people
 * @param chain the DH table, base and tool
 * @param wristJoint 0-based index of the middle joint of a spherical wrist (4 for a 6R arm), or
 *     -1 when there is none; used only for the wrist-singularity measure
 */
public record SerialRobot(String name, String description, DenavitHartenbergChain chain, int wristJoint)
        implements Robot {

    public SerialRobot {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(description, "description");
        Objects.requireNonNull(chain, "chain");
        if (wristJoint != -1 && (wristJoint < 1 || wristJoint >= chain.dof() - 1)) {
            throw new IllegalArgumentException("wrist joint must be an inner joint or -1: " + wristJoint);
        }
    }

    @Override
    public List<JointLimit> joints() {
        List<JointLimit> out = new ArrayList<>();
        int i = 1;
        for (DhJoint j : chain.joints()) {
            out.add(new JointLimit("q" + i++, j.type(), j.qMin(), j.qMax()));
        }
        return List.copyOf(out);
    }

    /** The chain's joint count, without building the named joint list (asked for every target). */
    @Override
    public int dof() {
        return chain.dof();
    }

    @Override
    public Transform3 forward(double... q) {
        return chain.forward(q);
    }

    @Override
    public IkSolver newSolver(IkOptions options) {
        return new SerialIkSolver(chain, options);
    }

    @Override
    public double wristConditioning(double[] q) {
        if (wristJoint < 0) {
            return 1;
        }
        Transform3 a = chain.frame(wristJoint - 1, q);
        Transform3 b = chain.frame(wristJoint + 1, q);
        return a.zAxis().cross(b.zAxis()).norm();
    }

    @Override
    public Transform3 tool() {
        return chain.tool();
    }

    @Override
    public SerialRobot withTool(Transform3 tool) {
        return new SerialRobot(name, description, chain.withTool(tool), wristJoint);
    }
}
