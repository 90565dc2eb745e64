package org.fresa.ui;

import java.beans.PropertyChangeListener;
import java.beans.PropertyChangeSupport;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.job.RecentJobs;
import org.fresa.model.CamInputException;

/**
 * The state behind the main window, without Swing: the job being edited, its file, whether it
 * has unsaved changes, and the recent jobs. Tabs replace the job through {@link #setJob}; the
 * window listens for {@link #JOB}, {@link #FILE} and {@link #DIRTY} changes.
 */
public final class MainViewModel {

    public static final String JOB = "job";
    public static final String FILE = "file";
    public static final String DIRTY = "dirty";

    private final PropertyChangeSupport changes = new PropertyChangeSupport(this);
    private final RecentJobs recent;
    private Job job = Job.empty(JobTask.POCKET);
    private Optional<Path> file = Optional.empty();
    private boolean dirty;

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

    /** Replaces the job after an edit in a tab; marks it unsaved when it changed. */
    public void setJob(Job j) {
        Objects.requireNonNull(j, "job");
        Job old = job;
        job = j;
        if (!j.equals(old)) {
            setDirty(true);
            changes.firePropertyChange(JOB, old, j);
        }
    }

    public void newJob() {
        Job old = job;
        job = Job.empty(JobTask.POCKET);
        setFile(Optional.empty());
        setDirty(false);
        changes.firePropertyChange(JOB, old, job);
    }

    /** Opens a job file; the current job is kept when the file is bad. */
    public void open(Path f) throws CamInputException {
        Job read = JobXml.read(f);
        Job old = job;
        job = read;
        setFile(Optional.of(f.toAbsolutePath()));
        setDirty(false);
        recent.add(f);
        changes.firePropertyChange(JOB, old, job);
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
