package org.fresa.kin;

import java.util.List;

/**
 * The closed-form inverse kinematics of a chain of a known build: every solution branch at once,
 * each joint moved into its limits by whole turns where it can be. The numerical solver polishes
 * (and so checks) each.
 */
interface ClosedFormSeeds {

    /** Joint values (internal units) of the solutions for a TCP pose (12 doubles), a branch per array. */
    List<double[]> seeds(double[] target);

    /** The closed form for this chain, when it has a build one is known for. */
    static java.util.Optional<ClosedFormSeeds> of(DenavitHartenbergChain c) {
        java.util.Optional<ClosedFormSeeds> wrist = SphericalWristSeeds.of(c).map(s -> s);
        return wrist.isPresent() ? wrist : ScaraSeeds.of(c).map(s -> s);
    }
}
