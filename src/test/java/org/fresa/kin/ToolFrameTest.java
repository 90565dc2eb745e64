package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

/** A tool frame moves the TCP off the flange, and the inverse kinematics follows it. */
class ToolFrameTest {

    static final Transform3 TOOL = Transform3.ofXyzRpyDeg(10, -5, 180, 0, 15, 0);

    @Test
    void theTriceptsTcpIsItsFlangeTimesTheTool() {
        TriceptRobot bare = Robots.tricept806();
        Robot tooled = bare.withTool(TOOL);
        double[] q = {1300, 1350, 1250, 20, -40, 30};
        Transform3 expected = bare.forward(q).times(TOOL);
        Transform3 tcp = tooled.forward(q);
        assertAll(
                () -> assertEquals(expected.tx(), tcp.tx(), 1e-9),
                () -> assertEquals(expected.tz(), tcp.tz(), 1e-9),
                () -> assertEquals(
                        0,
                        tooled.flange(q)
                                .translationPart()
                                .distance(bare.forward(q).translationPart()),
                        1e-9));
    }

    @Test
    void theTriceptsInverseKinematicsReachesTheTcp() {
        Robot tooled = Robots.tricept806().withTool(TOOL);
        double[] q = {1300, 1350, 1250, 20, -40, 30};
        Transform3 target = tooled.forward(q);
        IkResult r = tooled.newSolver(IkOptions.DEFAULT).solveCold(target);
        assertTrue(r instanceof IkResult.Converged, r::toString);
        Transform3 reached = tooled.forward(((IkResult.Converged) r).q());
        assertTrue(reached.translationPart().distance(target.translationPart()) <= 1e-7);
    }

    @Test
    void theIrb140sInverseKinematicsReachesTheTcp() {
        Robot tooled = Robots.irb140().withTool(TOOL);
        double[] q = {10, 20, -30, 40, 50, 60};
        Transform3 target = tooled.forward(q);
        IkResult r = tooled.newSolver(IkOptions.DEFAULT).solveCold(target);
        assertTrue(r instanceof IkResult.Converged, r::toString);
        Transform3 reached = tooled.forward(((IkResult.Converged) r).q());
        assertTrue(reached.translationPart().distance(target.translationPart()) <= 1e-7);
    }
}
