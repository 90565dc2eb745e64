package org.fresa.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.job.RobotTrajectoryService;

/**
 * The robot programs of the current job (no Swing): the last trajectory the Position tab
 * computed, or the files the last Job > Run wrote, whichever came last; none after New or Open.
 * The Output tab shows them. Listeners hear about every change.
 */
final class RobotRunModel {

    /** A solved trajectory and the name robot programs get (the STEP-NC file's name). */
    record Run(RobotTrajectoryService.Solved solved, String programName) {}

    /**
     * The files a run of the job wrote into a folder.
     *
     * @param robot the robot the job names
     * @param files every file the run wrote, in order
     */
    record Written(String robot, Path folder, List<Path> files) {
        Written {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(folder, "folder");
            files = List.copyOf(files);
        }

        /** The file of this name the run wrote, if it wrote one. */
        Optional<Path> file(String name) {
            return files.stream()
                    .filter(f -> f.getFileName().toString().equals(name))
                    .findFirst();
        }
    }

    private final List<Runnable> listeners = new ArrayList<>();
    private Run last;
    private Written written;

    Optional<Run> last() {
        return Optional.ofNullable(last);
    }

    Optional<Written> written() {
        return Optional.ofNullable(written);
    }

    /** Whether there are programs to show. */
    boolean isEmpty() {
        return last == null && written == null;
    }

    void set(Run r) {
        last = Objects.requireNonNull(r, "run");
        written = null;
        fire();
    }

    void setWritten(Written w) {
        written = Objects.requireNonNull(w, "written");
        last = null;
        fire();
    }

    /** Drops the programs: another document was opened. */
    void clear() {
        last = null;
        written = null;
        fire();
    }

    private void fire() {
        for (Runnable l : List.copyOf(listeners)) {
            l.run();
        }
    }

    void addListener(Runnable l) {
        listeners.add(l);
    }
}
