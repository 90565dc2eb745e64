package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.fresa.job.RobotTrajectoryService;

/**
 * The last trajectory the Position tab computed, shared with the Output tab (no Swing). Listeners
 * hear about every new result; a result stays until the next compute replaces it.
 */
final class RobotRunModel {

    /** A solved trajectory and the name robot programs get (the STEP-NC file's name). */
    record Run(RobotTrajectoryService.Solved solved, String programName) {
    }

    private final List<Consumer<Run>> listeners = new ArrayList<>();
    private Run last;

    Optional<Run> last() {
        return Optional.ofNullable(last);
    }

    void set(Run r) {
        last = r;
        for (Consumer<Run> l : List.copyOf(listeners)) {
            l.accept(r);
        }
    }

    void addListener(Consumer<Run> l) {
        listeners.add(l);
    }
}
