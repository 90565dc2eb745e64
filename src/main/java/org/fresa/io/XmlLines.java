package org.fresa.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * Where a value stands in an XML file, for the message that refuses it: the schema's binding
 * reads values without their lines, so the line is found again by the attribute's name and value.
 */
public final class XmlLines {

    private XmlLines() {}

    /** The line where an attribute has the word (or a list with it), or 0 when it cannot be found. */
    public static int lineOf(Path file, String attribute, String word) {
        java.util.regex.Pattern p = java.util.regex.Pattern.compile("\\b" + attribute + "\\s*=\\s*([\"'])(.*?)\\1");
        try {
            List<String> lines = Files.readAllLines(file, java.nio.charset.StandardCharsets.UTF_8);
            for (int i = 0; i < lines.size(); i++) {
                java.util.regex.Matcher m = p.matcher(lines.get(i));
                while (m.find()) {
                    // the word alone, or one item of a comma list
                    if (Arrays.stream(m.group(2).split(","))
                            .anyMatch(w -> w.trim().equals(word.trim()))) {
                        return i + 1;
                    }
                }
            }
        } catch (IOException e) {
            // the message goes without a line
        }
        return 0;
    }

    /** The line where an attribute has the value, or 0 when it cannot be found. */
    public static int lineOf(Path file, String attribute, double value) {
        java.util.regex.Pattern p = java.util.regex.Pattern.compile("\\b" + attribute + "\\s*=\\s*([\"'])(.*?)\\1");
        try {
            List<String> lines = Files.readAllLines(file, java.nio.charset.StandardCharsets.UTF_8);
            for (int i = 0; i < lines.size(); i++) {
                java.util.regex.Matcher m = p.matcher(lines.get(i));
                while (m.find()) {
                    try {
                        if (Double.compare(Double.parseDouble(m.group(2).trim()), value) == 0) {
                            return i + 1;
                        }
                    } catch (NumberFormatException e) {
                        // another attribute's text: look on
                    }
                }
            }
        } catch (IOException e) {
            // the message goes without a line
        }
        return 0;
    }
}
