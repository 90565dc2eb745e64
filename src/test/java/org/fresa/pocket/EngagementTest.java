package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.junit.jupiter.api.Test;

/**
 * The engagement measure ({@link Engagement}) on cuts whose angle is known in closed form: a slot
 * engages half the circumference (180 degrees), a straight cut of width s beside it
 * acos(1 - s / R).
 */
class EngagementTest {

    private static final double R = 3;
    private static final double FEED = 300;
    private static final double FINISH = 100;
    private static final List<Contour> FLOOR =
            List.of(Contour.polygon(List.of(new Vec2(0, 0), new Vec2(100, 0), new Vec2(100, 60), new Vec2(0, 60))));

    @Test
    void aSlotEngagesHalfTheCircumference() {
        List<Move> moves =
                List.of(new Move.Linear(new Vec3(10, 30, -3), FEED), new Move.Linear(new Vec3(90, 30, -3), FEED));
        Engagement e = Engagement.of(FLOOR, R, new Vec3(10, 30, 2), moves, FINISH);
        assertEquals(180, e.maxDeg(), 1.5);
        assertEquals(180, e.meanDeg(), 1.5);
        assertEquals(2 * R, Engagement.widthMm(e.maxDeg(), R), 1e-3);
    }

    @Test
    void aCutBesideTheSlotEngagesTheAngleOfItsWidth() {
        double s = 2.4;
        // the slot (at the finishing feed, reported apart), then a pass s beside it with the
        // material on its right (climb), stopped before the slot's round start
        List<Move> moves = List.of(
                new Move.Linear(new Vec3(10, 30, -3), FINISH),
                new Move.Linear(new Vec3(90, 30, -3), FINISH),
                new Move.Linear(new Vec3(90, 30 + s, -3), FINISH),
                new Move.Linear(new Vec3(40, 30 + s, -3), FEED));
        Engagement e = Engagement.of(FLOOR, R, new Vec3(10, 30, 2), moves, FINISH);
        // acos(1 - 2.4 / 3) = 78.46 deg
        assertEquals(Math.toDegrees(Math.acos(1 - s / R)), e.maxDeg(), 1.5);
        assertEquals(Engagement.angleDeg(s, R), e.meanDeg(), 1.5);
        assertEquals(180, e.finishingMaxDeg(), 1.5);
    }

    @Test
    void aPassThatOnlyTouchesUncutFloorEngagesNothing() {
        // passes 3 mm apart from y 30 down to y 6 at the finishing feed, then the last one again:
        // its circumference touches the uncut floor below y 3 and cuts none of it
        List<Move> moves = new java.util.ArrayList<>();
        boolean right = true;
        for (int y = 30; y >= 6; y -= 3) {
            moves.add(new Move.Linear(new Vec3(right ? 10 : 90, y, -3), FINISH));
            moves.add(new Move.Linear(new Vec3(right ? 90 : 10, y, -3), FINISH));
            right = !right;
        }
        moves.add(new Move.Linear(new Vec3(50, 6, -3), FEED));
        Engagement e = Engagement.of(FLOOR, R, new Vec3(10, 30, 2), moves, FINISH);
        assertEquals(0, e.maxDeg(), 2.01);
    }
}
