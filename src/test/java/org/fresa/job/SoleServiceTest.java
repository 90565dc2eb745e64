package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.grading.GradedSize;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.sole.Foot;
import org.fresa.sole.SoleTread;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SoleServiceTest {

    private static final Path SAMPLE = Path.of("samples/jobs/sole-men40.xml");

    @Test
    void theSampleJobReadsBackAsItWasWritten(@TempDir Path dir) throws Exception {
        Job job = JobXml.read(SAMPLE);
        JobSettings.SoleSettings s = job.sole().orElseThrow();
        assertEquals(8, s.designs().size());
        assertEquals(5, s.tools().size());
        assertEquals("additive", s.shrinkageMode());
        Path copy = dir.resolve("copy.xml");
        JobXml.write(job, copy);
        JobSettings.SoleSettings back = JobXml.read(copy).sole().orElseThrow();
        assertEquals(s.designs(), back.designs());
        assertEquals(s.tools(), back.tools());
        assertEquals(s.marginMm(), back.marginMm());
    }

    @Test
    void noTreadCutLeavesTheGradedOutlineOfItsSizeOnEitherFoot() throws Exception {
        Job job = JobXml.read(SAMPLE);
        SoleService.SolePlan p = SoleService.plan(job.sole().orElseThrow(), "sample");
        for (double size : p.grader().plan().sizes()) {
            GradedSize g = p.grader().grade(size);
            for (Foot foot : Foot.values()) {
                Contour outline = foot == Foot.RIGHT ? g.output().get(0)
                        : SoleTread.mirrored(g.output().get(0), p.grader().origin().x());
                Toolpath tp = SoleService.treadProgram(p, g, foot);
                int cuts = 0;
                for (ToolpathSection sec : tp.sections()) {
                    Vec3 at = sec.start();
                    for (Move m : sec.moves()) {
                        if (!(m instanceof Move.Rapid) && m.end().z() < 0) {
                            Vec2 q = m.end().xy();
                            Vec2 a = at.xy();
                            for (int k = 0; k <= 4; k++) {
                                Vec2 pt = m instanceof Move.Circular c ? arcPoint(c, a, k / 4.0) : a.interpolate(q, k / 4.0);
                                double d = outline.distanceTo(pt);
                                assertTrue(outline.contains(pt, Tolerance.DEFAULT)
                                        && d >= 2 + sec.toolDiameterMm() / 2 - 1e-6,
                                        "size " + g.name() + " " + foot + ": groove edge leaves the outline at " + pt);
                            }
                            cuts++;
                        }
                        at = m.end();
                    }
                }
                assertTrue(cuts > 100, "size " + g.name() + " " + foot + " has its tread");
            }
        }
    }

    private static Vec2 arcPoint(Move.Circular c, Vec2 from, double t) {
        org.fresa.geom.Arc2 a = new org.fresa.geom.Arc2(c.center().xy(), from, c.end().xy(), c.ccw());
        if (from.distance(c.end().xy()) < 1e-12) {
            a = new org.fresa.geom.Arc2(c.center().xy(), from, from, c.ccw());
        }
        return a.pointAt(t);
    }

    @Test
    void theSampleJobWritesTreadProgramsThatLinuxCncAcceptsAndReportsTheCavityMissing(@TempDir Path dir)
            throws Exception {
        TaskOutcome t = JobRunner.run(JobXml.read(SAMPLE), new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, t.exitStatus());
        assertTrue(t.problems().get(0).contains("cavity"));
        for (String size : List.of("38", "39", "40", "41", "42")) {
            for (String f : List.of("tread-" + size + "-right.ngc", "tread-" + size + "-left.ngc", "size-" + size + ".csv",
                    "sole-" + size + ".png")) {
                assertTrue(Files.size(dir.resolve(f)) > 0, f);
            }
        }
        Path rs274 = Path.of("../shared/tools/rs274");
        Assumptions.assumeTrue(Files.isExecutable(rs274), "rs274 not available");
        try (var files = Files.list(dir)) {
            for (Path f : files.filter(x -> x.toString().endsWith(".ngc")).toList()) {
                Process p = new ProcessBuilder(rs274.toString(), "--tool-diameter", "3.5", f.toString())
                        .redirectErrorStream(true).start();
                String log = new String(p.getInputStream().readAllBytes());
                assertEquals(0, p.waitFor(), f + ": " + log);
            }
        }
    }
}
