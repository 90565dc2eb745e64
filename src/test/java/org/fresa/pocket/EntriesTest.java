package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.junit.jupiter.api.Test;

class EntriesTest {

    static final List<Curve2> SHORT_CUT = List.of(Segment2.of(0, 0, 1.35, 0), Segment2.of(1.35, 0, 0, 0));
    static final Entries.Room EVERYWHERE = (c, r) -> true;

    /** Steepest descent of the moves from (start, top), in degrees. */
    static double steepestDeg(Vec2 start, double top, List<Move> moves) {
        Vec3 at = Vec3.of(start, top);
        double worst = 0;
        for (Move m : moves) {
            double drop = at.z() - m.end().z();
            double run;
            if (m instanceof Move.Circular c) {
                Vec2 a = at.xy().minus(c.center().xy());
                Vec2 b = m.end().xy().minus(c.center().xy());
                double sweep = Math.atan2(a.cross(b), a.dot(b));
                sweep = c.ccw()
                        ? (sweep <= 1e-12 ? sweep + 2 * Math.PI : sweep)
                        : (sweep >= -1e-12 ? -sweep + 2 * Math.PI : -sweep);
                run = a.norm() * (sweep + 2 * Math.PI * c.turns());
            } else {
                run = at.xy().distance(m.end().xy());
            }
            if (drop > 1e-12) {
                worst = Math.max(worst, Math.toDegrees(Math.atan2(drop, run)));
            }
            at = m.end();
        }
        return worst;
    }

    @Test
    void aHelixOfTheToolRadiusIsTakenWhereItHasRoom() {
        Entry e = Entries.choose(EntryRule.DEFAULT, Vec2.ZERO, SHORT_CUT, true, EVERYWHERE, 5, 3)
                .orElseThrow();
        Entry.Helix h = assertInstanceOf(Entry.Helix.class, e);
        List<Move> moves = h.moves(0, -3, 300);
        assertAll(
                () -> assertEquals(5, h.radiusMm(), 1e-12),
                // 3 mm at most 3 deg on a radius of 5: 2 pi 5 tan(3 deg) = 1.646 mm a turn, 2 turns
                () -> assertEquals(2, h.turns(3)),
                () -> assertTrue(steepestDeg(Vec2.ZERO, 0, moves) <= 3 + 1e-9),
                () -> assertEquals(
                        Vec3.of(Vec2.ZERO, -3), moves.get(moves.size() - 1).end()));
    }

    static final EntryRule CENTRE_CUTTING = new EntryRule(EntryRule.Kind.AUTO, 3, true);

    @Test
    void withoutRoomForAHelixACentreCuttingToolRampsBackAndForthAlongTheShortCut() {
        Entry e = Entries.choose(CENTRE_CUTTING, Vec2.ZERO, SHORT_CUT, true, Entries.Room.NONE, 5, 3)
                .orElseThrow();
        Entry.Ramp r = assertInstanceOf(Entry.Ramp.class, e);
        List<Move> moves = r.moves(0, -3, 300);
        // 3 / tan(3 deg) = 57.2 mm of travel along a cut of 2.7 mm: 22 legs
        assertAll(
                () -> assertEquals(22, r.legs()),
                () -> assertTrue(steepestDeg(Vec2.ZERO, 0, moves) <= 3 + 1e-9),
                () -> assertEquals(
                        Vec3.of(Vec2.ZERO, -3), moves.get(moves.size() - 1).end()));
    }

    @Test
    void aCutShorterThanTheToolRadiusIsNoRampForACutterThatDoesNotCutAtItsCentre() {
        // forth and back along 1.35 mm, the centre within 0.675 mm: the 2.5 mm core is plunged
        assertFalse(Entries.choose(EntryRule.DEFAULT, Vec2.ZERO, SHORT_CUT, true, Entries.Room.NONE, 5, 3)
                .isPresent());
    }

    @Test
    void theLegsRunOnAlongThePathFollowedAtDepthUntilTheyMoveTheCentre() {
        List<Curve2> onwards = List.of(Segment2.of(0, 0, 0, 20));
        Entry.Ramp r = assertInstanceOf(
                Entry.Ramp.class,
                Entries.choose(
                                EntryRule.DEFAULT,
                                Vec2.ZERO,
                                SHORT_CUT,
                                onwards,
                                true,
                                Entries.Room.NONE,
                                Entries.Room.NONE,
                                5,
                                3)
                        .orElseThrow());
        List<Move> moves = r.moves(0, -3, 300);
        // the shortest start of the path whose centre positions span a circle of 2.5 mm (a thousandth more)
        List<Vec2> course = new java.util.ArrayList<>(List.of(Vec2.ZERO));
        moves.forEach(m -> course.add(m.end().xy()));
        assertAll(
                () -> assertTrue(Entries.movesTheCentreOver(course, 5)),
                () -> assertTrue(r.legLengthMm() < 2.7 + 5.1, r.legLengthMm() + " mm"),
                () -> assertTrue(steepestDeg(Vec2.ZERO, 0, moves) <= 3 + 1e-9),
                () -> assertEquals(
                        Vec3.of(Vec2.ZERO, -3), moves.get(moves.size() - 1).end()));
    }

