package org.fresa.toolpath;

import java.util.Optional;
import org.fresa.model.EnumWords;

/**
 * Whose conventions the STEP-NC toolpaths follow ({@code --paths}).
 */
public enum PathConvention {
    /** Fresa's own: exact arcs, entries within the tool's angle, retracts to the clearance plane. */
    FRESA,
    /**
     * The 2016 STEP-NC robot thesis's, point for point ({@link ThesisPaths}): every path a list of
     * straight moves, so that its point lists, counts and Appendix C samples can be compared.
     */
    THESIS;

    /** The word of {@code --paths} and of the job's {@code paths} attribute. */
    public String word() {
        return EnumWords.of(this);
    }

    /** The convention of a word ({@code fresa}, {@code thesis}), case ignored. */
    public static Optional<PathConvention> byWord(String word) {
        for (PathConvention c : values()) {
            if (c.word().equalsIgnoreCase(word == null ? "" : word.trim())) {
                return Optional.of(c);
            }
        }
        return Optional.empty();
    }
}
