package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * AP238 in its integrated form (AIM), read from hand-made files: the same model as the ARM, every
 * value converted from its own unit.
 */
class Ap238AimBinderTest {

    static final Path INCH = Path.of("src/test/resources/stepnc/aim-inch-hole-and-pocket.stp");
    private static final double EPS = 1e-9;

    static StepNcProgram inMillimetres() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#1=(CONVERSION_BASED_UNIT('INCH',#3) LENGTH_UNIT() NAMED_UNIT(#4));",
                        "#1=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));");
        return StepNcReader.read(new StringReader(text), "mm.stp");
    }

    private static void near(Vec3 expected, Vec3 actual) {
        assertTrue(expected.distance(actual) <= EPS, "expected " + expected + ", found " + actual);
    }

    @Test
    void theWorkplanRunsItsWorkingstepsInSequencePositionOrder() throws Exception {
        StepNcProgram p = StepNcReader.read(INCH);
        assertTrue(p.integratedForm());
        assertEquals("AIM", p.form());
        assertEquals("INCH PART", p.projectId());
        assertEquals(
                List.of("WS DRILL HOLE1", "WS ROUGH POCKET1"),
                p.workingsteps().stream().map(MachiningWorkingstep::id).toList());
        assertTrue(p.skipped().isEmpty(), p.skipped().toString());
        assertEquals("MAIN WORKPLAN", p.mainWorkplan().orElseThrow().id());
        assertEquals("SETUP1", p.workingsteps().get(0).setup().orElseThrow().id());
        assertEquals(
                List.of("PLATE"), p.workpieces().stream().map(Workpiece::id).toList());
        // the project is a MACHINING_PROJECT, the workingsteps are in the main workplan's sequence
        assertFalse(
                p.warnings().stream().anyMatch(w -> w.contains("PROJECT")),
                p.warnings().toString());
    }

    @Test
    void anSiPrefixScalesTheFilesLengths() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#1=(CONVERSION_BASED_UNIT('INCH',#3) LENGTH_UNIT() NAMED_UNIT(#4));",
                        "#1=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.CENTI.,.METRE.));");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "cm.stp");
        near(new Vec3(10, 20, 0), p.workingsteps().get(0).feature().location());
        assertEquals(5, p.workingsteps().get(0).feature().depthMm().getAsDouble(), EPS);
        // 5 cm/minute
        assertEquals(
                50,
                p.workingsteps().get(0).operation().technology().feedMmPerMin().getAsDouble(),
                1e-9);
    }

    @Test
    void inchLengthsAndInchPerMinuteFeedsComeOutInMillimetres() throws Exception {
        StepNcProgram p = StepNcReader.read(INCH);
        MachiningWorkingstep drill = p.workingsteps().get(0);
        Feature hole = drill.feature();
        assertEquals(Feature.FeatureType.ROUND_HOLE, hole.type());
        assertEquals("HOLE1", hole.id());
        near(new Vec3(25.4, 50.8, 0), hole.location());
        assertEquals(12.7, hole.depthMm().getAsDouble(), EPS);
        assertEquals(6.35, hole.diameterMm().getAsDouble(), EPS);
        assertEquals("FLAT_HOLE_BOTTOM", hole.bottomCondition().orElseThrow());
        near(new Vec3(0, 0, 25.4), drill.securityPlane().orElseThrow().translationPart());
        Operation op = drill.operation();
        assertEquals(Operation.OperationType.DRILLING, op.type());
        assertEquals(10.16, op.retractPlaneMm().getAsDouble(), EPS);
        assertEquals(6.35, op.tool().orElseThrow().diameterMm().getAsDouble(), EPS);
        assertEquals(118, op.tool().orElseThrow().topAngle().getAsDouble(), 1e-6);
        // 5 inch/minute = 127 mm/min; 1200 revolutions/minute
        assertEquals(127, op.technology().feedMmPerMin().getAsDouble(), 1e-9);
        assertEquals("inch/minute", op.technology().feedrateUnit());
        assertEquals(1200, op.technology().spindleRpm().getAsDouble(), 1e-9);

        MachiningWorkingstep rough = p.workingsteps().get(1);
        Feature pocket = rough.feature();
        assertEquals(Feature.FeatureType.CLOSED_POCKET, pocket.type());
        near(new Vec3(76.2, 25.4, 0), pocket.location());
        assertEquals(12.7, pocket.depthMm().getAsDouble(), EPS);
        assertEquals(7.62, pocket.orthogonalRadiusMm().getAsDouble(), EPS);
        Profile.General g = (Profile.General) pocket.profile().orElseThrow();
        assertTrue(g.closed());
        assertEquals(4, g.segments().size());
        near(new Vec3(-25.4, -19.05, 0), g.segments().get(0).start());
        near(new Vec3(25.4, -19.05, 0), g.segments().get(0).end());
        Operation mill = rough.operation();
        assertEquals(Operation.OperationType.BOTTOM_AND_SIDE_ROUGH_MILLING, mill.type());
        assertEquals(6.35, mill.axialCuttingDepthMm().getAsDouble(), EPS);
        assertEquals(
                Strategy.StrategyType.CONTOUR_PARALLEL,
                mill.strategy().orElseThrow().type());
        assertEquals("CW", mill.strategy().orElseThrow().rotationDirection().orElseThrow());
        assertEquals(
                ApproachRetract.Kind.PLUNGE_RAMP, mill.approach().orElseThrow().kind());
        assertEquals(10, mill.approach().orElseThrow().angle().getAsDouble(), 1e-9);
        assertEquals(12.7, mill.tool().orElseThrow().diameterMm().getAsDouble(), EPS);
        assertEquals(4, mill.tool().orElseThrow().teeth().getAsInt());
        assertTrue(
                p.spellings().stream().anyMatch(s -> s.contains("lengths in INCH (25.4 mm), converted to mm")),
                p.spellings().toString());
    }

    @Test
    void theSameFileInMillimetresKeepsItsNumbers() throws Exception {
        StepNcProgram p = inMillimetres();
        Feature hole = p.workingsteps().get(0).feature();
        near(new Vec3(1, 2, 0), hole.location());
        assertEquals(0.5, hole.depthMm().getAsDouble(), EPS);
        assertEquals(0.25, hole.diameterMm().getAsDouble(), EPS);
        // 5 mm/minute: kept, and reported as too slow to cut
        assertEquals(
                5,
                p.workingsteps().get(0).operation().technology().feedMmPerMin().getAsDouble(),
                1e-9);
        assertTrue(
                p.warnings().stream().anyMatch(w -> w.contains("too slow to cut")),
                p.warnings().toString());
        assertFalse(
                p.spellings().stream().anyMatch(s -> s.startsWith("lengths in")),
                p.spellings().toString());
    }

    @Test
    void aWorkingstepOutsideEverySequenceIsNamedWithThatReason() throws Exception {
        String text =
                Files.readString(INCH).replace("#304=MACHINING_PROCESS_SEQUENCE_RELATIONSHIP('','',#300,#400,1.);", "");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "t.stp");
        assertEquals(1, p.workingsteps().size());
        assertEquals(1, p.skipped().size());
        assertEquals("WS DRILL HOLE1", p.skipped().get(0).id());
        assertTrue(
                p.skipped().get(0).reason().contains("in no workplan's sequence"),
                p.skipped().get(0).reason());
    }

    @Test
    void anOperationTheBindingDoesNotKnowIsKeptWithItsNameForThePlannerToRefuse() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "#420=DRILLING_OPERATION('DRILL HOLE1','drilling','','');",
                        "#420=FACING_TURNING_OPERATION('FACE','roughing','','');");
        StepNcProgram p = StepNcReader.read(new StringReader(text), "t.stp");
        Operation op = p.workingsteps().get(0).operation();
        assertEquals(Operation.OperationType.OTHER, op.type());
        assertTrue(op.entity().startsWith("FACING_TURNING_OPERATION"), op.entity());
    }

    @Test
    void explicitToolpathsAreReadInSequenceWithTheirArcsTraversedAsTheFileSays() throws Exception {
        StepNcProgram p = StepNcReader.read(Path.of("src/test/resources/stepnc/aim-cc1-toolpaths.stp"));
        MachiningWorkingstep ws = p.workingsteps().get(0);
        assertEquals("TOOLPATH_FEATURE", ws.feature().entity());
        Operation op = ws.operation();
        assertEquals(Operation.OperationType.FREEFORM_OPERATION, op.type());
        assertEquals(
                List.of("TP 1", "TP 2", "TP 3"),
                op.toolpaths().stream().map(ExplicitToolpath::id).toList());
        assertEquals(
                List.of(true, false, true),
                op.toolpaths().stream().map(ExplicitToolpath::rapid).toList());
        assertEquals(300, op.technology().feedMmPerMin().getAsDouble(), 1e-9);
        assertEquals(1200, op.technology().spindleRpm().getAsDouble(), 1e-9);
        List<Profile.Segment> cut = op.toolpaths().get(1).curve();
        assertEquals(5, cut.size());
        // sense_agreement .T.: along the circle (counter-clockwise); .F.: against it (clockwise)
        Profile.Arc ccw = (Profile.Arc) cut.get(2);
        near(new Vec3(30, 0, -1), ccw.start());
        near(new Vec3(40, 10, -1), ccw.end());
        assertTrue(ccw.ccw());
        Profile.Arc cw = (Profile.Arc) cut.get(3);
        near(new Vec3(40, 10, -1), cw.start());
        near(new Vec3(50, 20, -1), cw.end());
        near(new Vec3(50, 10, -1), cw.center());
        assertFalse(cw.ccw());
        // a segment whose same_sense is .F. is traversed from its curve's end
        near(new Vec3(50, 20, -1), cut.get(4).start());
        near(new Vec3(60, 20, -1), cut.get(4).end());
    }

    // ---- the workpiece's bounding block ----

    static final Path SLOTS = Path.of("src/test/resources/stepnc/aim-slots.stp");

    /** aim-slots.stp with each text replaced (each must be there), read. */
    private static StepNcProgram slotsWith(String... fromTo) throws Exception {
        String text = Files.readString(SLOTS);
        for (int k = 0; k < fromTo.length; k += 2) {
            assertTrue(text.contains(fromTo[k]), fromTo[k]);
            text = text.replace(fromTo[k], fromTo[k + 1]);
        }
        return StepNcReader.read(new StringReader(text), "changed.stp");
    }

    private static Optional<Workpiece.Block> block(StepNcProgram p) {
        assertEquals(1, p.workpieces().size());
        return p.workpieces().get(0).block();
    }

    /** The one warning about the workpiece's bounding geometry. */
    private static String blockWarning(StepNcProgram p) {
        List<String> w = p.warnings().stream()
                .filter(x -> x.startsWith("workpiece #28 'BLOCK 120 X 150 X 30'"))
                .toList();
        assertEquals(1, w.size(), p.warnings().toString());
        return w.get(0);
    }

    @Test
    void theBlockPlacedAtItsCentreIsTheArmsBlockFromItsCorner() throws Exception {
        StepNcProgram aim = StepNcReader.read(SLOTS);
        Workpiece.Block a = block(aim).orElseThrow();
        Workpiece.Block r = block(StepNcReader.read(Path.of("src/test/resources/stepnc/slots-profiles.stp")))
                .orElseThrow();
        // the ARM's BLOCK 'STOCK': its corner at (0, 0, -30), 120 x 150 x 30; the AIM's orientation at (60, 75, -30)
        assertTrue(
                r.placement().eq(a.placement(), Tolerance.DEFAULT),
                a.placement().toString());
        near(new Vec3(0, 0, -30), a.placement().translationPart());
        assertEquals(120, a.xMm(), EPS);
        assertEquals(150, a.yMm(), EPS);
        assertEquals(30, a.zMm(), EPS);
        assertEquals(List.of(r.xMm(), r.yMm(), r.zMm()), List.of(a.xMm(), a.yMm(), a.zMm()));
        assertTrue(
                aim.spellings().stream().anyMatch(x -> x.contains("BLOCK_SHAPE_REPRESENTATION placed at the centre")),
                aim.spellings().toString());
        assertFalse(
                aim.warnings().stream().anyMatch(x -> x.contains("workpiece #")),
                aim.warnings().toString());
    }

    @Test
    void anInchBlockComesOutInMillimetres() throws Exception {
        // the plate 5 x 3 x 1 inch, its orientation at (2.5, 1.5, -1) inch
        Workpiece.Block b = block(StepNcReader.read(INCH)).orElseThrow();
        near(new Vec3(0, 0, -25.4), b.placement().translationPart());
        assertEquals(127, b.xMm(), EPS);
        assertEquals(76.2, b.yMm(), EPS);
        assertEquals(25.4, b.zMm(), EPS);
        // the same numbers in millimetres are millimetres
        Workpiece.Block mm = block(inMillimetres()).orElseThrow();
        near(new Vec3(0, 0, -1), mm.placement().translationPart());
        assertEquals(List.of(5.0, 3.0, 1.0), List.of(mm.xMm(), mm.yMm(), mm.zMm()));
    }

    @Test
    void aTurnedBlocksCornerIsHalfItsWidthAndHeightBackAlongItsOwnAxes() throws Exception {
        // the orientation's x axis along +y: the width runs along y, the height along -x
        Workpiece.Block b = block(slotsWith(
                        "#473=AXIS2_PLACEMENT_3D('orientation',#474,#18,#19);",
                        "#473=AXIS2_PLACEMENT_3D('orientation',#474,#18,#9001);\n" + "#9001=DIRECTION('',(0.,1.,0.));"))
                .orElseThrow();
        assertTrue(
                b.placement()
                        .eq(
                                Transform3.ofFrame(new Vec3(135, 15, -30), new Vec3(0, 0, 1), new Vec3(0, 1, 0)),
                                Tolerance.DEFAULT),
                b.placement().toString());
        assertEquals(List.of(120.0, 150.0, 30.0), List.of(b.xMm(), b.yMm(), b.zMm()));
    }

    @Test
    void aBlockWithoutItsLengthIsReportedAndNotRead() throws Exception {
        StepNcProgram p = slotsWith(
                "BLOCK_SHAPE_REPRESENTATION($,(#473,#475,#476,#477),$)",
                "BLOCK_SHAPE_REPRESENTATION($,(#473,#476,#477),$)");
        assertTrue(block(p).isEmpty());
        String w = blockWarning(p);
        assertTrue(
                w.contains("its bounding geometry #472 BLOCK_SHAPE_REPRESENTATION has no 'length'")
                        && w.endsWith("not read, the stock is not known"),
                w);
    }

    @Test
    void aBlockOfNoWidthOrOfANegativeHeightIsReportedAndNotRead() throws Exception {
        StepNcProgram p = slotsWith(
                "LENGTH_MEASURE(120.0),#1) REPRESENTATION_ITEM('width')",
                "LENGTH_MEASURE(0.0),#1) REPRESENTATION_ITEM('width')",
                "LENGTH_MEASURE(150.0),#1) REPRESENTATION_ITEM('height')",
                "LENGTH_MEASURE(-150.0),#1) REPRESENTATION_ITEM('height')");
        assertTrue(block(p).isEmpty());
        String w = blockWarning(p);
        assertTrue(w.contains("its 'width' is 0 mm, not positive; its 'height' is -150 mm, not positive"), w);
    }

    @Test
    void aBlockWhoseSizeIsNotALengthOrWithAnItemOfItsOwnIsReportedAndNotRead() throws Exception {
        StepNcProgram degrees = slotsWith(
                "LENGTH_MEASURE(120.0),#1) REPRESENTATION_ITEM('width')",
                "LENGTH_MEASURE(120.0),#5) REPRESENTATION_ITEM('width')");
        assertTrue(block(degrees).isEmpty());
        assertTrue(blockWarning(degrees).contains("its 'width' #476 is not in a length unit"), blockWarning(degrees));
        StepNcProgram fifth = slotsWith(
                "BLOCK_SHAPE_REPRESENTATION($,(#473,#475,#476,#477),$)",
                "BLOCK_SHAPE_REPRESENTATION($,(#473,#475,#476,#477,#31),$)");
        assertTrue(block(fifth).isEmpty());
        assertTrue(blockWarning(fifth).contains("an item #31"), blockWarning(fifth));
    }

    @Test
    void aBoundingGeometryOfAnotherKindIsReportedAndNotRead() throws Exception {
        StepNcProgram p = slotsWith(
                "#472=BLOCK_SHAPE_REPRESENTATION($,(#473,#475,#476,#477),$)",
                "#472=CYLINDRICAL_SHAPE_REPRESENTATION($,(#473,#475,#476),$)");
        assertTrue(block(p).isEmpty());
        String w = blockWarning(p);
        assertTrue(w.contains("its bounding geometry #472 is a CYLINDRICAL_SHAPE_REPRESENTATION, not a"), w);
        // two bounding geometries: neither is read
        StepNcProgram two = slotsWith(
                "#471=SHAPE_DEFINITION_REPRESENTATION(#470,#472);",
                "#471=SHAPE_DEFINITION_REPRESENTATION(#470,#472);\n"
                        + "#9000=SHAPE_DEFINITION_REPRESENTATION(#470,#9001);\n"
                        + "#9001=SHAPE_REPRESENTATION('',(#473),#7);");
        assertTrue(block(two).isEmpty());
        assertTrue(blockWarning(two).contains("has several bounding geometries"), blockWarning(two));
    }

    @Test
    void aRawpiecesBlockIsNotTheWorkpiecesStock() throws Exception {
        // as annex J.6: the workpiece made from a rawpiece 'STOCK', which is made from the block
        StepNcProgram p = slotsWith(
                "#468=MAKE_FROM_USAGE_OPTION('','','',#28,#469,0,'',$);",
                "#468=MAKE_FROM_USAGE_OPTION('','','',#9000,#469,0,'',$);\n"
                        + "#9000=PRODUCT_DEFINITION('STOCK','',$,#25);\n"
                        + "#9001=MAKE_FROM_USAGE_OPTION('','','',#28,#9000,0,'',$);");
        assertTrue(block(p).isEmpty());
        String w = blockWarning(p);
        assertTrue(
                w.contains("#9000 'STOCK' (its rawpiece), has a block of its own (#472 BLOCK_SHAPE_REPRESENTATION):"
                        + " not taken as this workpiece's stock"),
                w);
    }

    @Test
    @CorpusCheck
    void annexJ6sRawpieceBlockIsNotItsWorkpiecesStock() throws Exception {
        Path j6 = TestInputs.SHARED_CORPUS.resolve("stepnc/ap238/annexJ6-cc3-iso14649-11-example1-aim.stp");
        Assumptions.assumeTrue(Files.isRegularFile(j6), TestInputs.sharedCorpusAbsent(j6.getParent()));
        StepNcProgram p = StepNcReader.read(j6);
        assertEquals(
                List.of("SIMPLE WORKPIECE"),
                p.workpieces().stream().map(Workpiece::id).toList());
        assertTrue(p.workpieces().get(0).block().isEmpty());
        assertTrue(
                p.warnings().stream()
                        .anyMatch(x -> x.startsWith("workpiece #400 'SIMPLE WORKPIECE': the workpiece it is made from,"
                                + " #300 'STOCK' (its rawpiece), has a block of its own (#305")),
                p.warnings().toString());
    }
}
