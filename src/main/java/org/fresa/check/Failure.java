package org.fresa.check;

/**
 * The first block of a program that breaks a rule.
 *
 * @param line the line number in the program text, from 1 (for a robot program, the motion's index)
 * @param where the block in the planner's words ("block N45 (line 12)", "motion 17")
 * @param text the block as written
 * @param rule the rule it breaks
 * @param reason why, with the figures
 */
public record Failure(int line, String where, String text, Rule rule, String reason) {

    /** One line for stderr and the GUI: where, the block, the rule, the reason. */
    public String message() {
        return where + " \"" + text.strip() + "\": " + rule.name() + ": " + reason;
    }

    @Override
    public String toString() {
        return message();
    }
}
