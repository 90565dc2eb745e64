package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.model.ContourFile;
import org.junit.jupiter.api.Test;

class PocketProfileTest {

    @Test
    void aCounterClockwiseContourFileIsMilledLikeAClockwiseOne() throws Exception {
        String text = Files.readString(Path.of("samples/pocket/slot-ccw.contour"));
        PocketProfile p = PocketProfile.fromContours(ContourFile.read(new StringReader(text), "slot"));
        assertEquals(4, p.elements().size());
        assertTrue(p.elements().stream().filter(PocketElement::arc).allMatch(PocketElement::convex));
        Recognition.Result r = Recognition.of(p);
        // a stadium: its leaf is the half width, everywhere along the spine
        assertEquals(20, r.root().leafT(), 1e-6);
        assertEquals(40, r.maxHoleDiameterMm(), 1e-6);
        PocketPlan plan = PassPlanner.plan(r, new PocketTechnology(10, 0.6, 0.1, 0, -4, 2, 3000, 300, 100), false);
        assertEquals(5, plan.generated().get(0).offsetMm(), 1e-12);
        assertTrue(plan.milled().get(0).offsetMm() >= 15 - 1e-9, "the innermost pass reaches the leaf within R");
    }

    @Test
    void cavity01AsAPolygonGivesTheSameLeafWithUnitNormals() throws Exception {
        String text = """
                contour
                move 14 56
                line 30 64
                line 62 64
                line 73.31776 28.42991
                line 66.56772 22.12987
                line 14 34
                line 14 56
                """;
        Recognition.Result r =
                Recognition.of(PocketProfile.fromContours(ContourFile.read(new StringReader(text), "c01")));
        // unit-normalised line 4 moves the first event to 7.950215 (seed §5.4); the leaf stays
        assertEquals(7.950215, r.root().events().get(0).t(), 1e-4);
        assertEquals(18.64534, r.root().leafT(), 1e-4);
    }
}
