package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The document's history without a screen: what one undo gives back. */
class MainViewModelTest {

    @TempDir
    Path dir;

    private MainViewModel model() {
        return new MainViewModel(new RecentJobs(dir.resolve("recent.txt")));
    }

    @Test
    void keystrokesInOneFieldAreOneEditAndUndoGivesBackTheJobBeforeTheFirst() {
        MainViewModel m = model();
        Job before = m.job();
        m.setJob(before.withName("a"), "name");
        m.setJob(before.withName("ab"), "name");
        m.setJob(before.withName("abc"), "name");
        assertTrue(m.undo());
        assertEquals(before, m.job());
        assertFalse(m.canUndo());
        assertTrue(m.redo());
        assertEquals(before.withName("abc"), m.job());
    }

    @Test
    void anotherFieldAnUndoOrAChoiceStartsANewEdit() {
        MainViewModel m = model();
        Job before = m.job();
        m.setJob(before.withName("a"), "name");
        Job named = before.withName("a").withRuns(List.of(JobTask.CUT));
        m.setJob(named);
        m.setJob(named.withName("ab"), "name");
        assertTrue(m.undo());
        assertEquals(named, m.job());
        // typing again after an undo is a new edit: the undone one stays undoable
        m.setJob(named.withName("x"), "name");
        m.setJob(named.withName("xy"), "name");
        m.undo();
        assertEquals(named, m.job());
        m.undo();
        assertEquals(before.withName("a"), m.job());
        m.undo();
        assertEquals(before, m.job());
    }

    @Test
    void typingBackWhatTheFieldHeldLeavesNoEdit() {
        MainViewModel m = model();
        Job before = m.job();
        m.setJob(before.withName("u"), "name");
        m.setJob(before, "name");
        assertFalse(m.canUndo());
        assertFalse(m.isDirty());
        m.setJob(before.withName("v"), "name");
        m.undo();
        assertEquals(before, m.job());
    }
}
