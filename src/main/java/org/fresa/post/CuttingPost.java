package org.fresa.post;

import java.util.Optional;
import org.fresa.model.EnumWords;

/**
 * The sheet-cutting posts of {@link SheetCuttingPost} as a setting: the {@link Dialect}s a cutting
 * machine's control reads ({@code linuxcnc}, the default, {@code iso}, {@code fanuc}, {@code 840d});
 * the thesis's 7M is a milling control only.
 */
public enum CuttingPost {
    LINUXCNC(Dialect.LINUXCNC),
    ISO(Dialect.ISO),
    FANUC(Dialect.FANUC),
    SIEMENS_840D(Dialect.SIEMENS_840D);

    private final Dialect dialect;

    CuttingPost(Dialect dialect) {
        this.dialect = dialect;
    }

    /** The dialect the program is written in. */
    public Dialect dialect() {
        return dialect;
    }

    /** The name as the command line and job files write it. */
    public String id() {
        return dialect.id();
    }

    @Override
    public String toString() {
        return id();
    }

    /** The post of a name, ignoring case. */
    public static Optional<CuttingPost> byName(String name) {
        return EnumWords.parseIgnoringCase(CuttingPost.class, CuttingPost::id, name);
    }
}
