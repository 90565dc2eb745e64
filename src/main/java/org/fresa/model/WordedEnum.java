package org.fresa.model;

/**
 * An enumerated setting whose word, as the command line and the job file write it, is its
 * constant's name by the rule of {@link EnumWords#of}: lower case, {@code _} as {@code -}.
 */
public interface WordedEnum {

    /** The constant's name as the enumeration declares it ({@link Enum#name()}). */
    String name();

    /** The name as the command line and the job file write it: {@code inside-out}, {@code software}. */
    default String word() {
        return EnumWords.ofName(name());
    }
}
