package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;

/**
 * {@code KEYWORD(p1, p2, ...)}: one entity record. A simple instance has one, a complex instance
 * ({@code #5=(A(...)B(...));}) one per partial entity, in file order.
 *
 * @param type the keyword, upper case (user-defined keywords keep their leading {@code !})
 */
public record StepRecord(String type, List<StepValue> params) {
    public StepRecord {
        Objects.requireNonNull(type, "type");
        params = List.copyOf(params);
    }

    /** The i-th parameter, or {@link StepValue#UNSET} past the end (short FDIS forms). */
    public StepValue param(int i) {
        return i < params.size() ? params.get(i) : StepValue.UNSET;
    }
}
