package org.fresa.model;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;

/**
 * An enumerated setting as the command line and the job file spell it: the constant's name in
 * lower case, an underscore written as a hyphen ({@code climb}, {@code inside-out}), unless the
 * enumeration gives its own words (a post's {@code 7m-compat}, {@code 840d}).
 */
public final class EnumWords {

    private EnumWords() {}

    /** The constant's name in lower case, {@code _} as {@code -}. */
    public static String of(Enum<?> constant) {
        return ofName(constant.name());
    }

    /** A constant's name in lower case, {@code _} as {@code -}. */
    public static String ofName(String constantName) {
        return constantName.toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }

    /** The constant whose word is the text as written, or empty. */
    public static <E extends Enum<E>> Optional<E> parse(Class<E> type, Function<E, String> word, String text) {
        for (E e : type.getEnumConstants()) {
            if (word.apply(e).equals(text)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** The constant whose word is the text in any case ({@link String#equalsIgnoreCase}), or empty. */
    public static <E extends Enum<E>> Optional<E> parseIgnoringCase(
            Class<E> type, Function<E, String> word, String text) {
        for (E e : type.getEnumConstants()) {
            if (word.apply(e).equalsIgnoreCase(text)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** The words of every constant, in the order declared (the default first). */
    public static <E extends Enum<E>> List<String> all(Class<E> type, Function<E, String> word) {
        return Arrays.stream(type.getEnumConstants()).map(word).toList();
    }
}
