package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.model.ContourFile;
import org.fresa.model.Toolpath;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

class MultiWaySplitTest {

    @Test
    void theCloverSplitsIntoThreeLobesAndItsHubAtOnceAndIsMilledCompletely() throws Exception {
        String text = Files.readString(Path.of("samples/pocket/clover.contour"));
        Recognition.Result r =
                Recognition.of(PocketProfile.fromContours(ContourFile.read(new StringReader(text), "clover")));
        // the saddles between the hub and each lobe: half the distance of two reflex corners
        assertEquals(28.8097, r.root().splitT(), 1e-4);
        assertEquals(4, r.root().children().size());
        List<Double> leaves = r.leafOffsets().stream().sorted().toList();
        assertEquals(30, leaves.get(0), 1e-6);
        assertEquals(30, leaves.get(2), 1e-6);
        // the hub's innermost point is the origin, 33.27 from each corner
        assertEquals(33.26656, leaves.get(3), 1e-4);
        PocketTechnology t = new PocketTechnology(8, 0.7, 0.1, 0, -3, 3, 3000, 300, 100);
        PocketPlan plan = PassPlanner.plan(r, t, false);
        Toolpath path = PocketToolpath.of(plan, true);
        Geometry swept = PocketCoverageTest.swept(path, -3, 4);
        Geometry wall = PocketCoverageTest.region(plan.generated().get(0), 4);
        assertTrue(wall.buffer(-0.01, 64).difference(swept).getArea() < 1e-3, "uncut material");
        assertTrue(swept.difference(wall.buffer(0.01, 64)).getArea() < 1e-3, "beyond the wall");
    }

    @Test
    void twoCollapsingNecksLeaveThreeRoomsAndAllAreMilled() throws Exception {
        String text = Files.readString(Path.of("samples/pocket/rooms.contour"));
        Recognition.Result r =
                Recognition.of(PocketProfile.fromContours(ContourFile.read(new StringReader(text), "rooms")));
        assertEquals(5, r.root().splitT(), 1e-9);
        assertEquals(3, r.root().children().size());
        for (RecognitionNode c : r.root().children()) {
            assertEquals(20, c.leafT(), 1e-9);
        }
        assertEquals(10, r.maxToolDiameterMm(), 1e-9);
        PocketTechnology t = new PocketTechnology(6, 0.7, 0.1, 0, -3, 3, 3000, 300, 100);
        PocketPlan plan = PassPlanner.plan(r, t, false);
        Toolpath path = PocketToolpath.of(plan, true);
        Geometry swept = PocketCoverageTest.swept(path, -3, 3);
        Geometry wall = PocketCoverageTest.region(plan.generated().get(0), 3);
        assertTrue(wall.buffer(-0.01, 64).difference(swept).getArea() < 1e-3, "uncut material");
        assertTrue(swept.difference(wall.buffer(0.01, 64)).getArea() < 1e-3, "beyond the wall");
    }
}
