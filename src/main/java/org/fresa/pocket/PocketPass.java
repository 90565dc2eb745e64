package org.fresa.pocket;

import java.util.List;
import org.fresa.geom.Vec2;

/**
 * One closed pass (an offset of the contour at one offset), clockwise, starting at its start
 * pointer.
 *
 * @param nodePath recognition-tree node ids from the root to the node this pass lies in
 * @param offsetMm the offset t of the tool centre from the wall (mm)
 * @param finishing true for the finishing pass at t = R
 * @param pieces the elements in order; the last ends where the first starts
 */
public record PocketPass(List<Integer> nodePath, double offsetMm, boolean finishing, List<PassPiece> pieces) {

    public PocketPass {
        nodePath = List.copyOf(nodePath);
        pieces = List.copyOf(pieces);
    }

    public int nodeId() {
        return nodePath.get(nodePath.size() - 1);
    }

    public Vec2 start() {
        return pieces.get(0).start();
    }

    /**
     * The same closed pass traversed the other way (climb milling): pieces in reverse order with
     * their ends swapped, starting where this pass starts.
     */
    public PocketPass reversed() {
        List<PassPiece> out = new java.util.ArrayList<>();
        for (int i = pieces.size() - 1; i >= 0; i--) {
            PassPiece p = pieces.get(i);
            out.add(new PassPiece(p.element(), p.offsetMm(), p.end(), p.start(), !p.reversed()));
        }
        return new PocketPass(nodePath, offsetMm, finishing, out);
    }

    /** True when the other pass's node is this pass's node or one of its ancestors. */
    public boolean linksOutwardTo(PocketPass other) {
        return nodePath.containsAll(other.nodePath)
                && other.nodePath.size() <= nodePath.size()
                && nodePath.subList(0, other.nodePath.size()).equals(other.nodePath);
    }
}
