package org.fresa.model;

import java.util.List;

/**
 * A whole program's tool-tip path in the workpiece frame: its sections in machining order.
 *
 * @param sections in order
 */
public record Toolpath(List<ToolpathSection> sections) {

    public Toolpath {
        sections = List.copyOf(sections);
    }

    public int moveCount() {
        int n = 0;
        for (ToolpathSection s : sections) {
            n += s.moves().size();
        }
        return n;
    }
}
