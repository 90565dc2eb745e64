package org.fresa.ui;

import java.util.function.Consumer;
import javax.swing.Timer;

/**
 * Puts what is typed into a field into the job once the typing pauses, so that the "6" on the way
 * to "6,5" never becomes the job's value: the job keeps the last value the planner meant. A
 * choice, a new document or an undo flushes or drops what is pending.
 */
final class TypingPause {

    /** How long the typing pauses before the field's value goes into the job. */
    static final int PAUSE_MS = 300;

    private final Timer timer;
    private final Consumer<String> commit;
    private String field;

    /** @param commit puts the field's value into the job (called on the event thread with its name) */
    TypingPause(Consumer<String> commit) {
        this.commit = commit;
        this.timer = new Timer(PAUSE_MS, e -> flush());
        timer.setRepeats(false);
    }

    /** The field was typed into and holds a good value: it goes into the job after the pause. */
    void typed(String name) {
        if (field != null && !field.equals(name)) {
            flush();
        }
        field = name;
        timer.restart();
    }

    /** The field's value is not a good one (or the job was replaced): nothing goes into the job. */
    void drop() {
        timer.stop();
        field = null;
    }

    /** Puts what is pending into the job now (before a choice, Compute or Save). */
    void flush() {
        timer.stop();
        if (field != null) {
            String f = field;
            field = null;
            commit.accept(f);
        }
    }
}
