package org.fresa.stepnc;

/**
 * An element of a workplan, in execution order: a machining workingstep, a nested workplan, or
 * another executable (RAPID_MOVEMENT, NC functions, ...) that is kept but not interpreted.
 */
public sealed interface Executable permits MachiningWorkingstep, Workplan, Executable.Other {

    long instanceId();

    /** its_id, or the empty string. */
    String id();

    /** An executable the binding does not interpret, e.g. RAPID_MOVEMENT or DISPLAY_MESSAGE. */
    record Other(long instanceId, String id, String entity) implements Executable {}
}
