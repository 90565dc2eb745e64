package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.EntryRule;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.stepnc.Workpiece;
import org.fresa.testing.InterpreterCheck;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * No descending feed move into material is steeper than the entry angle, measured on LinuxCNC's
 * canonical moves (STRAIGHT_FEED, ARC_FEED) of the written programs: the tool's path is replayed
 * over a height map of the material (cells of an eighth of the tool radius at most), and every
 * feed move that goes down while the tool's disc meets material above its tip counts with its
 * slope (descent over the length travelled across the tool axis; a helix's full turns counted).
 */
class EntryAngleTest {

    /** The programs write 3 decimals: a short ramp leg's slope is known to a few hundredths of a degree. */
    static final double TOLERANCE_DEG = 0.1;

    @ParameterizedTest
    @ValueSource(strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"})
    @InterpreterCheck
    void thesisPocketsEnterWithinTheEntryAngle(String name, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        PocketSettings s = PocketServiceTest.settings(name, "linuxcnc");
        Path out = dir.resolve(name + ".ngc");
        TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        Rs274.Result r = Rs274.run(out, s.toolDiameterMm());
        assertEquals(0, r.exitStatus(), Rs274.log(r));
        double steepest = steepestDeg(r.motions(), Transform3.IDENTITY, p -> true, s.zTopMm(), s.toolDiameterMm() / 2);
        System.out.printf(Locale.ROOT, "[entries] %s: steepest descent into material %.2f deg%n", name, steepest);
        assertTrue(steepest <= EntryRule.DEFAULT_ANGLE_DEG + TOLERANCE_DEG, name + ": " + steepest + " deg");
    }

    @ParameterizedTest
    @ValueSource(strings = {"iso14649-11-example1.stp", "example2.stp"})
    @InterpreterCheck
    void stepNcPocketsFacesAndMilledHolesEnterWithinTheEntryAngle(String file, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        StepNcProgram program = StepNcReader.read(Path.of("samples/stepnc", file));
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(program, Tolerance.DEFAULT);
        Map<Long, MachiningWorkingstep> byId = new HashMap<>();
        program.workingsteps().forEach(ws -> byId.put(ws.instanceId(), ws));
        Predicate<Vec3> stock = stock(program);
        double steepest = 0;
        int measured = 0;
        for (int i = 0; i < plan.steps().size(); i++) {
            MachiningWorkingstep ws = byId.get(plan.steps().get(i).workingstepInstanceId());
            if (ws.operation().type().isDrillingType()) {
                continue; // drills cut at their centre: they go straight down
            }
            ToolpathSection section = plan.toolpath().sections().get(i);
            boolean holeOfTheToolsSize = ws.feature().diameterMm().isPresent()
                    && ws.feature().diameterMm().getAsDouble() <= section.toolDiameterMm() + 1e-6;
            Path out = dir.resolve("ws" + i + ".ngc");
            StringWriter w = new StringWriter();
            NcPosts.byName("linuxcnc").orElseThrow().write(new Toolpath(List.of(section)), "ws" + i, w);
            Files.writeString(out, w.toString());
            Rs274.Result r = Rs274.run(out, section.toolDiameterMm());
            assertEquals(0, r.exitStatus(), Rs274.log(r));
            Transform3 toLocal = ws.feature().placement().inverse();
            Transform3 toWorld = ws.feature().placement();
            // material: inside the stock, from the feature's top (z = 0 of its frame) down
            Predicate<Vec2> material = p -> stock.test(toWorld.applyToPoint(Vec3.of(p, -1e-3)));
            double a = steepestDeg(r.motions(), toLocal, material, 0, section.toolDiameterMm() / 2);
            System.out.printf(Locale.ROOT, "[entries] %s %s (%s): steepest descent into material %.2f deg%n", file,
                    section.label(), ws.feature().type(), a);
            if (holeOfTheToolsSize) {
                // a hole no wider than the cutter has room for no helix or ramp: measured, not held to the angle
                continue;
            }
            steepest = Math.max(steepest, a);
            measured++;
        }
        assertTrue(measured > 0, file);
        assertTrue(steepest <= EntryRule.DEFAULT_ANGLE_DEG + TOLERANCE_DEG, file + ": " + steepest + " deg");
    }

    @Test
    void theMeasureSeesAPlungeIntoMaterial() {
        List<Rs274.Canon> moves = List.of(new Rs274.Canon("rapid", new Vec3(0, 0, 5), null, null, 0),
                new Rs274.Canon("feed", new Vec3(0, 0, -3), null, null, 0),
                new Rs274.Canon("feed", new Vec3(10, 0, -3), null, null, 0),
                new Rs274.Canon("feed", new Vec3(20, 0, -4), null, null, 0));
        double a = steepestDeg(moves, Transform3.IDENTITY, p -> true, 0, 3);
        assertEquals(90, a, 1e-9);
    }

    @Test
    void theMeasureIgnoresDescentsThroughTheAirAndCountsHelixTurns() {
        // down through the air to the top, then 2 turns of radius 5 over 1 mm: atan(1 / (4 pi 5))
        List<Rs274.Canon> moves = List.of(new Rs274.Canon("rapid", new Vec3(5, 0, 5), null, null, 0),
                new Rs274.Canon("feed", new Vec3(5, 0, 0), null, null, 0),
                new Rs274.Canon("arc", new Vec3(5, 0, -1), new Vec3(0, 0, 0), Vec3.UNIT_Z, 2));
        double a = steepestDeg(moves, Transform3.IDENTITY, p -> true, 0, 3);
        // the helix is sampled as chords an eighth of the radius long at most
        assertEquals(Math.toDegrees(Math.atan(1 / (4 * Math.PI * 5))), a, 1e-3);
    }

    /** The stock of a sample: the file's BLOCK, else ISO 14649-11 example 1's 100 x 120 mm block (its face's boundary). */
    private static Predicate<Vec3> stock(StepNcProgram program) {
        Optional<Workpiece.Block> block = program.workpieces().stream().flatMap(w -> w.block().stream()).findFirst();
        if (block.isPresent()) {
            Workpiece.Block b = block.get();
            Transform3 inv = b.placement().inverse();
            return p -> {
                Vec3 q = inv.applyToPoint(p);
                return q.x() >= 0 && q.x() <= b.xMm() && q.y() >= 0 && q.y() <= b.yMm() && q.z() >= 0 && q.z() <= b.zMm();
            };
        }
        return p -> p.x() >= 0 && p.x() <= 100 && p.y() >= 0 && p.y() <= 120;
    }

    /**
     * The steepest descending feed move into material (deg; 0 when there is none).
     *
     * @param toLocal from the program's frame to the frame whose +Z is the tool axis
     * @param material where material stands (local XY) up to topZ before any cut
     */
    static double steepestDeg(List<Rs274.Canon> motions, Transform3 toLocal, Predicate<Vec2> material, double topZ,
            double toolRadiusMm) {
        double res = Math.max(0.1, toolRadiusMm / 8);
        Map<Long, Double> cut = new HashMap<>();
        Vec3 at = null;
        double steepest = 0;
        for (Rs274.Canon c : motions) {
            if (c.kind().equals("dwell")) {
                continue;
            }
            if (at == null || c.kind().equals("rapid")) {
                at = c.end();
                continue;
            }
            List<Vec3> pts = new ArrayList<>();
            for (Vec3 p : samples(at, c, res)) {
                pts.add(toLocal.applyToPoint(p));
            }
            double across = 0;
            for (int k = 1; k < pts.size(); k++) {
                across += Math.hypot(pts.get(k).x() - pts.get(k - 1).x(), pts.get(k).y() - pts.get(k - 1).y());
            }
            double drop = pts.get(0).z() - pts.get(pts.size() - 1).z();
            boolean intoMaterial = false;
            for (Vec3 p : pts) {
                int i0 = (int) Math.floor((p.x() - toolRadiusMm) / res);
                int i1 = (int) Math.ceil((p.x() + toolRadiusMm) / res);
                int j0 = (int) Math.floor((p.y() - toolRadiusMm) / res);
                int j1 = (int) Math.ceil((p.y() + toolRadiusMm) / res);
                for (int i = i0; i <= i1; i++) {
                    for (int j = j0; j <= j1; j++) {
                        double x = i * res;
                        double y = j * res;
                        if (Math.hypot(x - p.x(), y - p.y()) > toolRadiusMm) {
                            continue;
                        }
                        long key = ((long) i << 32) ^ (j & 0xffffffffL);
                        double h = cut.getOrDefault(key, material.test(new Vec2(x, y)) ? topZ : Double.NEGATIVE_INFINITY);
                        if (h > p.z() + 1e-3) {
                            intoMaterial = true;
                            cut.put(key, p.z());
                        }
                    }
                }
            }
            if (intoMaterial && drop > 1e-4) {
                steepest = Math.max(steepest, Math.toDegrees(Math.atan2(drop, across)));
            }
            at = c.end();
        }
        return steepest;
    }

    /** Points along a move, at most res apart, the first its start. */
    private static List<Vec3> samples(Vec3 from, Rs274.Canon c, double res) {
        List<Vec3> out = new ArrayList<>();
        if (c.kind().equals("arc")) {
            Vec3 n = c.normal();
            Vec3 centre = c.center().plus(n.times(from.minus(c.center()).dot(n)));
            Vec3 u = from.minus(centre);
            Vec3 ve = c.end().minus(centre);
            ve = ve.minus(n.times(ve.dot(n)));
            double sense = Math.signum(c.rotation());
            double sweep = Math.atan2(n.dot(u.cross(ve)) * sense, u.dot(ve));
            if (sweep < 1e-9) {
                sweep += 2 * Math.PI;
            }
            double total = sweep + 2 * Math.PI * (Math.abs(c.rotation()) - 1);
            double rise = c.end().minus(from).dot(n);
            int steps = (int) Math.max(8, Math.ceil(total * u.norm() / res));
            for (int k = 0; k <= steps; k++) {
                double t = total * k / steps;
                double th = sense * t;
                Vec3 p = centre.plus(u.times(Math.cos(th))).plus(n.cross(u).times(Math.sin(th)))
                        .plus(n.times(rise * k / steps));
                out.add(p);
            }
            return out;
        }
        int steps = (int) Math.max(1, Math.ceil(from.distance(c.end()) / res));
        for (int k = 0; k <= steps; k++) {
            out.add(from.interpolate(c.end(), (double) k / steps));
        }
        return out;
    }
}
