package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.cell.TablePlacing;
import org.fresa.geom.Vec2;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobSettings.RobotSettings;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.PocketPost;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class JobXmlTest {

    @TempDir
    Path dir;

    static Job fullJob(Path dir) {
        return Job.empty(JobTask.ROBOT)
                .withName("cell 1")
                .withStepnc(
                        new StepNcSettings(dir.resolve("parts/example2.stp"), org.fresa.post.MillingPost.SIEMENS_840D))
                .withRobot(new RobotSettings(
                        "irb140",
                        new Placement(450, 0, 350, 0, 0, 15),
                        new Placement(0, 10, 0, -90, 0, 0),
                        List.of("csv", "rapid")))
                .withPocket(new PocketSettings(
                        dir.resolve("cavity01.dad"),
                        6,
                        0.62,
                        0.13,
                        30,
                        27,
                        3,
                        3200,
                        290,
                        100,
                        PocketPost.SINUMERIK_7M,
                        org.fresa.pocket.MillingDirection.CONVENTIONAL,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT))
                .withCutting(new CuttingSettings(
                        dir.resolve("sheet.dxf"),
                        2,
                        org.fresa.cutting.CutProcess.LASER,
                        3,
                        1,
                        org.fresa.cutting.LeadShape.LINE,
                        0.001,
                        org.fresa.dxf.DrawingUnits.MM,
                        true,
                        org.fresa.post.CuttingPost.ISO,
                        org.fresa.cutting.KerfCompensation.CONTROLLER,
                        org.fresa.cutting.CutSense.CCW,
                        org.fresa.cutting.CutSense.CCW,
                        0.5,
                        false))
                .withGrading(new GradingSettings(
                        dir.resolve("sole.contour"),
                        40,
                        "36-44",
                        true,
                        org.fresa.grading.SizeSystem.PARIS,
                        OptionalDouble.of(6.67),
                        OptionalDouble.empty(),
                        Optional.of(Vec2.of(12.5, -3)),
                        0.015,
                        org.fresa.grading.ShrinkageMode.ADDITIVE));
    }

    @Test
    void writeThenReadGivesTheSameJob() throws Exception {
        Job job = fullJob(dir);
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        assertEquals(job, JobXml.read(file));
    }

    @Test
    void thePlannersCutOrderAndStartPointsRoundTrip() throws Exception {
        org.fresa.cutting.CutOrderOverride order = new org.fresa.cutting.CutOrderOverride(List.of(
                new org.fresa.cutting.CutOrderOverride.Cut("part 2 hole 1", Vec2.of(70, 15.125), Optional.empty()),
                new org.fresa.cutting.CutOrderOverride.Cut("part 2", Vec2.of(90, 12), Optional.of(Vec2.of(75, 31))),
                new org.fresa.cutting.CutOrderOverride.Cut(
                        "part 1", Vec2.of(-0.1, 1.0 / 3), Optional.of(Vec2.of(-1e-7, 9999.5)))));
        Job job = fullJob(dir).withCutting(fullJob(dir).cutting().orElseThrow().withCutOrder(order));
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        String xml = Files.readString(file);
        assertTrue(
                xml.contains("<cutOrder>")
                        && xml.contains("contour=\"part 2 hole 1\"")
                        && xml.contains("startXMm=\"75.0\""),
                xml);
        assertEquals(job, JobXml.read(file));
        assertEquals(order, JobXml.read(file).cutting().orElseThrow().cutOrder());
        // no override: no element, saved jobs stay as they were
        JobXml.write(fullJob(dir), file);
        assertTrue(!Files.readString(file).contains("cutOrder"));
    }

    @org.junit.jupiter.params.ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.CsvSource(delimiter = '|', textBlock = """
            xMm="20000" yMm="1"                           | xMm
            xMm="1" yMm="1" startXMm="1" startYMm="-1e5" | startYMm
            xMm="1" yMm="1" startXMm="1"                  | startXMm and startYMm
            xMm="NaN" yMm="1"                             | NaN
            xMm="1"                                       | yMm
            """)
    void aBadCutOrderEntryIsRefusedWithItsLine(String attributes, String named) throws Exception {
        Path file = dir.resolve("bad.xml");
        Files.writeString(
                file,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"cut\">\n"
                        + "<cutting drawing=\"a.dxf\">\n<cutOrder>\n<cut contour=\"part 1\" xMm=\"0\" yMm=\"0\"/>\n"
                        + "<cut contour=\"part 2\" " + attributes + "/>\n</cutOrder>\n</cutting>\n</job>\n");
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(file));
        assertEquals(6, e.line().orElse(0), e.getMessage());
        assertTrue(e.getMessage().contains(named), e.getMessage());
    }

    @Test
    void theSpindleAndToolLengthAreKept() throws Exception {
        Job job = Job.empty(JobTask.ROBOT)
                .withRobot(new RobotSettings(
                        "irb140",
                        Placement.ORIGIN,
                        Placement.ORIGIN,
                        List.of("csv"),
                        Optional.of(new Placement(0, 0, 150, 0, 0, 0)),
                        OptionalDouble.of(50)));
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        assertEquals(job, JobXml.read(file));
    }

    @Test
    void theThesissPathConventionsAreKeptAndAnUnknownOneIsRefusedWithItsLine() throws Exception {
        Job job = Job.empty(JobTask.ROBOT)
                .withStepnc(new StepNcSettings(dir.resolve("example2.stp"), org.fresa.post.MillingPost.LINUXCNC)
                        .withPaths(org.fresa.toolpath.PathConvention.THESIS));
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        assertTrue(Files.readString(file).contains("paths=\"thesis\""));
        assertEquals(job, JobXml.read(file));
        assertEquals(
                org.fresa.toolpath.PathConvention.THESIS,
                JobXml.read(file).stepnc().orElseThrow().choices().paths());
        // the default is not written: saved jobs stay as they were
        JobXml.write(
                Job.empty(JobTask.ROBOT)
                        .withStepnc(
                                new StepNcSettings(dir.resolve("example2.stp"), org.fresa.post.MillingPost.LINUXCNC)),
                file);
        assertTrue(!Files.readString(file).contains("paths="));
        Path bad = dir.resolve("bad.xml");
        Files.writeString(
                bad,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"toolpath\">\n"
                        + "<stepnc file=\"a.stp\" paths=\"nist\"/></job>\n");
        CamInputException e =
                org.junit.jupiter.api.Assertions.assertThrows(CamInputException.class, () -> JobXml.read(bad));
        assertTrue(e.getMessage().contains("nist") && e.getMessage().contains("line 3"), e.getMessage());
    }

    @Test
    void thePlacementSearchIsKept() throws Exception {
        Job job = Job.empty(JobTask.ROBOT)
                .withRobot(new RobotSettings(
                        "tricept806",
                        Placement.ORIGIN,
                        new Placement(0, 10, 0, 0, 0, 0),
                        List.of("csv"),
                        Optional.empty(),
                        OptionalDouble.empty(),
                        TablePlacing.AUTO));
        Path file = dir.resolve("job.xml");
        JobXml.write(job, file);
        assertTrue(Files.readString(file).contains("place=\"auto\""));
        assertEquals(job, JobXml.read(file));
    }

    @Test
    void aToolLengthOutOfRangeIsRefused() throws Exception {
        Path file = dir.resolve("bad.xml");
        Files.writeString(
                file,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"robot\">"
                        + "<robot robot=\"irb140\" toolLengthMm=\"-5\"/></job>\n");
        org.junit.jupiter.api.Assertions.assertThrows(org.fresa.model.CamInputException.class, () -> JobXml.read(file));
    }

    @Test
    void aPocketWithoutDirectionIsClimbMilled() throws Exception {
        Path file = dir.resolve("old.xml");
        Files.writeString(
                file,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\">"
                        + "<pocket contour=\"c.dad\" toolDiameterMm=\"6\"/></job>\n");
        assertEquals(
                org.fresa.pocket.MillingDirection.CLIMB,
                JobXml.read(file).pocket().orElseThrow().direction());
    }

    @Test
    void aPocketWithOnlyItsContourAndToolReadsAsThePocketDefaults() throws Exception {
        Path file = dir.resolve("least.xml");
        Files.writeString(
                file,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\">"
                        + "<pocket contour=\"c.dad\" toolDiameterMm=\"6\"/></job>\n");
        PocketSettings d = PocketSettings.DEFAULTS;
        assertEquals(
                new PocketSettings(
                        dir.resolve("c.dad"),
                        6,
                        d.cutFraction(),
                        d.finishFraction(),
                        d.zTopMm(),
                        d.zBottomMm(),
                        d.maxDepthPerPassMm(),
                        d.spindleRpm(),
                        d.feedMmPerMin(),
                        d.finishFeedMmPerMin(),
                        d.post(),
                        d.direction(),
                        d.entry(),
                        d.entryAngleDeg(),
                        d.centreCutting(),
                        Optional.empty(),
                        PocketStrategy.DEFAULT),
                JobXml.read(file).pocket().orElseThrow());
    }

    @Test
    void pathsAreStoredRelativeToTheJobFile() throws Exception {
        Path file = dir.resolve("job.xml");
        JobXml.write(fullJob(dir), file);
        String xml = Files.readString(file);
        assertAll(
                () -> assertTrue(xml.contains("file=\"parts/example2.stp\""), xml),
                () -> assertFalse(xml.contains(dir.toString()), xml));
    }

    @Test
    void externalEntitiesAreRefused() throws Exception {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "top secret");
        Path file = dir.resolve("xxe.xml");
        Files.writeString(file, """
                <?xml version="1.0"?>
                <!DOCTYPE job [ <!ENTITY x SYSTEM "%s"> ]>
                <job xmlns="urn:fresa:job:1" version="1" task="pocket"><name>&x;</name></job>
                """.formatted(secret.toUri()));
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(file));
        assertAll(
                () -> assertTrue(e.getMessage().contains("DOCTYPE is not allowed"), e.getMessage()),
                () -> assertFalse(e.getMessage().contains("top secret")));
    }

    @Test
    void schemaViolationsNameLineAndColumn() throws Exception {
        Path file = dir.resolve("bad.xml");
        Files.writeString(file, """
                <?xml version="1.0"?>
                <job xmlns="urn:fresa:job:1" version="1" task="pocket">
                  <pocket contour="a.dad" toolDiameterMm="-6"/>
                </job>
                """);
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(file));
        assertEquals(3, e.line().orElse(0), e.getMessage());
        assertTrue(e.getMessage().contains("-6"), e.getMessage());
    }

    @Test
    void anUnknownTaskIsRefused() throws Exception {
        Path file = dir.resolve("task.xml");
        Files.writeString(file, "<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"weld\"/>");
        assertThrows(CamInputException.class, () -> JobXml.read(file));
    }

    @Test
    void aMissingFileIsBadInput() {
        CamInputException e = assertThrows(CamInputException.class, () -> JobXml.read(dir.resolve("none.xml")));
        assertTrue(e.getMessage().contains("none.xml"));
    }
}
