package org.fresa.ui;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * The user guide ({@code docs/user-guide.md}, packed in the jar) as HTML for the Help window.
 * Reads the few Markdown forms the guide uses: headings, paragraphs, bullet lists, tables,
 * {@code **bold**} and {@code `code`}. Swing-free.
 */
final class UserGuide {

    /** Where the build puts the guide in the jar. */
    static final String RESOURCE = "/org/fresa/ui/help/user-guide.md";

    private UserGuide() {}

    /** The guide's Markdown text from the jar. */
    static String markdown() {
        try (InputStream in = UserGuide.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                return "# User guide\n\nThe guide is missing from this build (" + RESOURCE + ").";
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The guide as HTML. */
    static String html() {
        return toHtml(markdown());
    }

    /** The guide's Markdown forms as HTML 3.2, which Swing's HTML view shows. */
    static String toHtml(String markdown) {
        StringBuilder out = new StringBuilder("<html><body style='font-family:sans-serif;margin:8px'>\n");
        List<String> paragraph = new ArrayList<>();
        boolean list = false;
        boolean table = false;
        for (String raw : markdown.split("\r?\n", -1)) {
            String line = raw.strip();
            boolean item = line.startsWith("- ");
            boolean continued = !line.isEmpty() && raw.startsWith("  ") && list;
            if (continued) {
                out.append(' ').append(inline(line));
                continue;
            }
            if (list && !item) {
                out.append("</li></ul>\n");
                list = false;
            }
            if (table && !line.startsWith("|")) {
                out.append("</table>\n");
                table = false;
            }
            if (line.isEmpty() || line.startsWith("#") || item || line.startsWith("|")) {
                flush(paragraph, out);
            }
            if (line.startsWith("#")) {
                int level = (int) line.chars().takeWhile(c -> c == '#').count();
                out.append("<h")
                        .append(level)
                        .append('>')
                        .append(inline(line.substring(level).strip()))
                        .append("</h")
                        .append(level)
                        .append(">\n");
            } else if (item) {
                out.append(list ? "</li><li>" : "<ul><li>").append(inline(line.substring(2)));
                list = true;
            } else if (line.startsWith("|")) {
                if (line.matches("\\|[-| :]+\\|")) {
                    continue;
                }
                String cell = table ? "td" : "th";
                out.append(table ? "" : "<table border='1' cellpadding='3' cellspacing='0'>\n")
                        .append("<tr>");
                String[] cells = line.substring(1, line.length() - 1).split("\\|");
                for (String c : cells) {
                    out.append('<')
                            .append(cell)
                            .append('>')
                            .append(inline(c.strip()))
                            .append("</")
                            .append(cell)
                            .append('>');
                }
                out.append("</tr>\n");
                table = true;
            } else if (!line.isEmpty()) {
                paragraph.add(line);
            }
        }
        flush(paragraph, out);
        if (list) {
            out.append("</li></ul>\n");
        }
        if (table) {
            out.append("</table>\n");
        }
        return out.append("</body></html>\n").toString();
    }

    private static void flush(List<String> paragraph, StringBuilder out) {
        if (!paragraph.isEmpty()) {
            out.append("<p>").append(inline(String.join(" ", paragraph))).append("</p>\n");
            paragraph.clear();
        }
    }

    private static String inline(String s) {
        String e = s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
        e = e.replaceAll("\\*\\*([^*]+)\\*\\*", "<b>$1</b>");
        return e.replaceAll("`([^`]+)`", "<code>$1</code>");
    }
}
