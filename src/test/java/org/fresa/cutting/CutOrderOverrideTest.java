package org.fresa.cutting;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.ProgressMonitor;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The planner's own order and start points over the automatic ones: two plates, the larger
 * (part 1, 40 x 30 mm at the origin) with a round hole of radius 8 mm, the smaller (part 2,
 * 30 x 30 mm at x = 60) with a square hole.
 */
class CutOrderOverrideTest {

    static final Vec2 HOLE_CENTRE = Vec2.of(20, 15);

    static List<Curve2> drawing() {
        List<Curve2> l = new ArrayList<>(CutPlannerTest.rect(0, 0, 40, 30));
        l.add(new Arc2(HOLE_CENTRE, Vec2.of(28, 15), Vec2.of(12, 15), true));
        l.add(new Arc2(HOLE_CENTRE, Vec2.of(12, 15), Vec2.of(28, 15), true));
        l.addAll(CutPlannerTest.rect(60, 0, 30, 30));
        l.addAll(CutPlannerTest.rect(70, 10, 10, 10));
        return l;
    }

    static CutPlan plan(CutOrderOverride o, CuttingOptions opts) {
        return CutPlanner.plan(Map.of("0", drawing()), opts, o, (f, s) -> {});
    }

    static CutPlan plan(CutOrderOverride o) {
        return plan(o, CutPlannerTest.plasma(2));
    }

    static List<String> labels(CutPlan p) {
        return p.cuts().stream().map(CutPath::label).toList();
    }

    static CutOrderOverride.Cut at(String label, double x, double y) {
        return new CutOrderOverride.Cut(label, Vec2.of(x, y), Optional.empty());
    }

    @Test
    void theContoursNamedAreCutInTheOrderAskedTheOthersAfterThem() {
        CutPlan auto = plan(CutOrderOverride.NONE);
        assertEquals(List.of("part 1 hole 1", "part 1", "part 2 hole 1", "part 2"), labels(auto));
        // part 2 named by a point on its right edge, its hole not named: the hole still comes first
        CutPlan p = plan(new CutOrderOverride(List.of(at("part 2", 90, 12))));
        assertEquals(List.of("part 2 hole 1", "part 2", "part 1 hole 1", "part 1"), labels(p));
        assertTrue(p.warnings().stream().noneMatch(w -> w.startsWith("cut order")), p.warnings()::toString);
        // every part's path as the automatic plan's: only the order moved
        assertEquals(auto.cutLengthMm(), p.cutLengthMm(), 1e-6);
    }

    @Test
    void theOverrideOfAPlanKeepsItsOrderAndMovingOneCutMovesOnlyIt() {
        CutPlan auto = plan(CutOrderOverride.NONE);
        CutOrderOverride same = CutOrderOverride.of(auto.cuts());
        assertEquals(labels(auto), labels(plan(same)));
        // the holes first, then the parts: part 1 hole 1, part 2 hole 1, part 1, part 2
        CutPlan p = plan(same.moved(2, 1));
        assertEquals(List.of("part 1 hole 1", "part 2 hole 1", "part 1", "part 2"), labels(p));
    }

    @Test
    void aStartPointMovesOntoTheNearestPointOfTheToolPathOnALine() {
        // above part 2's top edge: the tool path runs a half kerf above it, at y = 31
        CutOrderOverride o = new CutOrderOverride(
                List.of(new CutOrderOverride.Cut("part 2", Vec2.of(90, 12), Optional.of(Vec2.of(75, 40)))));
        CutPath c = cut(plan(o), "part 2");
        assertEquals(75, c.path().get(0).start().x(), 1e-9);
        assertEquals(31, c.path().get(0).start().y(), 1e-9);
        assertTrue(!c.leadIn().isEmpty(), "the lead-in placed at the new start");
        assertEquals(
                c.path().get(0).start(), c.leadIn().get(c.leadIn().size() - 1).end());
        assertNotEquals(c.pierce(), cut(plan(CutOrderOverride.NONE), "part 2").pierce());
    }

