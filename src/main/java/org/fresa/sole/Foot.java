package org.fresa.sole;

import java.util.Locale;

/** Which sole of the pair. The job's figures and outline are drawn for the right foot. */
public enum Foot {
    RIGHT,
    LEFT;

    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
