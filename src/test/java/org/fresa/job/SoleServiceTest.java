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
import org.fresa.io.OutputFolder;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.sole.Foot;
import org.fresa.sole.SoleTread;
import org.fresa.testing.InterpreterCheck;
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
        assertEquals(org.fresa.grading.ShrinkageMode.ADDITIVE, s.shrinkageMode());
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
                Contour outline = foot == Foot.RIGHT
                        ? g.output().get(0)
                        : SoleTread.mirrored(
                                g.output().get(0), p.grader().origin().x());
                Toolpath tp = SoleService.treadProgram(p, g, foot);
                int cuts = 0;
                for (ToolpathSection sec : tp.sections()) {
                    Vec3 at = sec.start();
                    for (Move m : sec.moves()) {
                        if (!(m instanceof Move.Rapid) && m.end().z() < 0) {
                            Vec2 q = m.end().xy();
                            Vec2 a = at.xy();
                            for (int k = 0; k <= 4; k++) {
                                Vec2 pt = m instanceof Move.Circular c
                                        ? arcPoint(c, a, k / 4.0)
                                        : a.interpolate(q, k / 4.0);
                                double d = outline.distanceTo(pt);
                                assertTrue(
                                        outline.contains(pt, Tolerance.DEFAULT)
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
        org.fresa.geom.Arc2 a =
                new org.fresa.geom.Arc2(c.center().xy(), from, c.end().xy(), c.ccw());
        if (from.distance(c.end().xy()) < 1e-12) {
            a = new org.fresa.geom.Arc2(c.center().xy(), from, from, c.ccw());
        }
        return a.pointAt(t);
    }

    @Test
    @InterpreterCheck
    void theSampleJobWritesEveryProgramAndLinuxCncAcceptsThem(@TempDir Path dir) throws Exception {
        TaskOutcome t = JobRunner.run(JobXml.read(SAMPLE), new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, t.exitStatus(), t.problems().toString());
        for (String size : List.of("38", "39", "40", "41", "42")) {
            for (String f : List.of(
                    "tread-" + size + "-right.ngc",
                    "tread-" + size + "-left.ngc",
                    "size-" + size + ".csv",
                    "sole-" + size + ".png",
                    "cavity-" + size + "-right.ngc",
                    "cavity-" + size + "-left.ngc")) {
                assertTrue(Files.size(dir.resolve(f)) > 0, f);
            }
        }
        Assumptions.assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        try (var files = Files.list(dir)) {
            for (Path f : files.filter(x -> x.toString().endsWith(".ngc")).toList()) {
                org.fresa.post.Rs274.Result r = org.fresa.post.Rs274.run(f, 3.5);
                assertEquals(0, r.exitStatus(), f + ": " + org.fresa.post.Rs274.log(r));
            }
        }
    }

    /** Shoelace sum over the floor feed moves (arcs as chords): positive when the loops run counter-clockwise. */
    private static double floorTurning(Toolpath tp, double z) {
        double sum = 0;
        for (ToolpathSection sec : tp.sections()) {
            Vec3 at = sec.start();
            for (Move m : sec.moves()) {
                if (!(m instanceof Move.Rapid)
                        && Math.abs(at.z() - z) < 1e-9
                        && Math.abs(m.end().z() - z) < 1e-9) {
                    sum += at.x() * m.end().y() - m.end().x() * at.y();
                }
                at = m.end();
            }
        }
        return sum / 2;
    }

    @Test
    void theCavityIsMilledCompletelyWithinTheOutlineOnBothFeetClimbKept() throws Exception {
        JobSettings.SoleSettings s = JobXml.read(SAMPLE).sole().orElseThrow();
        SoleService.SolePlan p = SoleService.plan(s, "men40");
        for (double size : List.of(38.0, 42.0)) {
            GradedSize g = p.grader().grade(size);
            Toolpath right = SoleService.cavityProgram(p, g, Foot.RIGHT).orElseThrow();
            Toolpath left = SoleService.cavityProgram(p, g, Foot.LEFT).orElseThrow();
            Contour outline = g.output().get(0);
            org.locationtech.jts.geom.Geometry wall = org.fresa.pocket.RegionPocketTestAccess.polygon(outline);
            double r = right.sections().get(0).toolDiameterMm() / 2;
            org.locationtech.jts.geom.Geometry swept = org.fresa.pocket.RegionPocketTestAccess.swept(right, -4, r);
            double uncut =
                    wall.buffer(-r, 64).buffer(r - 0.01, 64).difference(swept).getArea();
            double outside = swept.difference(wall.buffer(0.01, 64)).getArea();
            System.out.printf(
                    java.util.Locale.ROOT,
                    "sole cavity %s: uncut %.5f mm2, outside %.5f mm2%n",
                    g.name(),
                    uncut,
                    outside);
            assertTrue(uncut < 1e-3, g.name() + " uncut " + uncut);
            assertTrue(outside < 1e-3, g.name() + " beyond the outline " + outside);
            // the left foot cuts the mirror image of the right one
            org.locationtech.jts.geom.Geometry sweptLeft = org.fresa.pocket.RegionPocketTestAccess.swept(left, -4, r);
            double ox = p.grader().origin().x();
            org.locationtech.jts.geom.util.AffineTransformation mirror =
                    org.locationtech.jts.geom.util.AffineTransformation.reflectionInstance(ox, 0, ox, 1);
            double diff = mirror.transform(sweptLeft).symDifference(swept).getArea();
            assertTrue(diff < 0.05, g.name() + ": left is not the mirror of right, " + diff + " mm2 differ");
            // climb on both feet: every loop counter-clockwise with the clockwise spindle
            assertTrue(floorTurning(right, -4) > 0 && floorTurning(left, -4) > 0, "climb kept");
        }
    }

    @Test
    void aCavityToolNotSmallerThanTheToeArcIsRefusedNamingTheArc() throws Exception {
        Job job = JobXml.read(SAMPLE);
        JobSettings.SoleSettings s = job.sole().orElseThrow();
        List<JobSettings.SoleTool> tools = new java.util.ArrayList<>(s.tools());
        tools.add(new JobSettings.SoleTool("em60", 9, 60, 1500, 200, 80));
        JobSettings.SoleSettings big = new JobSettings.SoleSettings(
                s.outline(),
                s.baseSize(),
                s.sizes(),
                s.cavityDepthMm(),
                s.post(),
                s.system(),
                s.originMm(),
                s.shrinkage(),
                s.shrinkageMode(),
                s.treadDepthMm(),
                s.clearanceMm(),
                s.marginMm(),
                tools,
                s.designs(),
                "em60");
        SoleService.SolePlan p = SoleService.plan(big, "sample");
        GradedSize g = p.grader().grade(40);
        org.fresa.model.CamInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                org.fresa.model.CamInputException.class, () -> SoleService.cavityProgram(p, g, Foot.RIGHT));
        // figure 6.16: the toe arc C7 graded at 1.02 is 55.8 mm across
        assertTrue(e.getMessage().contains("55.8") && e.getMessage().contains("60.000 mm cavity tool"), e.getMessage());
    }
}
