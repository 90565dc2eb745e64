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
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
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
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
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

    /**
     * Every workingstep of the STEP-NC samples but the drills', replayed over the stock: each feed
     * move that descends into material steeper than the entry angle is either <em>into a pilot</em>
     * (straight down the axis of a hole a drill of the same program made before, at least half the
     * cutter's diameter wide, the cutter's axis within the hole's radius less a quarter of its
     * diameter of the hole's axis, ending no deeper than the drill's tip: example 2's holes as wide
     * as the 20 mm cutter, opened by a 10 mm drill, as the file's process plan says) or <em>into
     * material</em>, which no program may have.
     */
    @ParameterizedTest
    @CsvSource(
            delimiter = ';',
            value = {
                "iso14649-11-example1.stp; 0; ''",
                // example 2's eight holes as wide as their cutter, each after its own 10 mm drill: the 20 mm
                // cutter in 5 steps of 2 mm (4 holes), the 10 mm cutter in 10 steps of 1 mm (4 holes)
                "example2.stp; 60; 74 124 174 224 529 579 680 730"
            })
    @InterpreterCheck
    void stepNcPocketsFacesAndMilledHolesEnterWithinTheEntryAngle(
            String file, int pilotDescents, String throughPilots, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Measured m = measure(file, PlanningChoices.DEFAULT, dir);
        assertTrue(m.measured() > 0, file);
        assertEquals(List.of(), m.intoMaterial(), file);
        assertTrue(
                m.steepestDeg() <= EntryRule.DEFAULT_ANGLE_DEG + TOLERANCE_DEG, file + ": " + m.steepestDeg() + " deg");
        assertEquals(pilotDescents, m.intoPilots().size(), file + ": " + m.intoPilots());
        assertEquals(
                throughPilots.strip(),
                m.enteredThroughPilots().stream()
                        .map(String::valueOf)
                        .collect(java.util.stream.Collectors.joining(" ")),
                file);
    }

    /** {@code --entry-angle} and {@code --entry} of the STEP-NC commands: no entry into material steeper than asked. */
    @ParameterizedTest
    @CsvSource({
        "iso14649-11-example1.stp, auto, 1.5",
        "iso14649-11-example1.stp, ramp, 2",
        "iso14649-11-example1.stp, helix, 5",
        "example2.stp, auto, 1.5",
        "example2.stp, ramp, 2"
    })
    @InterpreterCheck
    void stepNcEntriesKeepTheAngleAsked(String file, String kind, double angleDeg, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        EntryRule asked = new EntryRule(EntryRule.Kind.of(kind).orElseThrow(), angleDeg, false);
        Measured m = measure(file, new PlanningChoices(false, PlanningChoices.DEFAULT_BREAKTHROUGH_MM, asked), dir);
        assertTrue(m.measured() > 0, file);
        assertEquals(List.of(), m.intoMaterial(), file);
        assertTrue(
                m.steepestDeg() <= angleDeg + TOLERANCE_DEG,
                file + " " + kind + " " + angleDeg + ": " + m.steepestDeg() + " deg");
    }

    /** What the measure finds in a STEP-NC file's programs. */
    record Measured(
            int measured,
            double steepestDeg,
            List<String> intoMaterial,
            List<String> intoPilots,
            java.util.SortedSet<Long> enteredThroughPilots) {}

    static Measured measure(String file, PlanningChoices choices, Path dir) throws Exception {
        StepNcProgram program = StepNcReader.read(Path.of("samples/stepnc", file));
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(program, Tolerance.DEFAULT, choices);
        double limit = choices.entry().angleDeg();
        Map<Long, MachiningWorkingstep> byId = new HashMap<>();
        program.workingsteps().forEach(ws -> byId.put(ws.instanceId(), ws));
        Predicate<Vec3> stock = stock(program);
        List<DrilledHole> drilled = new ArrayList<>();
        List<String> intoMaterial = new ArrayList<>();
        List<String> intoPilots = new ArrayList<>();
        java.util.SortedSet<Long> enteredThroughPilots = new java.util.TreeSet<>();
        double steepest = 0;
        int measured = 0;
        for (int i = 0; i < plan.steps().size(); i++) {
            MachiningWorkingstep ws = byId.get(plan.steps().get(i).workingstepInstanceId());
            ToolpathSection section = plan.toolpath().sections().get(i);
            Path out = dir.resolve("ws" + i + ".ngc");
            StringWriter w = new StringWriter();
            NcPosts.byName("linuxcnc").orElseThrow().write(new Toolpath(List.of(section)), "ws" + i, w);
            Files.writeString(out, w.toString());
            Rs274.Result r = Rs274.run(out, section.toolDiameterMm());
            assertEquals(0, r.exitStatus(), Rs274.log(r));
            Transform3 toWorld = ws.feature().placement();
            Vec3 axis = toWorld.applyToDirection(Vec3.UNIT_Z).normalized();
            String label = "ws " + i + " " + section.label() + " #" + ws.instanceId();
            if (ws.operation().type().isDrillingType()) {
                // drills cut at their centre: they go straight down, and leave the holes a cutter may enter
                drilled.addAll(holes(r.motions(), axis, section.toolDiameterMm() / 2, label));
                continue;
            }
            Transform3 toLocal = toWorld.inverse();
            // material: inside the stock, from the feature's top (z = 0 of its frame) down
            Predicate<Vec2> material = p -> stock.test(toWorld.applyToPoint(Vec3.of(p, -1e-3)));
            double radius = section.toolDiameterMm() / 2;
            double a = 0;
            int pilots = 0;
            for (Descent d : descents(r.motions(), toLocal, material, 0, radius)) {
                if (d.deg() <= limit + TOLERANCE_DEG) {
                    a = Math.max(a, d.deg());
                    continue;
                }
                Optional<String> pilot = drilled.stream()
                        .map(h -> h.admits(d, axis, radius))
                        .flatMap(Optional::stream)
                        .findFirst();
                String what = String.format(
                        Locale.ROOT, "%s %s: %.2f deg from %s to %s", file, label, d.deg(), d.from(), d.to());
                if (pilot.isPresent()) {
                    intoPilots.add(what + " into " + pilot.get());
                    enteredThroughPilots.add(ws.instanceId());
                    pilots++;
                } else {
                    intoMaterial.add(what);
                    a = Math.max(a, d.deg());
                }
            }
            System.out.printf(
                    Locale.ROOT,
                    "[entries] %s %s (%s): steepest descent into material %.2f deg, %d into a pilot%n",
                    file,
                    section.label(),
                    ws.feature().type(),
                    a,
                    pilots);
            steepest = Math.max(steepest, a);
            measured++;
        }
        intoPilots.forEach(s -> System.out.println("[entries] into a pilot: " + s));
        intoMaterial.forEach(s -> System.out.println("[entries] INTO MATERIAL: " + s));
        System.out.printf(
                Locale.ROOT,
                "[entries] %s (%s %.1f deg): %d workingsteps measured, steepest into material %.2f deg, "
                        + "%d steep descents into material, %d into pilot holes%n",
                file,
                choices.entry().kind().word(),
                limit,
                measured,
                steepest,
                intoMaterial.size(),
                intoPilots.size());
        return new Measured(measured, steepest, intoMaterial, intoPilots, enteredThroughPilots);
    }

    @Test
    void aPlungeIsIntoAPilotOnlyOnItsAxisNoDeeperThanTheDrillsTipAndIntoAWideEnoughHole() {
        DrilledHole pilot = new DrilledHole(new Vec3(20, 20, 190), Vec3.UNIT_Z, 5, "a 10 mm drill");
        Descent onAxis = new Descent(new Vec3(20, 20, 199), new Vec3(20, 20, 190), 90);
        assertTrue(pilot.admits(onAxis, Vec3.UNIT_Z, 10).isPresent());
        // the 20 mm cutter's core, up to 5 mm about its axis, must stay over the 10 mm hole: no offset at all
        assertTrue(pilot.admits(new Descent(new Vec3(20.5, 20, 199), new Vec3(20.5, 20, 195), 90), Vec3.UNIT_Z, 10)
                .isEmpty());
        // below the drill's tip
        assertTrue(pilot.admits(new Descent(new Vec3(20, 20, 192), new Vec3(20, 20, 189), 90), Vec3.UNIT_Z, 10)
                .isEmpty());
        // a 24 mm cutter's core is wider than the 10 mm hole
        assertTrue(pilot.admits(onAxis, Vec3.UNIT_Z, 12).isEmpty());
        // a hole drilled along another axis
        assertTrue(pilot.admits(onAxis, Vec3.UNIT_X, 10).isEmpty());
        // not straight down
        assertTrue(pilot.admits(new Descent(new Vec3(20, 20, 199), new Vec3(20, 20.2, 190), 88.7), Vec3.UNIT_Z, 10)
                .isEmpty());
    }

    /** A steep descent into material: where it starts and ends (program frame) and its slope. */
    record Descent(Vec3 from, Vec3 to, double deg) {}

    /**
     * A hole a drill made going straight down its axis: the conditions under which a cutter that
     * does not cut at its centre may follow it down, stated here independently of the program check.
     */
    record DrilledHole(Vec3 tip, Vec3 axis, double radiusMm, String by) {

        /** The last written digit of the programs. */
        static final double CLEAR_MM = 1e-3;

        /** Why the descent is into this hole, or empty when it is not. */
        Optional<String> admits(Descent d, Vec3 cutterAxis, double cutterRadiusMm) {
            Vec3 move = d.to().minus(d.from());
            double along = move.dot(axis);
            boolean straightDown =
                    along < 0 && move.minus(axis.times(along)).norm() <= CLEAR_MM && cutterAxis.dot(axis) > 1 - 1e-9;
            boolean wideEnough = 2 * radiusMm >= cutterRadiusMm - 1e-9; // the hole at least half the cutter's diameter
            double reach =
                    radiusMm - cutterRadiusMm / 2 + CLEAR_MM; // hole's radius less a quarter of the cutter's diameter
            double off = Math.max(off(d.from()), off(d.to()));
            double belowTip = -d.to().minus(tip).dot(axis);
            if (!(straightDown && wideEnough && off <= reach && belowTip <= CLEAR_MM)) {
                return Optional.empty();
            }
            return Optional.of(String.format(
                    Locale.ROOT,
                    "the %.1f mm hole %s drilled to %s (cutter %.1f mm, %.3f mm off its axis of %.3f allowed, %.3f mm above its tip)",
                    2 * radiusMm,
                    by,
                    tip,
                    2 * cutterRadiusMm,
                    off,
                    reach - CLEAR_MM,
                    -belowTip));
        }

        private double off(Vec3 p) {
            Vec3 d = p.minus(tip);
            return d.minus(axis.times(d.dot(axis))).norm();
        }
    }

    /** The holes a drilling section's straight-down feed moves leave: the tip of each. */
    private static List<DrilledHole> holes(List<Rs274.Canon> motions, Vec3 axis, double radiusMm, String by) {
        List<DrilledHole> out = new ArrayList<>();
        Vec3 at = null;
        for (Rs274.Canon c : motions) {
            if (c.kind().equals("dwell")) {
                continue;
            }
            if (at != null && c.kind().equals("feed")) {
                Vec3 d = c.end().minus(at);
                double along = d.dot(axis);
                if (along < 0 && d.minus(axis.times(along)).norm() <= DrilledHole.CLEAR_MM) {
                    out.add(new DrilledHole(c.end(), axis, radiusMm, by));
                }
            }
            at = c.end();
        }
        return out;
    }

    @Test
    void theMeasureSeesAPlungeIntoMaterial() {
        List<Rs274.Canon> moves = List.of(
                new Rs274.Canon("rapid", new Vec3(0, 0, 5), null, null, 0),
                new Rs274.Canon("feed", new Vec3(0, 0, -3), null, null, 0),
                new Rs274.Canon("feed", new Vec3(10, 0, -3), null, null, 0),
                new Rs274.Canon("feed", new Vec3(20, 0, -4), null, null, 0));
        double a = steepestDeg(moves, Transform3.IDENTITY, p -> true, 0, 3);
        assertEquals(90, a, 1e-9);
    }

    @Test
    void theMeasureIgnoresDescentsThroughTheAirAndCountsHelixTurns() {
        // down through the air to the top, then 2 turns of radius 5 over 1 mm: atan(1 / (4 pi 5))
        List<Rs274.Canon> moves = List.of(
                new Rs274.Canon("rapid", new Vec3(5, 0, 5), null, null, 0),
                new Rs274.Canon("feed", new Vec3(5, 0, 0), null, null, 0),
                new Rs274.Canon("arc", new Vec3(5, 0, -1), new Vec3(0, 0, 0), Vec3.UNIT_Z, 2));
        double a = steepestDeg(moves, Transform3.IDENTITY, p -> true, 0, 3);
        // the helix is sampled as chords an eighth of the radius long at most
        assertEquals(Math.toDegrees(Math.atan(1 / (4 * Math.PI * 5))), a, 1e-3);
    }

    /** The stock of a sample: the file's BLOCK, else ISO 14649-11 example 1's 100 x 120 mm block (its face's boundary). */
    private static Predicate<Vec3> stock(StepNcProgram program) {
        Optional<Workpiece.Block> block =
                program.workpieces().stream().flatMap(w -> w.block().stream()).findFirst();
        if (block.isPresent()) {
            Workpiece.Block b = block.get();
            Transform3 inv = b.placement().inverse();
            return p -> {
                Vec3 q = inv.applyToPoint(p);
                return q.x() >= 0
                        && q.x() <= b.xMm()
                        && q.y() >= 0
                        && q.y() <= b.yMm()
                        && q.z() >= 0
                        && q.z() <= b.zMm();
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
    static double steepestDeg(
            List<Rs274.Canon> motions, Transform3 toLocal, Predicate<Vec2> material, double topZ, double toolRadiusMm) {
        return descents(motions, toLocal, material, topZ, toolRadiusMm).stream()
                .mapToDouble(Descent::deg)
                .max()
                .orElse(0);
    }

    /** Every descending feed move into material, with its slope (deg). */
    static List<Descent> descents(
            List<Rs274.Canon> motions, Transform3 toLocal, Predicate<Vec2> material, double topZ, double toolRadiusMm) {
        List<Descent> out = new ArrayList<>();
        double res = Math.max(0.1, toolRadiusMm / 8);
        Map<Long, Double> cut = new HashMap<>();
        Vec3 at = null;
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
                across += Math.hypot(
                        pts.get(k).x() - pts.get(k - 1).x(),
                        pts.get(k).y() - pts.get(k - 1).y());
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
                        double h =
                                cut.getOrDefault(key, material.test(new Vec2(x, y)) ? topZ : Double.NEGATIVE_INFINITY);
                        if (h > p.z() + 1e-3) {
                            intoMaterial = true;
                            cut.put(key, p.z());
                        }
                    }
                }
            }
            if (intoMaterial && drop > 1e-4) {
                out.add(new Descent(at, c.end(), Math.toDegrees(Math.atan2(drop, across))));
            }
            at = c.end();
        }
        return out;
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
                Vec3 p = centre.plus(u.times(Math.cos(th)))
                        .plus(n.cross(u).times(Math.sin(th)))
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
