package org.fresa.job;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.fresa.io.Json;

/**
 * What a task did: its exit status (0 done, 1 read but not fully doable), the problems a planner
 * should read, a summary (printed with {@code --json}) and the files written.
 *
 * @param exitStatus 0 or 1 (bad input is a {@link org.fresa.model.CamInputException} instead)
 * @param problems one sentence each, why the job could not be fully done, or warnings
 * @param summary an ordered map of JSON-able values (String, Number, Boolean, List, Map)
 * @param files the files written, in order
 */
public record TaskOutcome(int exitStatus, List<String> problems, Map<String, Object> summary, List<Path> files) {

    public TaskOutcome {
        if (exitStatus != 0 && exitStatus != 1) {
            throw new IllegalArgumentException("exit status must be 0 or 1: " + exitStatus);
        }
        problems = List.copyOf(problems);
        Map<String, Object> ordered = new LinkedHashMap<>();
        Json.inStableOrder(Objects.requireNonNull(summary, "summary")).forEach((k, v) -> ordered.put((String) k, v));
        summary = java.util.Collections.unmodifiableMap(ordered);
        files = List.copyOf(files);
    }
}
