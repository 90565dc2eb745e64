package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Vec3;
import org.fresa.io.OutputFolder;
import org.fresa.post.MillingPost;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --post apt} against LinuxCNC: the APT file of a job, read back by a reader of this test's
 * own (not the program check's), makes exactly the motions LinuxCNC's interpreter makes of the
 * {@code linuxcnc} program of the same job, within 1e-6 mm: every rapid, feed and dwell, and every
 * arc's end, centre and sense, a helix of several turns as LinuxCNC's one ARC_FEED with its turn
 * count against the APT's CIRCLE/GOTO pair per turn.
 */
@InterpreterCheck
class AptPostAcceptanceTest {

    private static final double TOL_MM = 1e-6;

    /** How far a helix's intermediate turn end, rounded to the micrometre in the APT file, may lie (mm). */
    private static final double TURN_END_MM = 0.0005 * Math.sqrt(3) + 1e-6;

    /** One motion of an APT program as this test reads it. */
    record AptMotion(String kind, Vec3 end, Vec3 centre, Vec3 axis, double seconds) {}

    /** Reads GOTO, RAPID, CIRCLE + GOTO and DELAY; the other statements move nothing. */
    static List<AptMotion> read(String program) {
        List<AptMotion> out = new ArrayList<>();
        boolean rapid = false;
        double[] circle = null;
        for (String raw : program.split("\n")) {
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("$$") || line.startsWith("PARTNO")) {
                continue;
            }
            String word = line.contains("/") ? line.substring(0, line.indexOf('/')) : line;
            String[] args =
                    line.contains("/") ? line.substring(line.indexOf('/') + 1).split(",") : new String[0];
            switch (word) {
                case "UNITS" -> assertEquals("MM", args[0], line);
                case "RAPID" -> rapid = true;
                case "CIRCLE" -> {
                    circle = new double[7];
                    for (int i = 0; i < 7; i++) {
                        circle[i] = Double.parseDouble(args[i]);
                    }
                }
                case "GOTO" -> {
                    Vec3 end = new Vec3(
                            Double.parseDouble(args[0]), Double.parseDouble(args[1]), Double.parseDouble(args[2]));
                    if (circle != null) {
                        assertTrue(!rapid, "an arc after RAPID: " + line);
                        out.add(new AptMotion(
                                "arc",
                                end,
                                new Vec3(circle[0], circle[1], circle[2]),
                                new Vec3(circle[3], circle[4], circle[5]),
                                0));
                    } else {
                        out.add(new AptMotion(rapid ? "rapid" : "feed", end, null, null, 0));
                    }
                    rapid = false;
                    circle = null;
                }
                case "DELAY" -> out.add(new AptMotion("dwell", null, null, null, Double.parseDouble(args[0])));
                case "FEDRAT", "SPINDL", "LOADTL", "CUTTER", "COOLNT", "FINI" -> {}
                default -> throw new AssertionError("statement not expected from the post: " + line);
            }
        }
        return out;
    }

    /** What was compared: motions (rapid, feed, dwell, arc) and arcs among them. */
    record Counts(int motions, int arcs) {
        Counts plus(Counts o) {
            return new Counts(motions + o.motions, arcs + o.arcs);
        }
    }

    /** Compares the APT motions with the interpreter's, one by one. */
    static Counts compare(String what, List<Rs274.Canon> canon, List<AptMotion> apt) {
        int i = 0;
        int arcs = 0;
        Vec3 at = null;
        for (int k = 0; k < canon.size(); k++) {
            Rs274.Canon c = canon.get(k);
            String where = what + ", motion " + (k + 1) + " " + c;
            assertTrue(i < apt.size(), where + ": the APT program has no more motions");
            switch (c.kind()) {
                case "rapid", "feed" -> {
                    AptMotion m = apt.get(i++);
                    assertEquals(c.kind(), m.kind(), where);
                    near(c.end(), m.end(), where);
                    at = c.end();
                }
                case "dwell" -> {
                    AptMotion m = apt.get(i++);
                    assertEquals("dwell", m.kind(), where);
                    assertEquals(c.seconds(), m.seconds(), TOL_MM, where);
                }
                case "arc" -> {
                    assertTrue(at != null, where + ": an arc before any position");
                    Vec3 n = c.normal();
                    Vec3 sense = n.times(Math.signum(c.rotation()));
                    int turns = Math.abs(c.rotation());
                    double rise = c.end().minus(at).dot(n);
                    // the helix rises in proportion to its angle: whole turns, then the part
                    // turn to its end (a whole one where the end is over the start)
                    double part = partTurnRad(at, c.end(), c.center(), n, c.rotation() > 0);
                    double sweep = 2 * Math.PI * (turns - 1) + part;
                    for (int t = 1; t <= turns; t++) {
                        AptMotion m = apt.get(i++);
                        assertEquals("arc", m.kind(), where + " turn " + t);
                        near(sense, m.axis(), where + " sense");
                        Vec3 dc = m.centre().minus(c.center());
                        near(Vec3.ZERO, dc.minus(n.times(dc.dot(n))), where + " centre");
                        Vec3 end = t == turns ? c.end() : at.plus(n.times(rise * 2 * Math.PI * t / sweep));
                        // a turn's end short of the last is the APT's own point, written to the
                        // micrometre (LinuxCNC reports only the helix's end)
                        assertTrue(
                                end.distance(m.end()) <= (t == turns ? TOL_MM : TURN_END_MM),
                                where + " end of turn " + t + ": expected " + end + " but the APT has " + m.end());
                        arcs++;
                    }
                    at = c.end();
                }
                default -> throw new AssertionError(where);
            }
        }
        assertEquals(apt.size(), i, what + ": the APT program has motions LinuxCNC does not");
        return new Counts(i, arcs);
    }

    /** The angle (rad, in (0, 2 pi]) from a to b about the centre's axis n, in the arc's sense. */
    private static double partTurnRad(Vec3 a, Vec3 b, Vec3 centre, Vec3 n, boolean ccw) {
        Vec3 u = a.minus(centre);
        u = u.minus(n.times(u.dot(n)));
        Vec3 v = b.minus(centre);
        v = v.minus(n.times(v.dot(n)));
        double angle = Math.atan2(u.cross(v).dot(n), u.dot(v));
        double part = ccw ? angle : -angle;
        part = ((part % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
        return part < 1e-9 ? 2 * Math.PI : part;
    }

    private static void near(Vec3 expected, Vec3 actual, String where) {
        assertTrue(
                expected.distance(actual) <= TOL_MM, where + ": expected " + expected + " but the APT has " + actual);
    }

    private static Counts compareFiles(String what, Path ngc, Path apt, double toolDiameterMm) throws Exception {
        Rs274.Result r = Rs274.run(ngc, toolDiameterMm);
        assertEquals(0, r.exitStatus(), Rs274.log(r));
        Counts n = compare(what, r.motions(), read(Files.readString(apt)));
        System.out.printf(Locale.ROOT, "%s: %d motions, %d arcs compared%n", what, n.motions(), n.arcs());
        return n;
    }

    @Test
    void example1ReadsBackToLinuxCncsMotions(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        // the project's copy: NIST's edit gives the end mill 29 mm of edge for the 30 mm pocket, short
        // of the depth it cuts, which the planner refuses
        Path ex1 = Path.of("samples/stepnc/iso14649-11-example1.stp");
        Path a = dir.resolve("apt");
        Path g = dir.resolve("ngc");
        TaskOutcome oa = ToolpathService.run(ex1, MillingPost.APT, new OutputFolder(a), ProgressMonitor.NONE);
        TaskOutcome og = ToolpathService.run(ex1, MillingPost.LINUXCNC, new OutputFolder(g), ProgressMonitor.NONE);
        assertEquals(0, oa.exitStatus(), oa.problems().toString());
        assertEquals(0, og.exitStatus(), og.problems().toString());
        assertTrue(Files.exists(a.resolve("program.apt")) && !Files.exists(a.resolve("program.ngc")));
        assertEquals("apt", oa.summary().get("post"));
        Counts n = compareFiles("ISO 14649-11 example 1", g.resolve("program.ngc"), a.resolve("program.apt"), 18);
        assertTrue(n.arcs() > 0 && n.motions() > 100, n.toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"examplepart", "cavity01", "cavity02"})
    void thePocketProgramsReadBackToLinuxCncsMotions(String name, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        JobSettings.PocketSettings s = PocketServiceTest.settings(name, "apt");
        Path apt = dir.resolve("pocket.apt");
        Path ngc = dir.resolve("pocket.ngc");
        TaskOutcome oa = PocketService.run(s, apt, ProgressMonitor.NONE);
        TaskOutcome og = PocketService.run(PocketServiceTest.settings(name, "linuxcnc"), ngc, ProgressMonitor.NONE);
        assertEquals(0, oa.exitStatus(), oa.problems().toString());
        assertEquals(0, og.exitStatus(), og.problems().toString());
        Counts n = compareFiles("pocket " + name, ngc, apt, s.toolDiameterMm());
        assertTrue(n.arcs() > 0, n.toString());
    }

    @Test
    void aJobWithPostAptWritesPocketApt(@TempDir Path dir) throws Exception {
        String xml = Files.readString(Path.of("samples/jobs/pocket-cavity01.xml"));
        Path contour = Path.of("samples/pocket/cavity01.dad").toAbsolutePath();
        assertTrue(xml.contains("contour=\"../pocket/cavity01.dad\"") && xml.contains("post=\"7m-compat\""));
        Path job = dir.resolve("cavity01-apt.xml");
        Files.writeString(
                job,
                xml.replace("contour=\"../pocket/cavity01.dad\"", "contour=\"" + contour + "\"")
                        .replace("post=\"7m-compat\"", "post=\"apt\""));
        Path out = dir.resolve("out");
        TaskOutcome o = JobRunner.run(JobXml.read(job), new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals("apt", o.summary().get("post"));
        assertTrue(Files.readString(out.resolve("pocket.apt")).startsWith("PARTNO cavity01.dad\nUNITS/MM\n"));
        assertTrue(!Files.exists(out.resolve("pocket.ngc")) && !Files.exists(out.resolve("pocket.nc")));
    }

    @Test
    void aSoleTreadReadsBackToLinuxCncsMotions(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Job job = JobXml.read(Path.of("samples/jobs/sole-men40.xml"));
        JobSettings.SoleSettings s = job.sole().orElseThrow();
        Path a = dir.resolve("apt");
        Path g = dir.resolve("ngc");
        TaskOutcome oa =
                JobRunner.run(job.withSole(withPost(s, MillingPost.APT)), new OutputFolder(a), ProgressMonitor.NONE);
        TaskOutcome og = JobRunner.run(
                job.withSole(withPost(s, MillingPost.LINUXCNC)), new OutputFolder(g), ProgressMonitor.NONE);
        assertEquals(0, oa.exitStatus(), oa.problems().toString());
        assertEquals(0, og.exitStatus(), og.problems().toString());
        Counts all = new Counts(0, 0);
        for (String f : List.of("tread-40-right", "cavity-40-left")) {
            all = all.plus(compareFiles("sole " + f, g.resolve(f + ".ngc"), a.resolve(f + ".apt"), 3.5));
        }
        assertTrue(all.motions() > 0 && all.arcs() > 0, all.toString());
    }

    private static JobSettings.SoleSettings withPost(JobSettings.SoleSettings s, MillingPost post) {
        return new JobSettings.SoleSettings(
                s.outline(),
                s.baseSize(),
                "40",
                s.cavityDepthMm(),
                post,
                s.system(),
                s.originMm(),
                s.shrinkage(),
                s.shrinkageMode(),
                s.treadDepthMm(),
                s.clearanceMm(),
                s.marginMm(),
                s.tools(),
                s.designs(),
                s.cavityTool(),
                s.block());
    }
}
