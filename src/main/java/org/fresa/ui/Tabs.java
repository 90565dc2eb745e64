package org.fresa.ui;

import java.util.List;

/** The eight tabs of the main window, in order. */
final class Tabs {
    private Tabs() {}

    static List<ModuleTab> create(AppContext ctx) {
        RobotRunModel runs = ctx.runs();
        List<ModuleTab> tabs = List.of(
                new StepNcTab(ctx),
                new PositionTab(ctx, runs),
                new RobotTab(ctx),
                new PocketTab(ctx),
                new CuttingTab(ctx),
                new GradingTab(ctx),
                new SoleTab(ctx),
                new OutputTab(ctx, runs));
        for (ModuleTab t : tabs) {
            Tooltips.install(t.title(), t.component());
        }
        return tabs;
    }
}
