package org.fresa.ui;

import java.awt.Color;
import javax.swing.text.BadLocationException;
import javax.swing.text.DefaultHighlighter;
import javax.swing.text.Element;
import javax.swing.text.JTextComponent;

/**
 * Marks the block of a program that fails the program check: the whole line on a red background,
 * scrolled into view, with the caret on it.
 */
final class ProgramHighlight {

    /** The colour of the failing block. */
    static final Color REFUSED = new Color(255, 190, 190);

    private ProgramHighlight() {}

    /**
     * Highlights a line of the text.
     *
     * @param line from 1; nothing happens for a line the text does not have
     * @return true when the line was highlighted
     */
    static boolean line(JTextComponent text, int line) {
        Element root = text.getDocument().getDefaultRootElement();
        if (line < 1 || line > root.getElementCount()) {
            return false;
        }
        Element e = root.getElement(line - 1);
        try {
            text.getHighlighter()
                    .addHighlight(
                            e.getStartOffset(),
                            e.getEndOffset(),
                            new DefaultHighlighter.DefaultHighlightPainter(REFUSED));
        } catch (BadLocationException ex) {
            return false;
        }
        text.setCaretPosition(e.getStartOffset());
        return true;
    }
}
