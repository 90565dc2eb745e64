package org.fresa.job;

/**
 * The modules of Fresa and whether each is built yet. A module that is not built says so
 * plainly (command line: exit 1, "not available yet: see issue N"; GUI: a notice in its tab).
 */
public enum Module {
    STEPNC("STEP-NC import", 3, true),
    TOOLPATH("STEP-NC toolpaths and G-code", 4, true),
    ROBOT("robot cell and joint trajectory", 5, true),
    ROBOT_PROGRAMS("robot programs (XML, RAPID, KRL)", 6, true),
    POCKET("pocket milling", 7, true),
    CUTTING("sheet cutting", 8, true),
    GRADING("grading", 9, true),
    SOLE("sole mould", 10, true),
    BENCH("benchmarks", 11, true);

    private final String title;
    private final int issue;
    private final boolean available;

    Module(String title, int issue, boolean available) {
        this.title = title;
        this.issue = issue;
        this.available = available;
    }

    public String title() {
        return title;
    }

    /** The issue that builds this module. */
    public int issue() {
        return issue;
    }

    public boolean isAvailable() {
        return available;
    }

    public String unavailableMessage() {
        return title + ": not available yet: see issue " + issue;
    }
}
