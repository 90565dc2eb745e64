package org.fresa.ui;

import java.awt.Component;

/**
 * What a tab needs from the window: the shared view model (the job), the background task
 * runner, the window to own dialogs, and the robot programs of the current job.
 */
record AppContext(MainViewModel model, BackgroundTasks tasks, Component owner, RobotRunModel runs) {

    AppContext(MainViewModel model, BackgroundTasks tasks, Component owner) {
        this(model, tasks, owner, new RobotRunModel());
    }
}
