package org.fresa.ui;

import javax.swing.text.BadLocationException;
import javax.swing.text.Document;
import javax.swing.text.PlainDocument;

/**
 * Text documents filled off the event thread: a program of many thousand lines takes longer to
 * put into a text area's document than an event may take. A document no component
 * shows yet belongs to no thread; the event thread then only swaps it in.
 */
final class TextDocuments {
    private TextDocuments() {}

    static Document of(String text) {
        PlainDocument d = new PlainDocument();
        try {
            d.insertString(0, text, null);
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        return d;
    }
}
