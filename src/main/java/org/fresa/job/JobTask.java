package org.fresa.job;

import java.util.Locale;

/** What {@code fresa run} executes for a job: the command of the same name. */
public enum JobTask {
    STEPNC,
    TOOLPATH,
    ROBOT,
    POCKET,
    CUT,
    GRADE,
    SOLE;

    /** The name used in job files and on the command line. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @throws IllegalArgumentException for a name that is not a task */
    public static JobTask ofId(String id) {
        for (JobTask t : values()) {
            if (t.id().equals(id)) {
                return t;
            }
        }
        throw new IllegalArgumentException("unknown task: " + id);
    }
}
