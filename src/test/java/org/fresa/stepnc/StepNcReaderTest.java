package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class StepNcReaderTest {

    static final Path SAMPLES = Path.of("samples/stepnc");
    static final Path CORPUS = TestInputs.SHARED_CORPUS.resolve("stepnc");
    private static final Tolerance TOL = Tolerance.DEFAULT;

    static StepNcProgram read(String name) throws Exception {
        return StepNcReader.read(SAMPLES.resolve(name));
    }

    @Test
    void example2Has732InstancesAnd26WorkingstepsInWorkplanOrder() throws Exception {
        StepNcProgram p = read("example2.stp");
        assertEquals(732, p.instanceCount());
        assertEquals("3caras", p.projectId());
        assertEquals(StepNcProgram.Dialect.STEP_MODELER, p.dialect());
        List<Long> ids =
                p.workingsteps().stream().map(MachiningWorkingstep::instanceId).toList();
        assertEquals(
                List.of(
                        59L, 74L, 109L, 124L, 159L, 174L, 209L, 224L, 276L, 329L, 364L, 379L, 414L, 429L, 464L, 479L,
                        514L, 529L, 564L, 579L, 615L, 630L, 665L, 680L, 715L, 730L),
                ids);
    }

    @Test
    void example2Works24RoundHolesAnd2ClosedPocketsWithThreeToolDiameters() throws Exception {
        StepNcProgram p = read("example2.stp");
        Map<Feature.FeatureType, Long> byType = p.workingsteps().stream()
                .collect(Collectors.groupingBy(w -> w.feature().type(), TreeMap::new, Collectors.counting()));
        assertEquals(Map.of(Feature.FeatureType.ROUND_HOLE, 24L, Feature.FeatureType.CLOSED_POCKET, 2L), byType);
        Set<Double> diameters = p.workingsteps().stream()
                .map(w -> w.operation().tool().orElseThrow().diameterMm().orElseThrow())
                .collect(Collectors.toCollection(TreeSet::new));
        assertEquals(Set.of(10.0, 16.0, 20.0), diameters);
    }

    @Test
    void example2FeaturesLieOnThreeFacesWithAxesPlusZMinusYMinusX() throws Exception {
        StepNcProgram p = read("example2.stp");
        List<Vec3> axes = p.workingsteps().stream()
                .map(w -> w.feature().axis())
                .distinct()
                .toList();
        assertEquals(3, axes.size());
        assertTrue(axes.get(0).eq(Vec3.UNIT_Z, TOL));
        assertTrue(axes.get(1).eq(new Vec3(0, -1, 0), TOL));
        assertTrue(axes.get(2).eq(new Vec3(-1, 0, 0), TOL));
        for (MachiningWorkingstep w : p.workingsteps()) {
            assertEquals(10.0, w.feature().depthMm().orElseThrow(), 1e-12);
        }
    }

    @Test
    void example2FrontPocketIsA140By50RectangleAtItsCentre() throws Exception {
        MachiningWorkingstep w = read("example2.stp").workingsteps().get(9);
        assertEquals(329, w.instanceId());
        Feature f = w.feature();
        assertTrue(f.location().eq(new Vec3(100, 0, 55), TOL));
        Profile.Rectangular r = (Profile.Rectangular) f.profile().orElseThrow();
        assertEquals(50.0, r.widthMm());
        assertEquals(140.0, r.lengthMm());
        assertEquals(10.0, f.orthogonalRadiusMm().orElseThrow());
        Operation o = w.operation();
        assertEquals(Operation.OperationType.BOTTOM_AND_SIDE_ROUGH_MILLING, o.type());
        Strategy s = o.strategy().orElseThrow();
        assertEquals(Strategy.StrategyType.CONTOUR_PARALLEL, s.type());
        assertEquals(0.2, s.overlapFraction().orElseThrow(), 1e-12);
        assertEquals("length", s.overlapInterpretation().orElseThrow());
        assertEquals(1.6, o.axialCuttingDepthMm().orElseThrow());
        assertEquals(2884.683343540603, o.technology().spindleRpm().orElseThrow());
        assertEquals(
                ApproachRetract.Kind.PLUNGE_TOOLAXIS, o.approach().orElseThrow().kind());
    }

    @Test
    void example2Skips14WorkingstepsThatNoWorkplanReferences() throws Exception {
        StepNcProgram p = read("example2.stp");
        List<Long> skipped =
                p.skipped().stream().map(StepNcProgram.Skipped::instanceId).toList();
        assertEquals(
                List.of(48L, 98L, 148L, 198L, 261L, 314L, 353L, 403L, 453L, 503L, 553L, 604L, 654L, 704L), skipped);
        assertTrue(p.skipped().get(0).reason().contains("not referenced by any workplan"));
        assertEquals(
                Operation.OperationType.CENTER_DRILLING,
                p.skipped().get(0).workingstep().orElseThrow().operation().type());
    }

    @Test
    void example2NestsThreeWorkplansInTheMainOne() throws Exception {
        Workplan main = read("example2.stp").mainWorkplan().orElseThrow();
        assertEquals("Main workplan", main.id());
        assertEquals(
                List.of("workplan setup XY", "workplan setup XZ", "workplan setup ZY"),
                main.elements().stream().map(Executable::id).toList());
        Workplan xy = (Workplan) main.elements().get(0);
        Setup setup = xy.setup().orElseThrow();
        assertEquals(
                225.0, setup.securityPlane().orElseThrow().translationPart().z());
    }

    @Test
    void example1HasFiveWorkingstepsWithTheFilesStrategiesAndTools() throws Exception {
        StepNcProgram p = read("iso14649-11-example1.stp");
        assertEquals(StepNcProgram.Dialect.ISO_14649, p.dialect());
        List<String> features =
                p.workingsteps().stream().map(w -> w.feature().entity()).toList();
        assertEquals(List.of("PLANAR_FACE", "ROUND_HOLE", "ROUND_HOLE", "CLOSED_POCKET", "CLOSED_POCKET"), features);
        List<String> ops =
                p.workingsteps().stream().map(w -> w.operation().entity()).toList();
        assertEquals(
                List.of(
                        "PLANE_FINISH_MILLING",
                        "DRILLING",
                        "REAMING",
                        "BOTTOM_AND_SIDE_ROUGH_MILLING",
                        "BOTTOM_AND_SIDE_FINISH_MILLING"),
                ops);
        List<String> strategies = p.workingsteps().stream()
                .map(w -> w.operation().strategy().map(Strategy::entity).orElse("-"))
                .toList();
        assertEquals(
                List.of(
                        "BIDIRECTIONAL_MILLING",
                        "DRILLING_TYPE_STRATEGY",
                        "DRILLING_TYPE_STRATEGY",
                        "CONTOUR_PARALLEL",
                        "CONTOUR_PARALLEL"),
                strategies);
        List<String> tools = p.workingsteps().stream()
                .map(w -> w.operation().tool().orElseThrow().body())
                .toList();
        assertEquals(
                List.of("TAPERED_ENDMILL", "TWIST_DRILL", "TAPERED_REAMER", "TAPERED_ENDMILL", "TAPERED_ENDMILL"),
                tools);
        Tool drill = p.workingsteps().get(1).operation().tool().orElseThrow();
        assertEquals(20.0, drill.diameterMm().orElseThrow());
        assertEquals(2.0, drill.edgeRadiusMm().orElseThrow());
        assertEquals(45.0, drill.cuttingEdgeLengthMm().orElseThrow());
        assertEquals(90.0, drill.overallAssemblyLengthMm().orElseThrow());
        Technology face = p.workingsteps().get(0).operation().technology();
        assertEquals(2400.0, face.feedMmPerMin().orElseThrow(), 1e-9);
        assertEquals(720.0, face.spindleRpm().orElseThrow(), 1e-9);
        assertTrue(face.spindleClockwise());
        Feature hole = p.workingsteps().get(1).feature();
        assertEquals(22.0, hole.diameterMm().orElseThrow());
        assertEquals(30.0, hole.depthMm().orElseThrow());
        assertEquals("THROUGH_BOTTOM_CONDITION", hole.bottomCondition().orElseThrow());
        Feature pocket = p.workingsteps().get(3).feature();
        assertTrue(pocket.location().eq(new Vec3(70, 70, 0), TOL));
        assertTrue(pocket.placement().xAxis().eq(Vec3.UNIT_Y, TOL));
        Strategy bidir = p.workingsteps().get(0).operation().strategy().orElseThrow();
        assertEquals(0.05, bidir.overlapFraction().orElseThrow());
        assertTrue(bidir.feedDirection().orElseThrow().eq(Vec3.UNIT_Y, TOL));
        assertEquals(
                Feature.FeatureType.PLANAR_FACE,
                p.workingsteps().get(0).feature().type());
        assertEquals(
                120.0,
                p.workingsteps()
                        .get(0)
                        .feature()
                        .courseOfTravel()
                        .orElseThrow()
                        .distanceMm()
                        .orElseThrow());
    }

    /** The drilling strategy and the drilling attributes are bound, not discarded. */
    @Test
    void example1sDrillingStrategyAndReamingAttributesAreBound() throws Exception {
        StepNcProgram p = read("iso14649-11-example1.stp");
        DrillingStrategy d = p.workingsteps()
                .get(1)
                .operation()
                .strategy()
                .orElseThrow()
                .drilling()
                .orElseThrow();
        assertEquals(
                List.of(0.75, 0.5, 2.0, 0.5, 0.75, 8.0),
                List.of(
                        d.reducedCutAtStart().orElseThrow(),
                        d.reducedFeedAtStart().orElseThrow(),
                        d.depthOfStartMm().orElseThrow(),
                        d.reducedCutAtEnd().orElseThrow(),
                        d.reducedFeedAtEnd().orElseThrow(),
                        d.depthOfEndMm().orElseThrow()));
        assertEquals(
                DrillingStrategy.NONE,
                p.workingsteps()
                        .get(2)
                        .operation()
                        .strategy()
                        .orElseThrow()
                        .drilling()
                        .orElseThrow());
        DrillingParameters ream = p.workingsteps().get(2).operation().drilling().orElseThrow();
        assertEquals(java.util.Optional.of(true), ream.spindleStopAtBottom());
        assertTrue(ream.dwellTimeBottomS().isEmpty() && ream.feedOnRetract().isEmpty());
        DrillingParameters drill =
                p.workingsteps().get(1).operation().drilling().orElseThrow();
        assertEquals(DrillingParameters.NONE, drill);
        assertTrue(p.workingsteps().get(0).operation().drilling().isEmpty());
        assertTrue(p.workingsteps()
                .get(0)
                .operation()
                .strategy()
                .orElseThrow()
                .drilling()
                .isEmpty());
    }

    @Test
    @CorpusCheck
    void theFdisExample1IsReadWithItsDraftSpellingsReported() throws Exception {
        Path f = CORPUS.resolve("fdis/iso14649-11-fdis-example1.p21");
        Assumptions.assumeTrue(Files.exists(f), TestInputs.sharedCorpusAbsent(CORPUS));
        StepNcProgram p = StepNcReader.read(f);
        assertEquals(5, p.workingsteps().size());
        String seen = String.join("\n", p.spellings());
        assertTrue(seen.contains("BIDIRECTIONAL read as BIDIRECTIONAL_MILLING"), seen);
        assertTrue(seen.contains("TOOL_DIMENSION read as MILLING_TOOL_DIMENSION"), seen);
        assertTrue(seen.contains("ELEMENTARY_SURFACE read as PLANE"), seen);
        assertTrue(seen.contains("CUTTING_COMPONENT written with 4 attributes"), seen);
        assertTrue(seen.contains("percentage"), seen);
        // the draft writes DRILLING_TYPE_STRATEGY(75.000, 50.000, 2.000, 50.000, 75.000, 8.000)
        DrillingStrategy d = p.workingsteps()
                .get(1)
                .operation()
                .strategy()
                .orElseThrow()
                .drilling()
                .orElseThrow();
        assertEquals(0.5, d.reducedFeedAtStart().orElseThrow(), 1e-12);
        assertEquals(0.75, d.reducedFeedAtEnd().orElseThrow(), 1e-12);
        assertEquals(8.0, d.depthOfEndMm().orElseThrow(), 1e-12);
        Strategy bidir = p.workingsteps().get(0).operation().strategy().orElseThrow();
        assertEquals(Strategy.StrategyType.BIDIRECTIONAL, bidir.type());
        assertEquals("BIDIRECTIONAL", bidir.entity());
        assertEquals(0.05, bidir.overlapFraction().orElseThrow(), 1e-12);
        Profile.General outline =
                (Profile.General) p.workingsteps().get(3).feature().profile().orElseThrow();
        assertEquals(4, outline.segments().size());
        assertTrue(outline.closed());
        assertEquals(
                Strategy.StrategyType.CONTOUR_BIDIRECTIONAL,
                p.workingsteps().get(3).operation().strategy().orElseThrow().type());
        assertEquals(
                ApproachRetract.Kind.PLUNGE_RAMP,
                p.workingsteps().get(0).operation().approach().orElseThrow().kind());
    }

    @Test
    void theExplicitToolpathVariantIsReadFully() throws Exception {
        StepNcProgram p = read("iso14649-11-example1-explicit-toolpaths.stp");
        assertEquals(38, p.workingsteps().size());
        assertTrue(p.skipped().isEmpty());
        assertTrue(p.workingsteps().stream()
                .allMatch(w -> w.operation().type() == Operation.OperationType.FREEFORM_OPERATION));
        long rapids = p.mainWorkplan().orElseThrow().elements().stream()
                .filter(e -> e instanceof Executable.Other o && o.entity().equals("RAPID_MOVEMENT"))
                .count();
        assertEquals(6, rapids);
        assertTrue(p.unknownEntities().containsKey("TOOLPATH_LIST"));
    }

    static Stream<Path> corpusFiles() throws IOException {
        if (!Files.isDirectory(CORPUS)) {
            // one placeholder, so the test is reported skipped (JUnit refuses an empty source)
            return Stream.of(CORPUS);
        }
        try (Stream<Path> s = Files.walk(CORPUS)) {
            return s.filter(Files::isRegularFile).sorted().toList().stream();
        }
    }

    @ParameterizedTest
    @MethodSource("corpusFiles")
    @CorpusCheck
    void everyCorpusFileReadsWithoutError(Path file) throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isRegularFile(file), TestInputs.sharedCorpusAbsent(CORPUS));
        StepNcProgram p = StepNcReader.read(file);
        assertTrue(p.instanceCount() > 0);
        // ARM and AIM (AP238 integrated form) alike: every file of the corpus has workingsteps to run
        assertTrue(!p.workingsteps().isEmpty(), "no workingstep executed in " + file + ": " + p.skipped());
        assertEquals(p.workingsteps().isEmpty(), p.whyNothingToMachine().isPresent());
    }

    @Test
    @CorpusCheck
    void theCorpusIsThere() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(CORPUS), TestInputs.sharedCorpusAbsent(CORPUS));
        assertTrue(corpusFiles().count() >= 20);
    }

    private static final String HEAD = "ISO-10303-21;HEADER;FILE_DESCRIPTION((''),'2;1');"
            + "FILE_NAME('','',(''),(''),'','','');FILE_SCHEMA(('MACHINING_SCHEMA'));ENDSEC;\nDATA;\n";

    static StepNcProgram bind(String data) throws Exception {
        return StepNcReader.read(new StringReader(HEAD + data + "\nENDSEC;END-ISO-10303-21;"), "t.stp");
    }

    @Test
    void aWorkpieceBlockOfNoOrNegativeSizeIsReportedAndNotRead() throws Exception {
        Path part = Path.of("src/test/resources/stepnc/slots-profiles.stp");
        String text = Files.readString(part);
        String from = "#5= BLOCK('STOCK',#6,120.000,150.000,30.000);";
        assertTrue(text.contains(from));
        assertTrue(StepNcReader.read(part).workpieces().get(0).block().isPresent());
        for (String to : List.of(
                "#5= BLOCK('STOCK',#6,-120.000,150.000,30.000);", "#5= BLOCK('STOCK',#6,120.000,150.000,0.000);")) {
            StepNcProgram p = StepNcReader.read(new StringReader(text.replace(from, to)), "t.stp");
            assertTrue(p.workpieces().get(0).block().isEmpty(), to);
            assertTrue(
                    p.warnings().stream()
                            .anyMatch(w -> w.startsWith(
                                            "#5 BLOCK, the bounding geometry of workpiece 'BLOCK 120 X 150 X 30',")
                                    && w.endsWith("its lengths not all positive: not read, the stock is not known")),
                    p.warnings().toString());
        }
    }

    @Test
    void anUnknownEntityIsKeptAndCountedNotFatal() throws Exception {
        StepNcProgram p = bind("#1=PROJECT('p',#2,(),$,$,$);#2=WORKPLAN('w',(#3,#4),$,$,$);"
                + "#3=SELECTIVE('s',());#4=FANCY_WORKINGSTEP('x');");
        assertEquals(Map.of("FANCY_WORKINGSTEP", 1, "SELECTIVE", 1), p.unknownEntities());
        assertEquals(2, p.mainWorkplan().orElseThrow().elements().size());
        assertTrue(p.workingsteps().isEmpty());
    }

    @Test
    void aWorkplanThatContainsItselfIsRefusedWithItsLine() throws Exception {
        StepParseException e = org.junit.jupiter.api.Assertions.assertThrows(
                StepParseException.class,
                () -> bind("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#3),$,$,$);\n#3=WORKPLAN('v',(#2),$,$,$);"));
        assertTrue(e.getMessage().contains("contains itself"), e.getMessage());
        assertTrue(e.line().isPresent());
    }

    @Test
    void anAttributeOfTheWrongKindNamesTheInstanceAndLine() throws Exception {
        StepParseException e = org.junit.jupiter.api.Assertions.assertThrows(
                StepParseException.class,
                () -> bind("#1=PROJECT('p',#2,(),$,$,$);\n#2=WORKPLAN('w',(#3),$,$,$);\n"
                        + "#3=MACHINING_WORKINGSTEP('ws',$,#4,#4,$);\n#4=DIRECTION('',(0.,0.,1.));"));
        assertEquals(5, e.line().orElseThrow(), e.getMessage());
        assertEquals(3, e.instanceId().orElseThrow());
        assertTrue(e.getMessage().contains("manufacturing feature"), e.getMessage());
    }

    @Test
    void aCompositeCurveOfTrimmedLinesAndCirclesKeepsItsArcs() throws Exception {
        StepNcProgram p = bind("""
                #1=PROJECT('p',#2,(#3),$,$,$);
                #2=WORKPLAN('w',(#10),$,$,$);
                #3=WORKPIECE('wp',$,$,$,$,$,());
                #10=MACHINING_WORKINGSTEP('ws',$,#11,#20,$);
                #11=CLOSED_POCKET('pk',#3,(#20),#12,$,(),$,#13,$,$,#14);
                #12=AXIS2_PLACEMENT_3D('',#15,$,$);
                #15=CARTESIAN_POINT('',(10.,20.,0.));
                #13=PLANAR_POCKET_BOTTOM_CONDITION();
                #14=GENERAL_CLOSED_PROFILE($,#30);
                #30=COMPOSITE_CURVE('',(#31,#32),.F.);
                #31=COMPOSITE_CURVE_SEGMENT(.CONTINUOUS.,.T.,#41);
                #41=TRIMMED_CURVE('',#51,(#61),(#62),.T.,.CARTESIAN.);
                #51=LINE('',#61,#71);
                #71=VECTOR('',#72,1.);
                #72=DIRECTION('',(1.,0.,0.));
                #61=CARTESIAN_POINT('',(0.,0.,0.));
                #62=CARTESIAN_POINT('',(10.,0.,0.));
                #32=COMPOSITE_CURVE_SEGMENT(.CONTINUOUS.,.T.,#42);
                #42=TRIMMED_CURVE('',#52,(#62),(#61),.T.,.CARTESIAN.);
                #52=CIRCLE('',#53,5.);
                #53=AXIS2_PLACEMENT_3D('',#54,$,$);
                #54=CARTESIAN_POINT('',(5.,0.,0.));
                #20=BOTTOM_AND_SIDE_ROUGH_MILLING($,$,'op',$,$,$,$,$,$,$,$,$,$,$,$,$);""");
        Feature f = p.workingsteps().get(0).feature();
        assertTrue(f.location().eq(new Vec3(10, 20, 0), TOL));
        assertTrue(f.depthMm().isEmpty());
        Profile.General g = (Profile.General) f.profile().orElseThrow();
        assertEquals("COMPOSITE_CURVE", g.curveEntity());
        assertEquals(
                new Profile.Line(new Vec3(0, 0, 0), new Vec3(10, 0, 0)),
                g.segments().get(0));
        Profile.Arc arc = (Profile.Arc) g.segments().get(1);
        assertTrue(arc.center().eq(new Vec3(5, 0, 0), TOL));
        assertEquals(5.0, arc.radiusMm());
        assertTrue(arc.ccw());
        assertTrue(g.closed());
        assertTrue(p.workingsteps().get(0).operation().tool().isEmpty());
    }
}
