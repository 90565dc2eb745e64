package org.fresa.cutting;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fresa.dxf.DxfReader;
import org.fresa.geom.Contour;
import org.fresa.model.CamInputException;

/**
 * The closed contours of a DXF drawing for the modules that take one outline from a drawing
 * (pocket, grading): read, chained at 0.001 mm, largest first so the outline comes before any
 * inner contour.
 *
 * @param closed closed contours, largest area first
 * @param openChains how many chains did not close
 */
public record DrawingContours(List<Contour> closed, int openChains) {

    /** Chaining gap, mm: what CAD systems round coordinates to. */
    public static final double GAP_MM = 0.001;

    public DrawingContours {
        closed = List.copyOf(closed);
    }

    /** Reads the drawing and chains its curves. */
    public static DrawingContours read(Path file) throws CamInputException, IOException {
        Chainer.Chains chains = Chainer.chain(DxfReader.read(file).curves(), GAP_MM);
        List<Contour> closed = new ArrayList<>(chains.closed());
        closed.sort(Comparator.comparingDouble(Contour::area).reversed());
        return new DrawingContours(closed, chains.open().size());
    }
}