    @Test
    void whereThePathIsShortTooTheRampZigzagsOneRadiusInsideTheRoom() {
        // the region cleared lies above the line through the start (y >= 0)
        Entries.Room above = (c, r) -> c.y() - r > -1e-9 && Math.abs(c.x()) < 20;
        Entry.Ramp r = assertInstanceOf(
                Entry.Ramp.class,
                Entries.choose(EntryRule.DEFAULT, Vec2.ZERO, SHORT_CUT, List.of(), true, Entries.Room.NONE, above, 5, 3)
                        .orElseThrow());
        List<Move> moves = r.moves(0, -3, 300);
        assertAll(
                () -> assertEquals(5.005, r.legLengthMm(), 1e-9),
                // the first of sixteen directions from +X whose course keeps off that line by more
                // than half its sampling step (0.6 of it): 45 deg
                () -> assertEquals(
                        Math.PI / 4,
                        Math.atan2(
                                r.leg().get(0).end().y(), r.leg().get(0).end().x()),
                        1e-9),
                () -> assertTrue(steepestDeg(Vec2.ZERO, 0, moves) <= 3 + 1e-9),
                () -> assertEquals(
                        Vec3.of(Vec2.ZERO, -3), moves.get(moves.size() - 1).end()));
    }

    @Test
    void aRampOverAnArcStaysAnArc() {
        List<Curve2> cut = List.of(new Arc2(Vec2.ZERO, new Vec2(10, 0), new Vec2(10, 0), true));
        Entry e = Entries.choose(
                        new EntryRule(EntryRule.Kind.RAMP, 3, false), new Vec2(10, 0), cut, true, EVERYWHERE, 5, 2)
                .orElseThrow();
        List<Move> moves = e.moves(0, -2, 300);
        assertTrue(moves.stream().allMatch(m -> m instanceof Move.Circular));
        assertTrue(steepestDeg(new Vec2(10, 0), 0, moves) <= 3 + 1e-9);
    }

    @Test
    void aToolThatDoesNotCutAtItsCentreGetsNoEntryWithoutRoom() {
        List<Curve2> point = List.of();
        assertFalse(Entries.choose(EntryRule.DEFAULT, Vec2.ZERO, point, true, Entries.Room.NONE, 5, 3)
                .isPresent());
        Entry e = Entries.choose(
                        new EntryRule(EntryRule.Kind.AUTO, 3, true), Vec2.ZERO, point, true, Entries.Room.NONE, 5, 3)
                .orElseThrow();
        assertInstanceOf(Entry.Plunge.class, e);
    }

    @Test
    void aPlungeIsOnlyForACentreCuttingTool() {
        assertThrows(IllegalArgumentException.class, () -> new EntryRule(EntryRule.Kind.PLUNGE, 3, false));
        Entry e = Entries.choose(
                        new EntryRule(EntryRule.Kind.PLUNGE, 3, true), Vec2.ZERO, SHORT_CUT, true, EVERYWHERE, 5, 3)
                .orElseThrow();
        assertEquals(90, steepestDeg(Vec2.ZERO, 0, e.moves(0, -3, 300)), 1e-9);
    }

    @Test
    void aHelixTurnsAboutAPointNearerTheStartWhenNoneThroughItFits() {
        // only circles centred within 1 mm of the start fit
        Entries.Room near = (c, r) -> c.norm() <= 1;
        Entry.Helix h = assertInstanceOf(
                Entry.Helix.class,
                Entries.choose(EntryRule.DEFAULT, Vec2.ZERO, SHORT_CUT, true, near, 5, 3)
                        .orElseThrow());
        List<Move> moves = h.moves(0, -3, 300);
        assertAll(
                () -> assertEquals(Vec2.ZERO, h.centre()),
                () -> assertTrue(steepestDeg(Vec2.ZERO, 0, moves) <= 3 + 1e-9),
                () -> assertEquals(
                        Vec3.of(Vec2.ZERO, -3), moves.get(moves.size() - 1).end()));
    }
}
