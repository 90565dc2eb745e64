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

    /**
     * A solved trajectory, the name robot programs get (the STEP-NC file's name), and what the
     * run says of its planning, which Save says with what writing says.
     */
    record Run(RobotTrajectoryService.Solved solved, String programName, org.fresa.job.RobotService.Planning planning) {
        Run {
            Objects.requireNonNull(planning, "planning");
        }

        /** A trajectory solved from a toolpath without a STEP-NC planning (nothing said of one). */
        Run(RobotTrajectoryService.Solved solved, String programName) {
            this(solved, programName, new org.fresa.job.RobotService.Planning(List.of(), 0, 0));
        }

        /** What the run says of this trajectory before its programs are checked ({@code RobotService.said}). */
        List<String> said() {
            return org.fresa.job.RobotService.said(planning, solved);
        }
    }

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

    /** Drops the programs: another document was opened, or the job's run writes none (no placement found). */
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
