package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.Robots;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

class CellSceneTest {

    static final double EPS = 1e-6;

    @Test
    void theHomePoseIsZeroForRevoluteJointsAndMidRangeForPrismaticOnes() {
        assertArrayEquals(new double[6], CellScene.homePose(Robots.irb140()));
        assertArrayEquals(new double[] {1350, 1350, 1350, 0, 0, 0}, CellScene.homePose(Robots.tricept806()));
        assertArrayEquals(new double[] {0, 0, 97.5, 0}, CellScene.homePose(Robots.adeptOne()));
    }

    @Test
    void theIrb140AtHomeEndsAtItsFlangeWithTheToolFrameThere() {
        CellScene s = CellScene.of(
                Robots.irb140(),
                new double[6],
                Transform3.IDENTITY,
                Transform3.IDENTITY,
                Optional.empty(),
                List.of(),
                -1);
        List<Vec3> arm = s.links().get(0);
        Vec3 tip = arm.get(arm.size() - 1);
        // spec/robots.md: at q = 0 the flange is at (515, 0, 712)
        assertAll(
                () -> assertEquals(Vec3.ZERO, arm.get(0)),
                () -> assertEquals(0, tip.distance(new Vec3(515, 0, 712)), EPS),
                () -> assertEquals(
                        0,
                        s.frames().stream()
                                .filter(f -> f.name().equals("tool"))
                                .findFirst()
                                .orElseThrow()
                                .pose()
                                .translationPart()
                                .distance(tip),
                        EPS));
    }

    @Test
    void theTriceptsDrawnLegsHaveTheirJointLengths() {
        TriceptRobot t = Robots.tricept806();
        double[] q = {1300, 1400, 1500, 10, 20, 30};
        CellScene s = CellScene.of(t, q, Transform3.IDENTITY, Transform3.IDENTITY, Optional.empty(), List.of(), -1);
        for (int k = 0; k < 3; k++) {
            List<Vec3> leg = s.links().get(k);
            assertEquals(t.legBase(k), leg.get(0));
            assertEquals(q[k], leg.get(0).distance(leg.get(1)), 1e-6, "leg " + (k + 1));
        }
        List<Vec3> centre = s.links().get(4);
        assertEquals(0, centre.get(centre.size() - 1).distance(t.forward(q).translationPart()), EPS);
    }

    @Test
    void legLengthsWithoutAnAssemblyDrawNoRobot() {
        CellScene s = CellScene.of(
                Robots.tricept806(),
                new double[] {1, 1, 5000, 0, 0, 0},
                Transform3.IDENTITY,
                Transform3.IDENTITY,
                Optional.empty(),
                List.of(),
                -1);
        assertTrue(s.links().isEmpty());
    }

    @Test
    void theWorkpieceIsTheBoxAroundTheCuttingMovesInThePieceFrame() {
        Toolpath tp = new Toolpath(List.of(new ToolpathSection(
                "ws",
                Vec3.UNIT_Z,
                10,
                1,
                0,
                new Vec3(0, 0, 50),
                List.of(
                        new Move.Rapid(new Vec3(500, 500, 500)),
                        new Move.Linear(new Vec3(0, 0, -20), 100),
                        new Move.Linear(new Vec3(100, 60, 0), 100)))));
        Transform3 piece = Transform3.translation(400, 0, 300);
        List<List<Vec3>> edges = CellScene.workpieceEdges(tp, piece);
        assertEquals(12, edges.size());
        double minZ =
                edges.stream().flatMap(List::stream).mapToDouble(Vec3::z).min().orElseThrow();
        double maxX =
                edges.stream().flatMap(List::stream).mapToDouble(Vec3::x).max().orElseThrow();
        // the rapid to (500, 500, 500) is not part of the workpiece
        assertAll(() -> assertEquals(280, minZ, EPS), () -> assertEquals(500, maxX, EPS));
    }
}
