package org.fresa.ui;

import java.util.List;
import org.fresa.job.Module;

/**
 * The eight tabs of the main window, in order. A module that is built puts its own tab here in
 * place of the {@link UnavailableTab}.
 */
final class Tabs {
    private Tabs() {
    }

    static List<ModuleTab> create(AppContext ctx) {
        return List.of(
                new StepNcTab(ctx),
                new UnavailableTab("Position", Module.ROBOT),
                new UnavailableTab("Robot", Module.ROBOT),
                new PocketTab(),
                new CuttingTab(ctx),
                new GradingTab(ctx),
                new SoleTab(ctx),
                new UnavailableTab("Output", Module.ROBOT_PROGRAMS));
    }
}
