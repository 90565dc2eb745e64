package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

class TrajectorySolverTest {

    /** An arc around the robot from 150 to 210 deg: q1 cannot pass its +-180 deg limit and jumps round. */
    static List<ToolTarget> acrossTheBack() {
        List<ToolTarget> t = new ArrayList<>();
        for (int i = 0; i <= 60; i++) {
            double a = Math.toRadians(150 + i);
            t.add(ToolTarget.of("back", new Vec3(450 * Math.cos(a), 450 * Math.sin(a), 300), new Vec3(0, 0, -1)));
        }
        return t;
    }

    /** The IRB-140 without its over-the-head configurations (q3 limited to -130..50). */
    static SerialRobot frontOnly() {
        List<DhJoint> j = new ArrayList<>(Robots.irb140().chain().joints());
        DhJoint q3 = j.get(2);
        j.set(2, new DhJoint(q3.type(), q3.aMm(), q3.alphaDeg(), q3.dMm(), q3.thetaDeg(), -130, 50));
        return new SerialRobot("irb140-front", "test", new DenavitHartenbergChain(j), 4);
    }

    @Test
    void aConfigurationChangeIsMadeAwayFromThePartThroughThreeRelinkPoints() {
        TrajectorySolver.Result r = new TrajectorySolver(
                        frontOnly(), TrajectorySolver.Options.DEFAULT.withFreeRotation(false))
                .solve(acrossTheBack(), null);
        assertEquals(0, r.unreachable());
        assertEquals(
                3,
                r.relinks(),
                () -> r.points().stream()
                        .map(x -> x.status() + java.util.Arrays.toString(x.q()))
                        .toList()
                        .toString());
        List<TrajectoryPoint> p = r.points();
        int first = -1;
        for (int i = 0; i < p.size(); i++) {
            if (p.get(i).status() == TrajectoryPoint.Status.RELINK) {
                first = i;
                break;
            }
        }
        TrajectoryPoint b = p.get(first - 1);
        TrajectoryPoint up1 = p.get(first);
        TrajectoryPoint up2 = p.get(first + 1);
        TrajectoryPoint b2 = p.get(first + 2);
        // lifted along the tool axis (tool points down: lifted means up), same pose twice
        assertEquals(b.target().tz() + 50, up1.target().tz(), 1e-9);
        assertEquals(up1.target().tx(), up2.target().tx(), 1e-9);
        assertTrue(b2.target().translationPart().distance(b.target().translationPart()) < 1e-9);
        // B and the lifted B in the old configuration; the lifted B and B again in the new one
        assertTrue(Math.abs(up1.q()[0] - b.q()[0]) < 20);
        assertTrue(Math.abs(up2.q()[0] - up1.q()[0]) > 90, () -> up1.q()[0] + " -> " + up2.q()[0]);
        assertTrue(Math.abs(b2.q()[0] - up2.q()[0]) < 20);
        // every point exact, and no jump between neighbouring ok points
        TrajectoryPoint prev = null;
        for (TrajectoryPoint x : p) {
            assertTrue(x.posErrMm() <= 1e-6 && x.rotErrRad() <= 1e-8);
            if (x.status() == TrajectoryPoint.Status.OK && prev != null && prev.status() == TrajectoryPoint.Status.OK) {
                for (int i = 0; i < 6; i++) {
                    assertTrue(Math.abs(x.q()[i] - prev.q()[i]) <= 20);
                }
            }
            prev = x;
        }
    }

    @Test
    void anUnreachableTargetIsReportedWithoutJointsAndTheRestIsSolved() {
        List<ToolTarget> t = new ArrayList<>(List.of(
                ToolTarget.of("a", new Vec3(500, 0, 300), new Vec3(0, 0, -1)),
                ToolTarget.of("far", new Vec3(1500, 0, 300), new Vec3(0, 0, -1)),
                ToolTarget.of("b", new Vec3(505, 0, 300), new Vec3(0, 0, -1))));
        TrajectorySolver.Result r =
                new TrajectorySolver(Robots.irb140(), TrajectorySolver.Options.DEFAULT).solve(t, null);
        assertEquals(
                List.of(TrajectoryPoint.Status.OK, TrajectoryPoint.Status.UNREACHABLE, TrajectoryPoint.Status.OK),
                r.points().stream().map(TrajectoryPoint::status).toList());
        assertEquals(0, r.points().get(1).q().length);
        assertTrue(r.points().get(1).reached().isEmpty());
    }
}
