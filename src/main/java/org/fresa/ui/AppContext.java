package org.fresa.ui;

import java.awt.Component;

/**
 * What a tab needs from the window: the shared view model (the job), the background task
 * runner, and the window to own dialogs.
 */
record AppContext(MainViewModel model, BackgroundTasks tasks, Component owner) {
}
