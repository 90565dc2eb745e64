package org.fresa.sole;

import java.util.List;

/**
 * The tool-centre path of one macro call.
 *
 * @param joinsPrevious true for the thesis's continuous types (B, E and the relative SUB7B/8B/9B):
 *     the tool is already down, and the first stroke's cuts carry on the groove in progress
 *     (its start is the tool position the figure was given)
 * @param strokes the grooves in order
 * @param staysDown true when the tool is left at depth at the end (PRIM, NOVO, the continuous
 *     types), so that the next continuous figure chains on
 */
public record FigurePath(boolean joinsPrevious, List<Stroke> strokes, boolean staysDown) {

    public FigurePath {
        strokes = List.copyOf(strokes);
        if (strokes.isEmpty()) {
            throw new IllegalArgumentException("a figure path has at least one stroke");
        }
    }

    /** Where the tool is at the end. */
    public org.fresa.geom.Vec2 end() {
        return strokes.get(strokes.size() - 1).end();
    }

    public FigurePath mapped(Similarity2 t) {
        return new FigurePath(
                joinsPrevious, strokes.stream().map(s -> s.mapped(t)).toList(), staysDown);
    }
}