    @Test
    void aStartPointMovesOntoTheNearestPointOfTheToolPathOnAnArc() {
        // the round hole's tool path has a radius of 7 mm; asked at 45 deg, 20 mm out
        Vec2 ask = HOLE_CENTRE.plus(Vec2.of(1, 1).normalized().times(20));
        CutOrderOverride o = new CutOrderOverride(
                List.of(new CutOrderOverride.Cut("part 1 hole 1", Vec2.of(28, 15), Optional.of(ask))));
        CutPath c = cut(plan(o), "part 1 hole 1");
        Vec2 want = HOLE_CENTRE.plus(Vec2.of(1, 1).normalized().times(7));
        assertEquals(
                0,
                c.path().get(0).start().distance(want),
                1e-6,
                () -> c.path().get(0).start().toString());
        assertTrue(c.path().curves().stream().allMatch(k -> k instanceof Arc2), "the hole is still cut in arcs");
    }

    @Test
    void aStartPointOnACutWithoutLeadsStaysWhereAsked() {
        CuttingOptions noLeads = CuttingOptions.of(CutProcess.PLASMA, 2, 0, 0, false);
        CutOrderOverride o = new CutOrderOverride(
                List.of(new CutOrderOverride.Cut("part 1", Vec2.of(0, 10), Optional.of(Vec2.of(-5, 20)))));
        CutPath c = cut(plan(o, noLeads), "part 1");
        assertEquals(
                0, c.pierce().distance(Vec2.of(-1, 20)), 1e-9, () -> c.pierce().toString());
    }

    @Test
    void aPartBeforeItsHoleIsRefusedNamingBoth() {
        CutOrderOverride o = new CutOrderOverride(List.of(at("part 1", 0, 10), at("part 1 hole 1", 28, 15)));
        CutOrderOverride.Refused e = assertThrows(CutOrderOverride.Refused.class, () -> plan(o));
        assertTrue(
                e.getMessage().contains("part 1 (40.000 x 30.000 mm at 0.000, 0.000) (cut 1)")
                        && e.getMessage().contains("part 1 hole 1 (16.000 x 16.000 mm at 12.000, 7.000) (cut 2)"),
                e.getMessage());
    }

    @Test
    void aHoleBeforeThePartInsideItIsRefusedAndAnUnnamedInnerCutComesBeforeItsNamedOuter() {
        // a frame (part 1) whose window (part 1 hole 1) holds a small plate (part 2)
        List<Curve2> l = new ArrayList<>(CutPlannerTest.rect(0, 0, 100, 100));
        l.addAll(CutPlannerTest.rect(20, 20, 60, 60));
        l.addAll(CutPlannerTest.rect(40, 40, 20, 20));
        Map<String, List<Curve2>> d = Map.of("0", l);
        CuttingOptions o = CutPlannerTest.plasma(2);
        assertEquals(List.of("part 2", "part 1 hole 1", "part 1"), labels(CutPlanner.plan(d, o)));
        CutOrderOverride.Refused e = assertThrows(
                CutOrderOverride.Refused.class,
                () -> CutPlanner.plan(
                        d,
                        o,
                        new CutOrderOverride(List.of(at("part 1 hole 1", 20, 50), at("part 2", 40, 50))),
                        (f, s) -> {}));
        assertTrue(
                e.getMessage()
                        .startsWith("the cut order cuts part 1 hole 1 (60.000 x 60.000 mm at 20.000, 20.000)"
                                + " (cut 1) before part 2"),
                e.getMessage());
        // only the frame named: the window and the plate in it still come first, plate before window
        assertEquals(
                List.of("part 2", "part 1 hole 1", "part 1"),
                labels(CutPlanner.plan(d, o, new CutOrderOverride(List.of(at("part 1", 100, 50))), (f, s) -> {})));
    }

    @Test
    void aContourNotInTheDrawingIsWarnedAboutAndIgnored() {
        CutPlan p = plan(new CutOrderOverride(List.of(at("part 9", 500, 500), at("part 2", 90, 12))));
        assertEquals(List.of("part 2 hole 1", "part 2", "part 1 hole 1", "part 1"), labels(p));
        assertTrue(
                p.warnings()
                        .contains("cut order: no contour of the drawing passes through part 9 at (500.000, 500.000):"
                                + " ignored"),
                p.warnings()::toString);
    }

