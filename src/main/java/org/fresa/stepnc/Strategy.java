package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec3;

/**
 * A 2½D milling strategy (ISO 14649-11 two5D_milling_strategy) or a drilling strategy.
 *
 * <p>Overlap: ISO defines it as a ratio of the tool diameter. Files write it as a fraction
 * (0.05), a percentage (5.0) or, in STEP Modeler's files, a length in mm (4.0 for a Ø20 tool).
 * {@code overlapFraction} is the ratio in 0..1 and {@code overlapInterpretation} says which
 * reading was taken.
 *
 * @param type the kind of strategy
 * @param entity the entity name as written (BIDIRECTIONAL or BIDIRECTIONAL_MILLING, ...)
 * @param overlap as written
 * @param overlapFraction overlap as a fraction of the tool diameter
 * @param overlapInterpretation "fraction", "percent" or "length" (empty without overlap)
 * @param allowMultiplePasses allow_multiple_passes
 * @param feedDirection feed_direction in the feature frame
 * @param stepoverDirection LEFT or RIGHT
 * @param rotationDirection CW or CCW
 * @param cutmode CLIMB or CONVENTIONAL
 * @param drilling the reductions of a DRILLING_TYPE_STRATEGY (empty for milling strategies)
 */
public record Strategy(
        long instanceId,
        StrategyType type,
        String entity,
        OptionalDouble overlap,
        OptionalDouble overlapFraction,
        Optional<String> overlapInterpretation,
        Optional<Boolean> allowMultiplePasses,
        Optional<Vec3> feedDirection,
        Optional<String> stepoverDirection,
        Optional<String> rotationDirection,
        Optional<String> cutmode,
        Optional<DrillingStrategy> drilling) {
    public Strategy {
        Objects.requireNonNull(type);
        Objects.requireNonNull(entity);
        Objects.requireNonNull(overlap);
        Objects.requireNonNull(overlapFraction);
        Objects.requireNonNull(overlapInterpretation);
        Objects.requireNonNull(allowMultiplePasses);
        Objects.requireNonNull(feedDirection);
        Objects.requireNonNull(stepoverDirection);
        Objects.requireNonNull(rotationDirection);
        Objects.requireNonNull(cutmode);
        Objects.requireNonNull(drilling);
    }

    public enum StrategyType {
        UNIDIRECTIONAL,
        BIDIRECTIONAL,
        CONTOUR_PARALLEL,
        CONTOUR_SPIRAL,
        BIDIRECTIONAL_CONTOUR,
        CONTOUR_BIDIRECTIONAL,
        CENTER_MILLING,
        EXPLICIT,
        DRILLING_TYPE_STRATEGY,
        /** a strategy entity the binding does not know (e.g. GRIMA's trochoidal strategies) */
        OTHER
    }
}
