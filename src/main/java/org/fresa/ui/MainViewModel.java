package org.fresa.ui;

import java.beans.PropertyChangeListener;
import java.beans.PropertyChangeSupport;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.model.CamInputException;

/**
 * The state behind the main window, without Swing: the job being edited, its file, whether it
 * has unsaved changes, the undo and redo history, and the recent jobs. Tabs replace the job
 * through {@link #setJob}; the window listens for {@link #JOB}, {@link #FILE} and {@link #DIRTY}
 * changes. New and Open replace the whole document: {@link #DOCUMENT} first (every tab drops
 * what it shows and its results), then {@link #JOB} with the new job.
 *
 * <p>The job is immutable, so the history is a stack of whole jobs: undo gives back exactly the
 * job before the edit ({@code equals}), and the job is unsaved exactly when it differs from the
 * one last read or written.
 */
public final class MainViewModel {

    public static final String JOB = "job";
    public static final String FILE = "file";
    public static final String DIRTY = "dirty";
    /** Fired when New or Open replaced the document, before {@link #JOB}. */
    public static final String DOCUMENT = "document";
    /** Fired when undo or redo became possible or impossible. */
    public static final String HISTORY = "history";

    /** How many edits undo goes back at most. */
    static final int HISTORY_LIMIT = 500;

    private final PropertyChangeSupport changes = new PropertyChangeSupport(this);
    private final RecentJobs recent;
    private Job job = Job.empty(JobTask.POCKET);
    private Optional<Path> file = Optional.empty();
    private boolean dirty;
    private Job saved = job;
    private final Deque<Job> undo = new ArrayDeque<>();
    private final Deque<Job> redo = new ArrayDeque<>();
    private int generation;
    // the field whose typing made the last undo step: its next keystrokes extend that step
    private String typing;

    public MainViewModel(RecentJobs recent) {
        this.recent = Objects.requireNonNull(recent, "recent");
    }

    public void addListener(PropertyChangeListener l) {
        changes.addPropertyChangeListener(l);
    }

    public Job job() {
        return job;
    }

    public Optional<Path> file() {
        return file;
    }

    public boolean isDirty() {
        return dirty;
    }

    /** The window title: "Fresa", then the job's file name and a star when unsaved. */
    public String title() {
        String name = file.map(f -> f.getFileName().toString()).orElse(job.name());
        return "Fresa - " + name + (dirty ? " *" : "");
    }

    /**
     * How many times New or Open replaced the document: work started for one document (a read,
     * a run) compares it when it ends and drops its result when another document came meanwhile.
     */
    public int generation() {
        return generation;
    }

    /** Replaces the job after an edit in a tab; the edit can be undone; unsaved when it differs. */
    public void setJob(Job j) {
        setJob(j, null);
    }

    /**
     * Replaces the job after typing in a field: the keystrokes typed into one field one after the
     * other are one edit, so one undo gives back the job from before the first of them (as a text
     * editor undoes a word, not a letter). Any other edit, an undo or a redo ends the typing.
     *
     * @param field the field typed into, or null for an edit of its own (a choice, a button)
     */
    public void setJob(Job j, String field) {
        Objects.requireNonNull(j, "job");
        Job old = job;
        if (j.equals(old)) {
            return;
        }
        boolean could = canUndo() || canRedo();
        boolean same = field != null && field.equals(typing) && !undo.isEmpty();
        if (same && j.equals(undo.peek())) {
            // typed back to what it was: no edit is left
            undo.pop();
            typing = null;
        } else if (!same) {
            undo.push(old);
            if (undo.size() > HISTORY_LIMIT) {
                undo.removeLast();
            }
            typing = field;
        }
        redo.clear();
        job = j;
        setDirty(!j.equals(saved));
        changes.firePropertyChange(JOB, old, j);
        changes.firePropertyChange(HISTORY, could, canUndo() || canRedo());
    }

    public boolean canUndo() {
        return !undo.isEmpty();
    }

    public boolean canRedo() {
        return !redo.isEmpty();
    }

    /** Goes back to the job before the last edit; false when there is none. */
    public boolean undo() {
        return step(undo, redo);
    }

    /** Makes the last undone edit again; false when there is none. */
    public boolean redo() {
        return step(redo, undo);
    }

    private boolean step(Deque<Job> from, Deque<Job> to) {
        if (from.isEmpty()) {
            return false;
        }
        Job old = job;
        typing = null;
        to.push(old);
        job = from.pop();
        setDirty(!job.equals(saved));
        changes.firePropertyChange(JOB, old, job);
        changes.firePropertyChange(HISTORY, null, job);
        return true;
    }

    public void newJob() {
        replace(Job.empty(JobTask.POCKET), Optional.empty());
    }

    /** Opens a job file; the current job is kept when the file is bad. */
    public void open(Path f) throws CamInputException {
        Job read = JobXml.read(f);
        recent.add(f);
        replace(read, Optional.of(f.toAbsolutePath()));
    }

    private void replace(Job j, Optional<Path> f) {
        Job old = job;
        generation++;
        typing = null;
        job = j;
        saved = j;
        undo.clear();
        redo.clear();
        setFile(f);
        setDirty(false);
        changes.firePropertyChange(DOCUMENT, null, j);
        changes.firePropertyChange(JOB, old, j);
        changes.firePropertyChange(HISTORY, null, j);
    }

    /** Saves to the current file; false when the job has none yet (ask for a name, then saveAs). */
    public boolean save() throws IOException {
        if (file.isEmpty()) {
            return false;
        }
        saveAs(file.get());
        return true;
    }

    public void saveAs(Path f) throws IOException {
        Path target = f.getFileName().toString().contains(".") ? f : f.resolveSibling(f.getFileName() + ".xml");
        if ("untitled".equals(job.name())) {
            String n = target.getFileName().toString();
            Job old = job;
            job = job.withName(n.substring(0, n.lastIndexOf('.')));
            changes.firePropertyChange(JOB, old, job);
        }
        JobXml.write(job, target);
        saved = job;
        setFile(Optional.of(target.toAbsolutePath()));
        setDirty(false);
        recent.add(target);
    }

    /** Where robots edited in the Robot tab are kept until saved elsewhere (next to the recent jobs). */
    public Path editedRobotsFolder() {
        return recent.folder().resolve("robots");
    }

    public List<Path> recentJobs() {
        return recent.list();
    }

    private void setFile(Optional<Path> f) {
        Optional<Path> old = file;
        file = f;
        changes.firePropertyChange(FILE, old, f);
    }

    private void setDirty(boolean d) {
        boolean old = dirty;
        dirty = d;
        changes.firePropertyChange(DIRTY, old, d);
    }
}
