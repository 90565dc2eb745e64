package org.fresa.stepnc;

import java.util.List;
import java.util.Optional;

/**
 * {@code #id = ...;}: one entity instance of the data section.
 *
 * @param id the instance name, 1 to 2^63-1
 * @param records one record for a simple instance, several for a complex one
 * @param line 1-based line of the instance name
 * @param column 1-based column of the instance name
 */
public record StepInstance(long id, List<StepRecord> records, int line, int column) {
    public StepInstance {
        records = List.copyOf(records);
        if (records.isEmpty()) {
            throw new IllegalArgumentException("an instance has at least one record");
        }
    }

    public boolean isComplex() {
        return records.size() > 1;
    }

    /** The entity name of a simple instance; for a complex one, the names joined by '+'. */
    public String type() {
        if (records.size() == 1) {
            return records.get(0).type();
        }
        StringBuilder sb = new StringBuilder();
        for (StepRecord r : records) {
            sb.append(sb.length() > 0 ? "+" : "").append(r.type());
        }
        return sb.toString();
    }

    /** The record of a simple instance (the first partial record of a complex one). */
    public StepRecord record() {
        return records.get(0);
    }

    public Optional<StepRecord> part(String type) {
        return records.stream().filter(r -> r.type().equals(type)).findFirst();
    }
}