    @Test
    void theProgramOfAnOverriddenOrderPassesTheProgramCheck(@TempDir Path dir) throws Exception {
        List<Contour> contours = List.of(
                new Contour(CutPlannerTest.rect(0, 0, 40, 30)),
                new Contour(List.of(drawing().get(4), drawing().get(5))),
                new Contour(CutPlannerTest.rect(60, 0, 30, 30)),
                new Contour(CutPlannerTest.rect(70, 10, 10, 10)));
        Path dxf = dir.resolve("plates.dxf");
        Files.writeString(dxf, org.fresa.dxf.DxfWriter.write(contours, "0"));
        CutOrderOverride o = new CutOrderOverride(List.of(
                at("part 2 hole 1", 70, 15),
                new CutOrderOverride.Cut("part 2", Vec2.of(90, 12), Optional.of(Vec2.of(75, 40))),
                new CutOrderOverride.Cut("part 1 hole 1", Vec2.of(28, 15), Optional.of(Vec2.of(20, 0)))));
        CuttingSettings s = new CuttingSettings(
                        dxf,
                        2,
                        CutProcess.PLASMA,
                        3,
                        1,
                        LeadShape.ARC,
                        0.05,
                        org.fresa.dxf.DrawingUnits.MM,
                        false,
                        org.fresa.post.CuttingPost.LINUXCNC)
                .withCutOrder(o);
        CuttingService.Result r = CuttingService.compute(s, ProgressMonitor.NONE);
        assertEquals(List.of("part 2 hole 1", "part 2", "part 1 hole 1", "part 1"), labels(r.plan()));
        CuttingService.check(r, "program.ngc");
        assertTrue(r.program().contains("X75.000 Y31.000") || r.program().contains("X75 Y31"), r.program());
        // and LinuxCNC's interpreter runs it
        org.junit.jupiter.api.Assumptions.assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        Path ngc = dir.resolve("program.ngc");
        Files.writeString(ngc, r.program());
        org.fresa.post.Rs274.Result run = org.fresa.post.Rs274.run(ngc, 0);
        assertEquals(0, run.exitStatus(), () -> org.fresa.post.Rs274.log(run));
    }

    @Test
    void aJobWhoseOrderCutsAPartBeforeItsHoleExitsTwoNamingBoth(@TempDir Path dir) throws Exception {
        Path dxf = dir.resolve("plate.dxf");
        Files.writeString(
                dxf,
                org.fresa.dxf.DxfWriter.write(
                        List.of(
                                new Contour(CutPlannerTest.rect(0, 0, 40, 30)),
                                new Contour(CutPlannerTest.rect(10, 10, 10, 10))),
                        "0"));
        Path job = dir.resolve("job.xml");
        org.fresa.job.JobXml.write(
                org.fresa.job.Job.empty(org.fresa.job.JobTask.CUT)
                        .withCutting(new CuttingSettings(
                                        dxf,
                                        2,
                                        CutProcess.PLASMA,
                                        3,
                                        1,
                                        LeadShape.ARC,
                                        0.05,
                                        org.fresa.dxf.DrawingUnits.MM,
                                        false,
                                        org.fresa.post.CuttingPost.LINUXCNC)
                                .withCutOrder(new CutOrderOverride(
                                        List.of(at("part 1", 40, 15), at("part 1 hole 1", 10, 15))))),
                job);
        java.io.StringWriter err = new java.io.StringWriter();
        int status = org.fresa.app.cli.FresaCommand.execute(
                new java.io.PrintWriter(new java.io.StringWriter(), true),
                new java.io.PrintWriter(err, true),
                "run",
                job.toString(),
                "--out",
                dir.resolve("out").toString());
        assertEquals(2, status, err.toString());
        assertTrue(
                err.toString().contains("cuts part 1 (40.000 x 30.000 mm at 0.000, 0.000) (cut 1) before part 1 hole 1")
                        && !err.toString().contains("\tat "),
                err.toString());
        assertTrue(!Files.exists(dir.resolve("out").resolve("program.ngc")), "no program written");
    }

    static CutPath cut(CutPlan p, String label) {
        return p.cuts().stream()
                .filter(c -> c.label().equals(label))
                .findFirst()
                .orElseThrow();
    }
}
