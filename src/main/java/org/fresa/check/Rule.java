package org.fresa.check;

/**
 * The rules a program must keep, in the words a planner reads in the refusal. Each rule is one
 * small type ({@link SpindleRule}, {@link WordRule}, {@link EntryAngleRule}, {@link FloorRule}, {@link RapidRule})
 * that looks at one interpreted block at a time. A rule has no state: two rules of one type are
 * equal.
 */
public abstract sealed class Rule permits SpindleRule, WordRule, EntryAngleRule, FloorRule, RapidRule {

    private final String name;
    private final String statement;

    /**
     * @param name a short name ({@code spindle}, {@code words}, {@code entry angle}, {@code floor}, {@code rapid})
     * @param statement the rule as one sentence
     */
    Rule(String name, String statement) {
        this.name = name;
        this.statement = statement;
    }

    /** A short name ({@code spindle}, {@code words}, {@code entry angle}, {@code floor}, {@code rapid}). */
    public final String name() {
        return name;
    }

    /** The rule as one sentence. */
    public final String statement() {
        return statement;
    }

    /** The reason the step breaks the rule, or null when it keeps it. */
    public abstract String broken(Step step, Limits limits);

    @Override
    public final boolean equals(Object o) {
        return o != null && o.getClass() == getClass();
    }

    @Override
    public final int hashCode() {
        return getClass().hashCode();
    }

    @Override
    public final String toString() {
        return getClass().getSimpleName() + "[]";
    }
}
