package org.fresa.grading;

import java.util.List;

/**
 * The sizes graded from one base outline.
 *
 * @param frame origin and length axis used
 * @param rule the factors' data (CP and LP are measured on the base outline)
 * @param sizes in the plan's order
 */
public record GradingResult(GradingFrame frame, GradingRule rule, List<GradedSize> sizes) {
    public GradingResult {
        sizes = List.copyOf(sizes);
    }
}
