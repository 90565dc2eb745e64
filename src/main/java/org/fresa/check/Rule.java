package org.fresa.check;

/**
 * The rules a program must keep, in the words a planner reads in the refusal. Each rule is one
 * small type ({@link SpindleRule}, {@link WordRule}, {@link EntryAngleRule}, {@link FloorRule})
 * that looks at one interpreted block at a time.
 */
public sealed interface Rule permits SpindleRule, WordRule, EntryAngleRule, FloorRule {

    /** A short name ({@code spindle}, {@code words}, {@code entry angle}, {@code floor}). */
    String name();

    /** The rule as one sentence. */
    String statement();

    /** The reason the step breaks the rule, or null when it keeps it. */
    String broken(Step step, Limits limits);
}
