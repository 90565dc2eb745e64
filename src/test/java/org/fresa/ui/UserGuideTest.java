package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class UserGuideTest {

    @Test
    void theGuideInTheJarIsTheOneInDocs() throws Exception {
        assertEquals(Files.readString(Path.of("docs/user-guide.md")), UserGuide.markdown());
    }

    @Test
    void theGuideNamesEveryTabThePlotKeysAndF1() {
        String html = UserGuide.html();
        assertAll(
                () -> assertTrue(html.contains("<h1>Fresa user guide</h1>"), html),
                () -> assertTrue(html.contains("<b>Fit</b>"), "the fit button"),
                () -> assertTrue(html.contains("<td>F1</td>"), "the keys table"),
                () -> {
                    for (String tab : new String[] {
                        "STEP-NC", "Position", "Robot", "Pocket", "Cutting", "Grading", "Sole", "Output"
                    }) {
                        assertTrue(html.contains("<b>" + tab + "</b> (Alt+"), tab);
                    }
                });
    }

    @Test
    void markdownListsTablesAndCodeBecomeHtml() {
        String html = UserGuide.toHtml("""
                # Title

                Some `code` and **bold**
                text & more.

                - one
                  continued
                - two

                | a | b |
                |---|---|
                | 1 | 2 |
                """);
        assertAll(
                () -> assertTrue(html.contains("<h1>Title</h1>"), html),
                () -> assertTrue(html.contains("<p>Some <code>code</code> and <b>bold</b> text &amp; more.</p>"), html),
                () -> assertTrue(html.contains("<ul><li>one continued</li><li>two</li></ul>"), html),
                () -> assertTrue(html.contains("<tr><th>a</th><th>b</th></tr>"), html),
                () -> assertTrue(html.contains("<tr><td>1</td><td>2</td></tr>"), html));
    }
}
