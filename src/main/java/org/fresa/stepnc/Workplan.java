package org.fresa.stepnc;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * WORKPLAN: executables in order, possibly nested workplans, with the setup they run in.
 *
 * @param setup its_setup; a nested workplan without one runs in its parent's setup
 */
public record Workplan(long instanceId, String id, List<Executable> elements, Optional<Setup> setup)
        implements Executable {
    public Workplan {
        Objects.requireNonNull(id);
        elements = List.copyOf(elements);
        Objects.requireNonNull(setup);
    }

    /** Every machining workingstep below this workplan, nested workplans flattened, in order. */
    public List<MachiningWorkingstep> flatten() {
        List<MachiningWorkingstep> out = new ArrayList<>();
        collect(this, out);
        return out;
    }

    private static void collect(Workplan w, List<MachiningWorkingstep> out) {
        for (Executable e : w.elements) {
            if (e instanceof MachiningWorkingstep ws) {
                out.add(ws);
            } else if (e instanceof Workplan sub) {
                collect(sub, out);
            }
        }
    }
}
