package org.fresa.ui;

import java.util.Objects;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * What the planner types or chooses in a tab's settings, on its way into the job: a field typed
 * into is marked at once and its good value goes into the job once the typing pauses; a choice
 * puts what was typed first, then itself, each its own undo step. While the tab fills its fields
 * from the job, their listeners write nothing back.
 */
final class FieldEdits {

    private final BooleanSupplier takeFields;
    private final Consumer<String> commit;
    private final TypingPause typing;
    private boolean filling;

    /**
     * @param takeFields takes the fields into the view model and marks the bad ones; true when
     *     every field is good
     * @param commit puts the settings into the job as one undo step named after the field (null
     *     for a choice)
     */
    FieldEdits(BooleanSupplier takeFields, Consumer<String> commit) {
        this.takeFields = Objects.requireNonNull(takeFields, "takeFields");
        this.commit = Objects.requireNonNull(commit, "commit");
        this.typing = new TypingPause(commit);
    }

    /** A field was typed into: marked at once, its good value into the job once the typing pauses. */
    void typed(String field) {
        if (filling) {
            return;
        }
        if (takeFields.getAsBoolean()) {
            typing.typed(field);
        } else {
            typing.drop();
        }
    }

    /** A choice: what was typed goes first, then the choice, each its own undo step. */
    void chosen(String field) {
        if (filling) {
            return;
        }
        typing.flush();
        commit.accept(field);
    }

    /** Fills the fields from the job without writing them back. */
    void fill(Runnable fillFields) {
        filling = true;
        try {
            fillFields.run();
        } finally {
            filling = false;
        }
    }

    /** True while the fields are filled from the job. */
    boolean filling() {
        return filling;
    }

    /** What was typed is not to reach the job (the job was replaced, or the value is bad). */
    void drop() {
        typing.drop();
    }

    /** What was typed goes into the job now (before Compute, Save or an edit of another kind). */
    void flush() {
        typing.flush();
    }
}
