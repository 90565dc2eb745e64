package org.fresa.setting;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import org.fresa.model.CamInputException;

/**
 * The values one enumerated setting may take, with the names the command line ({@code --post})
 * and job files ({@code post}) give it and the word each value is written as, so that the
 * command line, the job file and the tabs read and write the same words and refuse the same
 * typos in the same way. Words are matched ignoring case and surrounding blanks, as the
 * command line always has; they are written as {@link #word} gives them.
 *
 * @param option the command-line option, or empty for a setting that only job files have
 * @param attribute the job file's attribute ({@code schemas/job.xsd})
 * @param type the enumeration
 * @param word how a value is written
 * @param reader how a word is read, when it takes more spellings than {@link #word} writes; null
 *     for the written words only
 * @param <E> the enumeration
 */
public record SettingChoice<E extends Enum<E>>(
        String option,
        String attribute,
        Class<E> type,
        Function<E, String> word,
        Function<String, Optional<E>> reader) {

    public SettingChoice {
        Objects.requireNonNull(option, "option");
        Objects.requireNonNull(attribute, "attribute");
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(word, "word");
    }

    /** A choice among every value of the enumeration, in their declared order. */
    public static <E extends Enum<E>> SettingChoice<E> of(
            String option, String attribute, Class<E> type, Function<E, String> word) {
        return new SettingChoice<>(option, attribute, type, word, null);
    }

    /** A choice that also reads other spellings than the written words (the command line's aliases). */
    public static <E extends Enum<E>> SettingChoice<E> of(
            String option,
            String attribute,
            Class<E> type,
            Function<E, String> word,
            Function<String, Optional<E>> reader) {
        return new SettingChoice<>(option, attribute, type, word, reader);
    }

    /** The values, in the order the tabs offer them. */
    public List<E> values() {
        return Arrays.asList(type.getEnumConstants());
    }

    /** The written words, in the order of {@link #values()}. */
    public List<String> words() {
        return values().stream().map(word).toList();
    }

    /** The word of a value. */
    public String word(E value) {
        return word.apply(value);
    }

    /** The value of a word (ignoring case and blanks), or empty. */
    public Optional<E> find(String text) {
        if (text == null) {
            return Optional.empty();
        }
        if (reader != null) {
            return reader.apply(text);
        }
        String t = text.trim().toLowerCase(Locale.ROOT);
        return values().stream()
                .filter(v -> word.apply(v).toLowerCase(Locale.ROOT).equals(t))
                .findFirst();
    }

    /** The problem with a word that is no value, one sentence without the setting's name. */
    public String problem(String text) {
        return "unknown value '" + text + "': expected one of " + String.join(", ", words());
    }

    /**
     * The value of a word.
     *
     * @throws CamInputException naming the command-line option, for a word that is no value
     */
    public E check(String text) throws CamInputException {
        return find(text)
                .orElseThrow(() -> new CamInputException(option.isEmpty() ? attribute : option, problem(text)));
    }

    /**
     * The value of a word; for readers of files that find the line afterwards.
     *
     * @throws Unknown for a word that is no value
     */
    public E require(String text) {
        return find(text).orElseThrow(() -> new Unknown(this, text));
    }

    /**
     * A word that is no value of its setting, met inside a reader, which turns it into a
     * {@link CamInputException} with the file and line.
     */
    public static final class Unknown extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        private final transient SettingChoice<?> choice;
        private final String text;

        Unknown(SettingChoice<?> choice, String text) {
            super(choice.attribute() + ": " + choice.problem(text));
            this.choice = choice;
            this.text = text;
        }

        public SettingChoice<?> choice() {
            return choice;
        }

        public String text() {
            return text;
        }
    }
}
