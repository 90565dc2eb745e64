package org.fresa.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where a value stands in an XML file, for the message that refuses it: the schema's binding
 * reads values without their lines, so the line is found again by the attribute's name and value.
 */
public final class XmlLines {

    private XmlLines() {}

    /** The line where an attribute has the word (or a list with it), or 0 when it cannot be found. */
    public static int lineOf(Path file, String attribute, String word) {
        // the word alone, or one item of a comma list
        return lineWhere(
                file,
                attribute,
                text -> Arrays.stream(text.split(",")).anyMatch(w -> w.trim().equals(word.trim())));
    }

    /** The line where an attribute has the value, or 0 when it cannot be found. */
    public static int lineOf(Path file, String attribute, double value) {
        return lineWhere(file, attribute, text -> {
            try {
                return Double.compare(Double.parseDouble(text.trim()), value) == 0;
            } catch (NumberFormatException e) {
                // another attribute's text: look on
                return false;
            }
        });
    }

    /** The first line where the attribute's text is the one looked for, or 0. */
    private static int lineWhere(Path file, String attribute, Predicate<String> looked) {
        Pattern p = Pattern.compile("\\b" + attribute + "\\s*=\\s*([\"'])(.*?)\\1");
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            for (int i = 0; i < lines.size(); i++) {
                Matcher m = p.matcher(lines.get(i));
                while (m.find()) {
                    if (looked.test(m.group(2))) {
                        return i + 1;
                    }
                }
            }
        } catch (IOException e) {
            // the message goes without a line
        }
        return 0;
    }
}
