package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;

/** The slowed stretches of a line or an arc: found where along it a sample lies, cut out of it as lines and arcs. */
class EngagementFeedTest {

    @Test
    void aSampleIsPlacedAlongALineOrAnArcEitherWayRound() {
        Segment2 s = new Segment2(new Vec2(0, 0), new Vec2(10, 0));
        assertEquals(0.25, EngagementFeed.fractionAlong(s, new Vec2(2.5, 0.3)), 1e-12);
        assertEquals(1, EngagementFeed.fractionAlong(s, new Vec2(12, 0)), 1e-12);
        // a quarter turn from (10, 0) to (0, 10) about the origin, counter-clockwise and back
        Arc2 ccw = new Arc2(Vec2.ZERO, new Vec2(10, 0), new Vec2(0, 10), true);
        Vec2 at30 = new Vec2(10 * Math.cos(Math.toRadians(30)), 10 * Math.sin(Math.toRadians(30)));
        assertEquals(1 / 3.0, EngagementFeed.fractionAlong(ccw, at30), 1e-12);
        assertEquals(2 / 3.0, EngagementFeed.fractionAlong(ccw.reversed(), at30), 1e-12);
        // past the end, nearer the end than the start
        assertEquals(1, EngagementFeed.fractionAlong(ccw, new Vec2(-1, 10)), 1e-12);
        assertEquals(0, EngagementFeed.fractionAlong(ccw, new Vec2(10, -1)), 1e-12);
    }

    @Test
    void aSlowedStretchIsCutOutOfAnArcAsAnArcAndThePiecesJoin() {
        Arc2 c = Arc2.circle(new Vec2(5, 5), 4, false);
        EngagementFeed f = new EngagementFeed(
                Map.of(c, List.of(new EngagementFeed.Stretch(0.25, 0.5, 0.6))),
                new EngagementFeed.Slowed(1, 0.25 * c.length(), 150, new Vec2(5, 1), 110, 0.6));
        List<EngagementFeed.Piece> pieces = f.pieces(c);
        assertEquals(3, pieces.size());
        assertEquals(
                List.of(1.0, 0.6, 1.0),
                pieces.stream().map(EngagementFeed.Piece::factor).toList());
        double length = 0;
        Vec2 at = c.start();
        for (EngagementFeed.Piece p : pieces) {
            Arc2 a = assertInstanceOf(Arc2.class, p.curve());
            assertEquals(c.center(), a.center());
            assertTrue(a.start().distance(at) < 1e-12, a + " after " + at);
            assertEquals(4, a.start().distance(a.center()), 1e-12);
            at = a.end();
            length += a.length();
        }
        assertEquals(c.length(), length, 1e-9);
        assertEquals(0.25 * c.length(), pieces.get(1).curve().length(), 1e-9);
        // a curve with no stretch is written whole, at its feed
        Curve2 other = new Segment2(new Vec2(0, 0), new Vec2(1, 0));
        assertEquals(List.of(new EngagementFeed.Piece(other, 1)), f.pieces(other));
        assertEquals(180, EngagementFeed.feed(300, 0.6));
        assertEquals(300, EngagementFeed.feed(300, 1));
    }
}
