package org.fresa.stepnc;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * An ISO 14649 program as bound from a Part 21 file: the project, its workplan tree, the
 * machining workingsteps in execution order, and what was not executed or not understood.
 *
 * @param source the file name
 * @param schemas FILE_SCHEMA names
 * @param dialect which writer's conventions (units, overlap) were assumed
 * @param instanceCount number of entity instances in the file
 * @param projectId the PROJECT's its_id (empty when the file has none)
 * @param mainWorkplan the project's main workplan (or the first top-level workplan)
 * @param workpieces every WORKPIECE of the project
 * @param workingsteps machining workingsteps in execution order, nested workplans flattened
 * @param skipped workingsteps defined in the file but not reached from the main workplan
 * @param unknownEntities entity types the binding does not know: kept raw, counted
 * @param spellings draft/published variants and arities seen, one sentence each
 * @param warnings things read but doubtful
 * @param file the raw instance graph, for anything the binding does not cover
 */
public record StepNcProgram(
        String source,
        List<String> schemas,
        Dialect dialect,
        long instanceCount,
        String projectId,
        Optional<Workplan> mainWorkplan,
        List<Workpiece> workpieces,
        List<MachiningWorkingstep> workingsteps,
        List<Skipped> skipped,
        Map<String, Integer> unknownEntities,
        List<String> spellings,
        List<String> warnings,
        StepFile file) {

    public StepNcProgram {
        Objects.requireNonNull(source);
        schemas = List.copyOf(schemas);
        Objects.requireNonNull(dialect);
        Objects.requireNonNull(projectId);
        Objects.requireNonNull(mainWorkplan);
        workpieces = List.copyOf(workpieces);
        workingsteps = List.copyOf(workingsteps);
        skipped = List.copyOf(skipped);
        unknownEntities = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(unknownEntities));
        spellings = List.copyOf(spellings);
        warnings = List.copyOf(warnings);
        Objects.requireNonNull(file);
    }

    /**
     * The file is AP238 in its integrated form (AIM, as STEP Tools' ST-Developer and STEP-NC Maker
     * write it): its workingsteps are {@code action_method}s tied by relationships, read through
     * their AIM mapping into this model.
     */
    public boolean integratedForm() {
        return dialect == Dialect.AP238_AIM;
    }

    /** "ARM" (ISO 14649 entities) or "AIM" (AP238 integrated form). */
    public String form() {
        return integratedForm() ? "AIM" : "ARM";
    }

    /**
     * Why a program with no executable workingstep gives nothing to machine, in the planner's
     * words; empty when there are workingsteps.
     */
    public Optional<String> whyNothingToMachine() {
        if (!workingsteps.isEmpty()) {
            return Optional.empty();
        }
        StringBuilder why = new StringBuilder(source).append(" has no workingstep reached from a workplan");
        if (!skipped.isEmpty()) {
            why.append(" (").append(skipped.size()).append(" skipped: ");
            for (int i = 0; i < Math.min(3, skipped.size()); i++) {
                Skipped s = skipped.get(i);
                why.append(i > 0 ? "; " : "")
                        .append('#')
                        .append(s.instanceId())
                        .append(" '")
                        .append(s.id())
                        .append("' ")
                        .append(s.reason());
            }
            why.append(skipped.size() > 3 ? "; ...)" : ")");
        }
        return Optional.of(
                why.append(": nothing to machine, no program written").toString());
    }

    /**
     * The workpiece a feature is made in: the one its its_workpiece names, else the project's
     * only workpiece; empty when neither tells.
     */
    public Optional<Workpiece> workpieceOf(Feature f) {
        Optional<StepInstance> inst = file.instance(f.instanceId());
        if (inst.isPresent() && !inst.get().isComplex()) {
            // ISO 14649-10 manufacturing_feature: its_id, its_workpiece, its_operations, ...
            int i = Iso14649Schema.get()
                    .find(inst.get().record().type())
                    .map(l -> l.def().indexOf("its_workpiece"))
                    .orElse(-1);
            if (i >= 0 && inst.get().record().param(i) instanceof StepValue.Ref r) {
                for (Workpiece w : workpieces) {
                    if (w.instanceId() == r.id()) {
                        return Optional.of(w);
                    }
                }
            }
        }
        return workpieces.size() == 1 ? Optional.of(workpieces.get(0)) : Optional.empty();
    }

    /**
     * The program with only what planning reads of the raw instance graph, the features'
     * instances ({@link #workpieceOf}): the rest of a large file's instance table, most of its
     * memory once it is bound, can go. Everything bound stays as it is.
     */
    public StepNcProgram forPlanning() {
        java.util.Set<Long> features = new java.util.HashSet<>();
        for (MachiningWorkingstep w : workingsteps) {
            features.add(w.feature().instanceId());
        }
        for (Skipped s : skipped) {
            s.workingstep().ifPresent(w -> features.add(w.feature().instanceId()));
        }
        return new StepNcProgram(
                source,
                schemas,
                dialect,
                instanceCount,
                projectId,
                mainWorkplan,
                workpieces,
                workingsteps,
                skipped,
                unknownEntities,
                spellings,
                warnings,
                file.only(features));
    }

    /** The schema names joined as the header lists them. */
    public String schema() {
        return String.join(",", schemas);
    }

    /**
     * A workingstep present in the file but not executed.
     *
     * @param workingstep bound when it could be; empty when its feature or operation is unusable
     */
    public record Skipped(long instanceId, String id, String reason, Optional<MachiningWorkingstep> workingstep) {}

    /** Whose conventions the file follows, for units and the meaning of overlap. */
    public enum Dialect {
        /** ISO 14649-10/11 as published (feed, cutting speed m/s; spindle rev/s) */
        ISO_14649,
        /**
         * UFSC GRIMA's writers (STEP Modeler, COMBINED_SCHEMA, and their JSDAI files whose spindle
         * speeds are rpm): spindle rpm, cutting speed m/min, overlap in mm, angles in radians
         */
        STEP_MODELER,
        /**
         * AP238 in its integrated form (AIM): every measure carries its own unit and is converted
         * to mm, mm/min, rpm and degrees when it is read
         */
        AP238_AIM
    }
}
