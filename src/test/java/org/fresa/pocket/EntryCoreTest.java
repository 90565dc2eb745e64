package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.EnclosingCircle;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

/**
 * A cutter that does not cut at its centre goes down only along a course that moves its centre:
 * the core under it (half its radius, as the helix rule takes it) must pass off every point. A
 * ramp round a loop a few tenths of a millimetre across keeps the core over the same spot all the
 * way down, a plunge in all but name; the region engine used to do that in small faces.
 */
class EntryCoreTest {

    @Test
    void everyEntryOfTheRandomPocketsMovesTheCentreByHalfTheRadius() {
        Random rnd = new Random(21);
        int planned = 0;
        int refused = 0;
        List<String> bad = new ArrayList<>();
        for (int attempt = 0; attempt < 300; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            RegionPocket.Plan plan;
            try {
                plan = RegionPocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT, true);
            } catch (ToolTooLargeException e) {
                assertTrue(e.getMessage().contains("centre-cutting"), e.getMessage());
                refused++;
                continue;
            }
            planned++;
            for (ToolpathSection s : plan.toolpath().sections()) {
                String worst = narrowestEntry(s, t.radiusMm());
                if (worst != null) {
                    bad.add("pocket " + attempt + ": " + worst);
                }
            }
        }
        assertTrue(
                bad.isEmpty(),
                bad.size() + " entries keep the core in place, e.g. " + bad.subList(0, Math.min(5, bad.size())));
        // most pockets still have room to go down; the others are refused with the reason
        assertTrue(planned >= 270, "planned " + planned + ", refused " + refused);
    }

    @Test
    void aFaceTooSmallToGoDownIntoIsRefusedUnlessTheToolCutsAtItsCentre() throws Exception {
        // a 7.4 mm round pocket for a 6 mm cutter: its tool centres have 0.7 mm of room
        Vec2 o = new Vec2(0, 0);
        Contour round = Contour.of(
                List.of(
                        new Arc2(o, new Vec2(3.7, 0), new Vec2(-3.7, 0), true),
                        new Arc2(o, new Vec2(-3.7, 0), new Vec2(3.7, 0), true)),
                Tolerance.DEFAULT);
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.1, 0, -3, 3, 3000, 300, 300);
        ToolTooLargeException e = assertThrows(
                ToolTooLargeException.class,
                () -> RegionPocket.plan(round, List.of(), t, true, EntryRule.DEFAULT, true));
        assertTrue(e.getMessage().contains("does not cut at its centre"), e.getMessage());
        RegionPocket.Plan plan =
                RegionPocket.plan(round, List.of(), t, true, new EntryRule(EntryRule.Kind.AUTO, 3, true), true);
        assertEquals(1, plan.toolpath().sections().size());
    }

    @Test
    void theEnclosingCircleOfAZigzagIsHalfItsLength() {
        assertEquals(1.5, EnclosingCircle.radiusMm(List.of(new Vec2(0, 0), new Vec2(3, 0), new Vec2(0, 0))), 1e-12);
        assertEquals(
                5,
                EnclosingCircle.radiusMm(List.of(new Vec2(5, 0), new Vec2(-5, 0), new Vec2(0, 5), new Vec2(3, 4))),
                1e-12);
    }

    /** The first descending course whose centre stays within half the radius, or null. */
    static String narrowestEntry(ToolpathSection s, double radiusMm) {
        for (List<Vec2> run : descents(s)) {
            if (!Entries.movesTheCentreOver(run, radiusMm)) {
                return String.format(
                        Locale.ROOT,
                        "a ramp within %.3f mm about X%.3f Y%.3f",
                        EnclosingCircle.radiusMm(run),
                        run.get(0).x(),
                        run.get(0).y());
            }
        }
        return null;
    }

    /**
     * The tool centre's positions seen from above along each run of feed moves that go down (a
     * helix or a ramp along an arc sampled 64 times a turn's sweep).
     */
    static List<List<Vec2>> descents(ToolpathSection s) {
        List<List<Vec2>> out = new ArrayList<>();
        Vec3 at = s.start();
        List<Vec2> run = new ArrayList<>();
        for (Move m : s.moves()) {
            boolean down = m.end().z() < at.z() - 1e-9;
            if (m instanceof Move.Circular c && down) {
                // a helix or a ramp along an arc of the loop: its course seen from above
                if (run.isEmpty()) {
                    run.add(new Vec2(at.x(), at.y()));
                }
                Vec2 centre = new Vec2(c.center().x(), c.center().y());
                Vec2 from = new Vec2(at.x(), at.y()).minus(centre);
                Vec2 to = new Vec2(c.end().x(), c.end().y()).minus(centre);
                double a0 = Math.atan2(from.y(), from.x());
                double part = Math.atan2(to.y(), to.x()) - a0;
                part = c.ccw()
                        ? (part % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI)
                        : (-part % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI);
                if (part < 1e-9 && from.distance(to) < 1e-9) {
                    // ending where it began: one whole turn (a helix of one turn)
                    part = 2 * Math.PI;
                }
                double sweep = (part + 2 * Math.PI * c.turns()) * (c.ccw() ? 1 : -1);
                double r = from.norm();
                for (int k = 1; k <= 64; k++) {
                    double a = a0 + sweep * k / 64;
                    run.add(centre.plus(new Vec2(Math.cos(a), Math.sin(a)).times(r)));
                }
            } else if (m instanceof Move.Linear && down) {
                if (run.isEmpty()) {
                    run.add(new Vec2(at.x(), at.y()));
                }
                run.add(new Vec2(m.end().x(), m.end().y()));
            } else if (!run.isEmpty()) {
                out.add(run);
                run = new ArrayList<>();
            }
            at = m.end();
        }
        if (!run.isEmpty()) {
            out.add(run);
        }
        return out;
    }
}
