package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.PocketPost;
import org.fresa.setting.SettingRanges;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PocketServiceTest {

    static PocketSettings settings(String name, String post) throws Exception {
        for (String line : Files.readAllLines(Path.of("samples/pocket/jobs.csv"))) {
            String[] f = line.split(",");
            if (f[0].equals(name + ".dad")) {
                double[] v = new double[9];
                for (int i = 0; i < 9; i++) {
                    v[i] = Double.parseDouble(f[i + 1]);
                }
                return new PocketSettings(
                        Path.of("samples/pocket", f[0]),
                        v[0],
                        v[1],
                        v[2],
                        v[3],
                        v[4],
                        v[5],
                        v[6],
                        v[7],
                        v[8],
                        SettingRanges.Pocket.POST.require(post),
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT);
            }
        }
        throw new IllegalArgumentException(name);
    }

    @ParameterizedTest
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
    @InterpreterCheck
    void linuxCncAcceptsTheDefaultProgram(String name, @TempDir Path dir) throws Exception {
        assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        PocketSettings s = settings(name, "linuxcnc");
        Path out = dir.resolve(name + ".ngc");
        TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        org.fresa.post.Rs274.Result r = org.fresa.post.Rs274.run(out, s.toolDiameterMm());
        assertEquals(0, r.exitStatus(), org.fresa.post.Rs274.log(r));
    }

    @Test
    void theSummaryCarriesTheThesisSizes(@TempDir Path dir) throws Exception {
        TaskOutcome o =
                PocketService.run(settings("cavity06", "7m-compat"), dir.resolve("c6.nc"), ProgressMonitor.NONE);
        assertEquals(
                List.of(17.750278396781758, 30.0).size(), ((List<?>) o.summary().get("leaf_offsets")).size());
        assertEquals(60.0, (double) o.summary().get("max_hole_diameter"), 1e-6);
        assertEquals(30.0, (double) o.summary().get("max_tool_diameter"), 1e-6);
        assertEquals(14.17, (double) o.summary().get("wall_tool_diameter"), 0.01);
        assertEquals(5, o.summary().get("passes"));
    }

    @Test
    void everyStrategysSummaryCarriesTheThesisSizesTheCommandLinePromises(@TempDir Path dir) throws Exception {
        // spec/cli.md: fresa pocket --json prints at least leaf_offsets, max_hole_diameter,
        // max_tool_diameter, wall_tool_diameter, passes and path_length_mm, whatever the strategy
        for (org.fresa.pocket.PocketStrategy st : new org.fresa.pocket.PocketStrategy[] {
            new org.fresa.pocket.PocketStrategy(
                    org.fresa.pocket.PocketStrategy.Kind.ZIGZAG,
                    30,
                    0,
                    org.fresa.pocket.PocketStrategy.Order.INSIDE_OUT),
            new org.fresa.pocket.PocketStrategy(
                    org.fresa.pocket.PocketStrategy.Kind.OFFSET,
                    0,
                    0.5,
                    org.fresa.pocket.PocketStrategy.Order.OUTSIDE_IN)
        }) {
            TaskOutcome o = PocketService.run(
                    settings("cavity06", "linuxcnc").withStrategy(st), dir.resolve("c6.ngc"), ProgressMonitor.NONE);
            assertEquals(0, o.exitStatus(), o.problems().toString());
            assertEquals(2, ((List<?>) o.summary().get("leaf_offsets")).size(), st.toString());
            assertEquals(60.0, (double) o.summary().get("max_hole_diameter"), 1e-6);
            assertEquals(30.0, (double) o.summary().get("max_tool_diameter"), 1e-6);
            assertEquals(14.17, (double) o.summary().get("wall_tool_diameter"), 0.01);
            assertTrue((int) o.summary().get("passes") > 0, st.toString());
            assertTrue((double) o.summary().get("path_length_mm") > 0, st.toString());
        }
    }

    @Test
    void theThesisProgramOfCavity02WarnsOfItsCutIntoTheWall(@TempDir Path dir) throws Exception {
        // circles 5 and 6 miss each other by 0.755 mm, line 1 and circle 2 by 0.368 mm: the
        // thesis's pass joins them at the snapped point and cuts past circle 6 by that much
        TaskOutcome printed =
                PocketService.run(settings("cavity02", "7m-compat"), dir.resolve("c2.nc"), ProgressMonitor.NONE);
        TaskOutcome milled =
                PocketService.run(settings("cavity02", "linuxcnc"), dir.resolve("c2.ngc"), ProgressMonitor.NONE);
        String warning = printed.problems().stream()
                .filter(p -> p.contains("cuts into the wall"))
                .findFirst()
                .orElse("none in " + printed.problems());
        assertAll(
                () -> assertEquals(0, printed.exitStatus()),
                () -> assertTrue(warning.contains("by up to 0.755 mm"), warning),
                () -> assertTrue(warning.contains("0.368 mm at (15.814, 117.573)"), warning),
                () -> assertTrue(milled.problems().stream().noneMatch(p -> p.contains("cuts into the wall"))));
    }

    @Test
    void aBadRecordWritesNothing(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.dad");
        Files.writeString(bad, " 1R                   1.2.3\r\n");
        PocketSettings s = new PocketSettings(
                bad,
                6,
                0.6,
                0.1,
                0,
                -3,
                3,
                3000,
                300,
                100,
                PocketPost.SINUMERIK_7M,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);
        CamInputException e = assertThrows(
                CamInputException.class, () -> PocketService.run(s, dir.resolve("x.nc"), ProgressMonitor.NONE));
        assertEquals(1, e.line().orElseThrow());
        assertFalse(Files.exists(dir.resolve("x.nc")));
    }

    @Test
    void everyGenericPostWritesTheProgram(@TempDir Path dir) throws Exception {
        for (String post : List.of("iso", "fanuc", "840d", "linuxcnc")) {
            TaskOutcome o =
                    PocketService.run(settings("cavity01", post), dir.resolve(post + ".nc"), ProgressMonitor.NONE);
            assertEquals(0, o.exitStatus(), post + ": " + o.problems());
            assertTrue(Files.readString(dir.resolve(post + ".nc")).contains(" X"), post);
        }
    }

    private static long words(String nc, String word) {
        return java.util.regex.Pattern.compile("\\b" + word + "\\b")
                .matcher(nc)
                .results()
                .count();
    }

    /** Signed area of the feed moves' XY endpoints at the floor (positive: counter-clockwise). */
    private static double floorArea(org.fresa.model.Toolpath path, double floorZ) {
        List<org.fresa.geom.Vec3> pts = new java.util.ArrayList<>();
        for (org.fresa.model.ToolpathSection sec : path.sections()) {
            for (org.fresa.model.Move m : sec.moves()) {
                if (!(m instanceof org.fresa.model.Move.Rapid)
                        && Math.abs(m.end().z() - floorZ) < 1e-9) {
                    pts.add(m.end());
                }
            }
        }
        double a = 0;
        for (int i = 1; i < pts.size(); i++) {
            a += pts.get(i - 1).x() * pts.get(i).y()
                    - pts.get(i).x() * pts.get(i - 1).y();
        }
        return a / 2;
    }

    @Test
    void conventionalMillingTurnsTheLoopsTheOtherWay(@TempDir Path dir) throws Exception {
        // climb milling by default, conventional on request
        // the example part's arcs are all convex: clockwise (G02) in the thesis's conventional passes
        PocketSettings climb = settings("examplepart", "linuxcnc");
        PocketSettings conventional = climb.withDirection(MillingDirection.CONVENTIONAL);
        assertEquals(MillingDirection.CLIMB, climb.direction());
        TaskOutcome a = PocketService.run(climb, dir.resolve("climb.ngc"), ProgressMonitor.NONE);
        TaskOutcome b = PocketService.run(conventional, dir.resolve("conv.ngc"), ProgressMonitor.NONE);
        String ca = Files.readString(dir.resolve("climb.ngc"));
        String cb = Files.readString(dir.resolve("conv.ngc"));
        org.fresa.pocket.PocketPlan plan = PocketService.plan(climb);
        double floor = climb.zBottomMm();
        double climbArea = floorArea(org.fresa.pocket.PocketToolpath.of(plan, true), floor);
        double convArea = floorArea(org.fresa.pocket.PocketToolpath.of(plan, false), floor);
        org.junit.jupiter.api.Assertions.assertAll(
                () -> assertEquals("climb", a.summary().get("direction")),
                () -> assertEquals("conventional", b.summary().get("direction")),
                () -> assertTrue(words(ca, "G3") > words(ca, "G2"), "climb: convex arcs counter-clockwise"),
                () -> assertEquals(words(ca, "G2"), words(cb, "G3")),
                () -> assertEquals(words(ca, "G3"), words(cb, "G2")),
                () -> assertTrue(climbArea > 0, "climb loops counter-clockwise: " + climbArea),
                () -> assertTrue(convArea < 0, "conventional loops clockwise: " + convArea),
                // a move shorter than a micrometre is left out of the program, which of them depends on the direction
                () -> assertEquals(
                        (double) a.summary().get("path_length_mm"),
                        (double) b.summary().get("path_length_mm"),
                        1e-3));
    }

    @Test
    void aPocketWithIslandsIsMilledConventionallyOnRequest(@TempDir Path dir) throws Exception {
        Path rooms = Path.of("samples/pocket/rooms-islands.contour");
        PocketSettings climb = islandSettings(rooms, "linuxcnc");
        List<org.fresa.geom.Contour> c = PocketService.readContours(rooms);
        double floor = climb.zBottomMm();
        double climbArea = floorArea(PocketService.regionPlan(climb, c).toolpath(), floor);
        double convArea = floorArea(
                PocketService.regionPlan(climb.withDirection(MillingDirection.CONVENTIONAL), c)
                        .toolpath(),
                floor);
        TaskOutcome o = PocketService.run(
                climb.withDirection(MillingDirection.CONVENTIONAL), dir.resolve("r.ngc"), ProgressMonitor.NONE);
        assertEquals("conventional", o.summary().get("direction"));
        assertTrue(climbArea > 0 && convArea < 0, climbArea + " " + convArea);
    }

    @Test
    void theSevenMPostsKeepTheThesisDirection(@TempDir Path dir) throws Exception {
        PocketSettings s = settings("cavity01", "7m-compat");
        TaskOutcome a = PocketService.run(s, dir.resolve("a.nc"), ProgressMonitor.NONE);
        TaskOutcome b = PocketService.run(
                s.withDirection(MillingDirection.CONVENTIONAL), dir.resolve("b.nc"), ProgressMonitor.NONE);
        assertEquals("conventional", a.summary().get("direction"));
        assertEquals(Files.readString(dir.resolve("a.nc")), Files.readString(dir.resolve("b.nc")));
        assertEquals(0, b.exitStatus());
    }

    @Test
    void theCorrectedSevenMPostTakesTheMillingDirection(@TempDir Path dir) throws Exception {
        // 7m (the thesis's dialect with its defects corrected) climb-mills by default like
        // the G-code posts; conventional gives the thesis's clockwise passes
        PocketSettings climb = settings("examplepart", "7m");
        TaskOutcome a = PocketService.run(climb, dir.resolve("climb.nc"), ProgressMonitor.NONE);
        TaskOutcome b = PocketService.run(
                climb.withDirection(MillingDirection.CONVENTIONAL), dir.resolve("conv.nc"), ProgressMonitor.NONE);
        String ca = Files.readString(dir.resolve("climb.nc"));
        String cb = Files.readString(dir.resolve("conv.nc"));
        org.fresa.pocket.PocketPlan plan = PocketService.plan(climb);
        org.junit.jupiter.api.Assertions.assertAll(
                () -> assertEquals("climb", a.summary().get("direction")),
                () -> assertEquals("conventional", b.summary().get("direction")),
                // the example part's arcs are all convex: G02 conventional, G03 climb
                () -> assertTrue(cb.contains("G02") && !cb.contains("G03"), cb),
                () -> assertTrue(ca.contains("G03") && !ca.contains("G02"), ca),
                () -> assertEquals(
                        cb,
                        new org.fresa.pocket.compat.Sinumerik7MPost(
                                        org.fresa.pocket.compat.Sinumerik7MPost.Mode.CORRECTED)
                                .write(plan)),
                () -> assertEquals(ca.lines().count(), cb.lines().count()),
                // same start point of every pass: the rapid to the first pass is the same block
                () -> assertEquals(
                        ca.lines().filter(l -> l.startsWith("N40 ")).toList(),
                        cb.lines().filter(l -> l.startsWith("N40 ")).toList()),
                // a move shorter than a micrometre is left out of the program, which of them depends on the direction
                () -> assertEquals(
                        (double) a.summary().get("path_length_mm"),
                        (double) b.summary().get("path_length_mm"),
                        1e-3));
    }

    @Test
    void anUnknownDirectionIsBadUsage() {
        CamInputException e = assertThrows(CamInputException.class, () -> SettingRanges.Pocket.DIRECTION.check("down"));
        assertTrue(
                e.getMessage().contains("--direction") && e.getMessage().contains("climb, conventional"),
                e.getMessage());
    }

    @Test
    void aSavedConventionalJobRunsHeadless(@TempDir Path dir) throws Exception {
        Path contour = dir.resolve("cavity01.dad");
        Files.copy(Path.of("samples/pocket/cavity01.dad"), contour);
        PocketSettings s = settings("cavity01", "linuxcnc");
        Job job = Job.empty(JobTask.POCKET)
                .withPocket(new PocketSettings(
                        contour,
                        s.toolDiameterMm(),
                        s.cutFraction(),
                        s.finishFraction(),
                        s.zTopMm(),
                        s.zBottomMm(),
                        s.maxDepthPerPassMm(),
                        s.spindleRpm(),
                        s.feedMmPerMin(),
                        s.finishFeedMmPerMin(),
                        PocketPost.LINUXCNC,
                        MillingDirection.CONVENTIONAL,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT));
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        assertTrue(Files.readString(file).contains("direction=\"conventional\""));
        Job read = JobXml.read(file);
        assertEquals(job, read);
        Path out = dir.resolve("out");
        TaskOutcome o = JobRunner.run(read, new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals("conventional", o.summary().get("direction"));
        PocketService.run(
                s.withDirection(MillingDirection.CONVENTIONAL), dir.resolve("direct.ngc"), ProgressMonitor.NONE);
        assertEquals(Files.readString(dir.resolve("direct.ngc")), Files.readString(out.resolve("pocket.ngc")));
    }

    @Test
    void anUnknownPostIsBadUsage() {
        CamInputException e =
                assertThrows(CamInputException.class, () -> SettingRanges.Pocket.POST.check("heidenhain"));
        assertTrue(e.getMessage().contains("7m-compat, 7m, linuxcnc, iso, fanuc, 840d, apt"), e.getMessage());
    }

    static PocketSettings islandSettings(Path contour, String post) {
        return new PocketSettings(
                contour,
                6,
                0.7,
                0.1,
                0,
                -6,
                3,
                3000,
                300,
                100,
                SettingRanges.Pocket.POST.require(post),
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);
    }

    @Test
    @InterpreterCheck
    void aContourFileWithTwoIslandsIsMilledAroundThemAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("rooms.ngc");
        TaskOutcome o = PocketService.run(
                islandSettings(Path.of("samples/pocket/rooms-islands.contour"), "linuxcnc"), out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(2, o.summary().get("islands"));
        // the largest circle: in the middle room, 40 x 40 without an island
        assertEquals(40, (double) o.summary().get("max_hole_diameter"), 1e-3);
        assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        org.fresa.post.Rs274.Result r = org.fresa.post.Rs274.run(out, 6);
        assertEquals(0, r.exitStatus(), org.fresa.post.Rs274.log(r));
    }

    @Test
    void aDxfWithIslandsGivesTheSameProgramAsTheContourFile(@TempDir Path dir) throws Exception {
        List<org.fresa.geom.Contour> c = PocketService.readContours(Path.of("samples/pocket/rooms-islands.contour"));
        Path dxf = dir.resolve("rooms.dxf");
        // islands first in the drawing: the outer one is found by containment, not by order
        Files.writeString(dxf, org.fresa.dxf.DxfWriter.write(List.of(c.get(2), c.get(0), c.get(1)), "0"));
        List<org.fresa.geom.Contour> read = PocketService.readContours(dxf);
        assertEquals(3, read.size());
        assertEquals(c.get(0).area(), read.get(0).area(), 1e-6);
        TaskOutcome o = PocketService.run(islandSettings(dxf, "linuxcnc"), dir.resolve("d.ngc"), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(2, o.summary().get("islands"));
    }

    @Test
    void theSevenMPostsRefuseIslandsAndAnIslandOutsideIsBadInput(@TempDir Path dir) throws Exception {
        Path rooms = Path.of("samples/pocket/rooms-islands.contour");
        assertThrows(
                CamInputException.class,
                () -> PocketService.run(islandSettings(rooms, "7m-compat"), dir.resolve("a.nc"), ProgressMonitor.NONE));
        Path bad = dir.resolve("bad.contour");
        Files.writeString(
                bad,
                "contour\nmove 0 0\nline 10 0\nline 10 10\nline 0 10\nline 0 0\n"
                        + "contour\nmove 8 8\nline 20 8\nline 20 9\nline 8 9\nline 8 8\n");
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> PocketService.run(islandSettings(bad, "linuxcnc"), dir.resolve("b.nc"), ProgressMonitor.NONE));
        assertTrue(e.getMessage().contains("not inside"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("b.nc")));
    }
}
