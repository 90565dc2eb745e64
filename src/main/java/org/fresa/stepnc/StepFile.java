package org.fresa.stepnc;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * A whole Part 21 exchange structure: the header records and the instances of every data section,
 * in file order, by name. References are checked: every {@link StepValue.Ref} names an instance
 * of this file.
 *
 * @param source the file name used in messages
 * @param header the header records (FILE_DESCRIPTION, FILE_NAME, FILE_SCHEMA, ...)
 * @param instances by instance name, in file order (unmodifiable)
 */
public record StepFile(String source, List<StepRecord> header, Map<Long, StepInstance> instances) {
    public StepFile {
        Objects.requireNonNull(source, "source");
        header = List.copyOf(header);
        instances = Collections.unmodifiableMap(instances);
    }

    public Optional<StepInstance> instance(long id) {
        return Optional.ofNullable(instances.get(id));
    }

    /** The schema names of FILE_SCHEMA, upper case; empty when the header has none. */
    public List<String> schemas() {
        List<String> out = new ArrayList<>();
        for (StepRecord r : header) {
            if (r.type().equals("FILE_SCHEMA") && r.param(0) instanceof StepValue.Aggregate a) {
                for (StepValue v : a.items()) {
                    if (v instanceof StepValue.Text t) {
                        out.add(t.value().toUpperCase(java.util.Locale.ROOT));
                    }
                }
            }
        }
        return out;
    }

    /** A header text attribute, e.g. FILE_NAME's preprocessor_version (index 4). */
    public Optional<String> headerText(String record, int index) {
        for (StepRecord r : header) {
            if (r.type().equals(record) && r.param(index) instanceof StepValue.Text t) {
                return Optional.of(t.value());
            }
        }
        return Optional.empty();
    }
}
