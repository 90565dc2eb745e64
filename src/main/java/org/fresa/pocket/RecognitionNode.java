package org.fresa.pocket;

import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec2;

/**
 * A node of the recognition tree (§6.4): one sub-area, as the subcontours it passes through from
 * its start offset, ending either in a leaf (the innermost point) or in a division into children.
 *
 * @param id heap-like number: the root is 1, children of n are numbered in order after it
 * @param states the subcontours, in increasing tFrom; the first one starts the node
 * @param events what happened at each later offset, for reports
 * @param children the sub-areas after the division, in generation order (empty at a leaf)
 * @param splitT offset of the division (NaN at a leaf)
 * @param leafT offset of the leaf (NaN when the node divides)
 * @param leafPoint the innermost point (empty when the node divides)
 */
public record RecognitionNode(
        int id,
        List<LoopState> states,
        List<Event> events,
        List<RecognitionNode> children,
        double splitT,
        double leafT,
        Optional<Vec2> leafPoint) {

    public RecognitionNode {
        states = List.copyOf(states);
        events = List.copyOf(events);
        children = List.copyOf(children);
    }

    /**
     * One event of a node.
     *
     * @param t offset (mm)
     * @param kind "cancel", "divide", "leaf"
     * @param elements the element numbers involved
     */
    public record Event(double t, String kind, List<Integer> elements) {}

    public double tStart() {
        return states.get(0).tFrom();
    }

    public boolean isLeaf() {
        return children.isEmpty();
    }

    /** The subcontour valid at offset t (the first one before the node's start). */
    public LoopState stateAt(double t) {
        LoopState s = states.get(0);
        for (LoopState st : states) {
            if (st.tFrom() <= t + 1e-9) {
                s = st;
            }
        }
        return s;
    }

    /** Largest leaf offset in this subtree. */
    public double maxLeafT() {
        if (isLeaf()) {
            return leafT;
        }
        double m = 0;
        for (RecognitionNode c : children) {
            m = Math.max(m, c.maxLeafT());
        }
        return m;
    }
}
