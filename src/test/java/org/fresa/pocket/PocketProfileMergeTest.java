package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.StringReader;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.model.ContourFile;
import org.junit.jupiter.api.Test;

class PocketProfileMergeTest {

    @Test
    void aCircleSplitWhereTheContourStartsBecomesOneArc() throws Exception {
        // the sole outline of samples/grading: the heel circle is cut in two at the contour's start
        Contour c = ContourFile.read(new StringReader("""
                contour
                move 0 -29.2
                arc 0 0 29.104775132475094 -2.356281920326864 ccw
                line 44.85324934799244 192.16874361593463
                arc 0 195.8 -44.85324934799244 192.16874361593463 ccw
                line -29.104775132475094 -2.356281920326864
                arc 0 0 0 -29.2 ccw
                """), "sole").get(0);
        Contour m = PocketProfile.mergeCarriers(c);
        assertEquals(4, m.size());
        assertEquals(c.signedArea(), m.signedArea(), 1e-9);
        assertEquals(
                1,
                PocketProfile.fromContours(List.of(c)).elements().stream()
                        .filter(e -> e.arc() && e.d() > 29 && e.d() < 30)
                        .count());
    }

    @Test
    void collinearSegmentsJoin() {
        Contour square = Contour.polygon(List.of(
                org.fresa.geom.Vec2.of(0, 0),
                org.fresa.geom.Vec2.of(5, 0),
                org.fresa.geom.Vec2.of(10, 0),
                org.fresa.geom.Vec2.of(10, 10),
                org.fresa.geom.Vec2.of(0, 10)));
        assertEquals(4, PocketProfile.mergeCarriers(square).size());
    }
}
