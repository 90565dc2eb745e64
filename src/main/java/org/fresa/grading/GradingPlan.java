package org.fresa.grading;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec2;

/**
 * What to grade: the system, the base size and the sizes wanted, the steps, the frame (given or
 * found), shrinkage, how arcs are written and the optional heel coordination.
 *
 * @param system size system
 * @param baseSize NP, the size the outline is drawn in
 * @param sizes the sizes ND to make
 * @param lengthStepMm VC per whole size
 * @param widthStepMm VL per whole size
 * @param origin the fixed point, or empty for the heel circle's centre
 * @param lengthAxisDeg the length axis (deg from +x, towards the toe), or empty to find it
 * @param shrinkage S, fraction, >= 0
 * @param shrinkageMode additive (thesis) or multiplicative
 * @param arcMode how graded arcs become circular arcs
 * @param arcToleranceMm largest distance of biarcs from the exact ellipse (mm)
 * @param coordination one heel per group of sizes, or empty
 */
public record GradingPlan(
        SizeSystem system,
        double baseSize,
        List<Double> sizes,
        double lengthStepMm,
        double widthStepMm,
        Optional<Vec2> origin,
        OptionalDouble lengthAxisDeg,
        double shrinkage,
        ShrinkageMode shrinkageMode,
        ArcMode arcMode,
        double arcToleranceMm,
        Optional<Coordination> coordination) {

    /** The biarc tolerance of NC and DXF output: 0.005 mm. */
    public static final double DEFAULT_ARC_TOLERANCE_MM = 0.005;

    public GradingPlan {
        Objects.requireNonNull(system, "system");
        sizes = List.copyOf(sizes);
        Objects.requireNonNull(origin, "origin");
        Objects.requireNonNull(lengthAxisDeg, "lengthAxisDeg");
        Objects.requireNonNull(shrinkageMode, "shrinkageMode");
        Objects.requireNonNull(arcMode, "arcMode");
        Objects.requireNonNull(coordination, "coordination");
        if (!(arcToleranceMm > 0)) {
            throw new IllegalArgumentException("arc tolerance must be > 0: " + arcToleranceMm);
        }
        system.checkSize(baseSize, "base size");
        for (double s : sizes) {
            system.checkSize(s, "size");
        }
        if (!(lengthStepMm > 0) || !(widthStepMm >= 0) || !Double.isFinite(lengthStepMm + widthStepMm)) {
            throw new IllegalArgumentException(
                    "steps must be finite, the length step > 0 mm and the width step >= 0 mm: " + lengthStepMm + ", "
                            + widthStepMm);
        }
    }

    /** A plan with the system's steps, the heel-centre origin, no shrinkage, biarcs. */
    public static GradingPlan of(SizeSystem system, double baseSize, List<Double> sizes) {
        return new GradingPlan(
                system,
                baseSize,
                sizes,
                system.lengthStepMm(),
                system.widthStepMm(),
                Optional.empty(),
                OptionalDouble.empty(),
                0,
                ShrinkageMode.MULTIPLICATIVE,
                ArcMode.BIARC,
                DEFAULT_ARC_TOLERANCE_MM,
                Optional.empty());
    }

    public GradingPlan withShrinkage(double s, ShrinkageMode mode) {
        return with(origin, s, mode, arcMode, coordination);
    }

    public GradingPlan withOrigin(Vec2 o) {
        return with(Optional.of(o), shrinkage, shrinkageMode, arcMode, coordination);
    }

    public GradingPlan withArcMode(ArcMode m) {
        return with(origin, shrinkage, shrinkageMode, m, coordination);
    }

    public GradingPlan withCoordination(Coordination c) {
        return with(origin, shrinkage, shrinkageMode, arcMode, Optional.of(c));
    }

    /** The same sizes and steps with another origin, shrinkage, arc mode or coordination. */
    private GradingPlan with(Optional<Vec2> o, double s, ShrinkageMode mode, ArcMode m, Optional<Coordination> c) {
        return new GradingPlan(
                system, baseSize, sizes, lengthStepMm, widthStepMm, o, lengthAxisDeg, s, mode, m, arcToleranceMm, c);
    }
}
