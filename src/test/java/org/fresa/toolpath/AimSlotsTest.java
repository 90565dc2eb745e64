package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.geom.Tolerance;
import org.fresa.post.NcPosts;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.Feature.SlotEnd.EndType;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The slots of slots-profiles.stp and slots-general.stp written in AP238's integrated form
 * (aim-slots.stp, aim-slots-general.stp, their features and workingsteps as annex J.6 writes
 * them): the AIM binder gives the ARM binder's slots (ends, profiles, paths) and the planner the
 * same toolpath; an end or a profile parameter the binder does not read is refused, never read as
 * square.
 */
class AimSlotsTest {

    static final Path AIM = Path.of("src/test/resources/stepnc/aim-slots.stp");
    static final Path PARTS = Path.of("src/test/resources/stepnc");
    private static final Pattern NUMBER = Pattern.compile("-?\\d+\\.\\d+(E-?\\d+)?");

    /** A record's text with every decimal number to 1e-9 (degrees come through a conversion factor). */
    static String rounded(Object o) {
        Matcher m = NUMBER.matcher(String.valueOf(o));
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            double v = Math.round(Double.parseDouble(m.group()) * 1e9) / 1e9 + 0.0;
            m.appendReplacement(out, String.format(Locale.ROOT, "%.9f", v));
        }
        m.appendTail(out);
        return out.toString();
    }

    @ParameterizedTest
    @CsvSource({"aim-slots.stp, slots-profiles.stp, 6", "aim-slots-general.stp, slots-general.stp, 9"})
    void theAimSlotsAreTheArmsSlots(String aimPart, String armPart, int workingsteps) throws Exception {
        StepNcProgram aim = StepNcReader.read(PARTS.resolve(aimPart));
        StepNcProgram arm = StepNcReader.read(PARTS.resolve(armPart));
        assertEquals(
                arm.workingsteps().stream().map(MachiningWorkingstep::id).toList(),
                aim.workingsteps().stream().map(MachiningWorkingstep::id).toList());
        assertEquals(workingsteps, aim.workingsteps().size());
        for (int i = 0; i < arm.workingsteps().size(); i++) {
            Feature a = aim.workingsteps().get(i).feature();
            Feature r = arm.workingsteps().get(i).feature();
            String at = arm.workingsteps().get(i).id();
            assertEquals(Feature.FeatureType.SLOT, a.type(), at);
            assertEquals(r.id(), a.id(), at);
            assertTrue(r.placement().eq(a.placement(), Tolerance.DEFAULT), at);
            assertEquals(r.depthMm(), a.depthMm(), at);
            assertEquals(rounded(r.profile()), rounded(a.profile()), at);
            assertEquals(rounded(r.courseOfTravel()), rounded(a.courseOfTravel()), at);
            assertEquals(r.slotEnds(), a.slotEnds(), at);
        }
    }

    /** What the comparisons hold: every end kind, start then end, and each kind of path. */
    @Test
    void thePartsHoldEveryEndAndPath() throws Exception {
        StepNcProgram profiles = StepNcReader.read(AIM);
        assertEquals(
                List.of(
                        new Feature.SlotEnd(
                                EndType.FLAT, "FLAT_SLOT_END_TYPE", OptionalDouble.of(6), OptionalDouble.of(4)),
                        new Feature.SlotEnd(
                                EndType.RADIUSED,
                                "RADIUSED_SLOT_END_TYPE",
                                OptionalDouble.empty(),
                                OptionalDouble.empty())),
                profiles.workingsteps().get(5).feature().slotEnds());
        assertEquals(
                EndType.OPEN,
                profiles.workingsteps().get(0).feature().slotEnds().get(1).type());
        List<Feature> f = StepNcReader.read(PARTS.resolve("aim-slots-general.stp")).workingsteps().stream()
                .map(MachiningWorkingstep::feature)
                .toList();
        // a loop's one end condition stands for both ends of its closed course
        assertEquals(
                List.of(EndType.LOOP, EndType.LOOP),
                f.get(2).slotEnds().stream().map(Feature.SlotEnd::type).toList());
        assertEquals(EndType.WOODRUFF, f.get(4).slotEnds().get(1).type());
        assertEquals(OptionalDouble.of(15), f.get(4).slotEnds().get(1).firstRadiusMm());
        assertEquals("GENERAL_PATH", f.get(0).courseOfTravel().orElseThrow().entity());
        assertEquals(3, f.get(0).courseOfTravel().orElseThrow().curve().size());
        assertEquals(
                2 * Math.PI,
                f.get(2).courseOfTravel().orElseThrow().sweepAngle().getAsDouble());
        // the AIM's sweep angle in degrees, the model's in radians as the ARM writes it
        assertEquals(
                Math.toRadians(-100),
                f.get(6).courseOfTravel().orElseThrow().sweepAngle().getAsDouble(),
                1e-12);
    }

    /** As the J.6-against-FDIS comparison: the same workingsteps planned, point for point within 1e-6 mm. */
    @ParameterizedTest
    @CsvSource({"aim-slots.stp, slots-profiles.stp, 6", "aim-slots-general.stp, slots-general.stp, 9"})
    void theAimSlotsAreMachinedAsTheArmFilesSlots(String aimPart, String armPart, int workingsteps) throws Exception {
        ToolpathPlanner.Plan aim = ToolpathPlanner.plan(StepNcReader.read(PARTS.resolve(aimPart)), Tolerance.DEFAULT);
        ToolpathPlanner.Plan arm = ToolpathPlanner.plan(StepNcReader.read(PARTS.resolve(armPart)), Tolerance.DEFAULT);
        assertEquals(workingsteps, aim.planned(), aim.problems().toString());
        assertEquals(
                arm.steps().stream().map(ToolpathPlanner.PlannedStep::label).toList(),
                aim.steps().stream().map(ToolpathPlanner.PlannedStep::label).toList());
        // the same reports, but for the tool's kind: the AIM names no tapered end mill ('endmill')
        assertEquals(
                arm.problems().stream()
                        .map(x -> x.replace("TAPERED_ENDMILL", "ENDMILL"))
                        .toList(),
                aim.problems());
        List<ToolpathCsv.Row> a = ToolpathCsv.rows(aim.toolpath(), NcPosts.CHORD_TOLERANCE_MM);
        List<ToolpathCsv.Row> r = ToolpathCsv.rows(arm.toolpath(), NcPosts.CHORD_TOLERANCE_MM);
        assertEquals(r.size(), a.size());
        for (int i = 0; i < r.size(); i++) {
            ToolpathCsv.Row x = r.get(i);
            ToolpathCsv.Row y = a.get(i);
            assertEquals(x.workingstep() + " " + x.move(), y.workingstep() + " " + y.move(), "row " + i);
            assertTrue(x.point().distance(y.point()) <= 1e-6, "row " + i + ": " + x + " vs " + y);
            assertTrue(x.toolAxis().distance(y.toolAxis()) <= 1e-6, "row " + i);
            assertEquals(x.feedMmPerMin(), y.feedMmPerMin(), 1e-9, "row " + i);
        }
    }

    /** The part with one text replaced (it must be there), planned; the square-U slot's refusal. */
    private static String squareURefusal(String from, String to) throws Exception {
        String text = Files.readString(AIM);
        assertTrue(text.contains(from), from);
        StepNcProgram p = StepNcReader.read(new StringReader(text.replace(from, to)), "changed.stp");
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(5, plan.planned(), plan.problems().toString());
        MachiningWorkingstep ws = p.workingsteps().get(5);
        assertEquals("WS SQUARE U ENDS", ws.id());
        assertTrue(plan.sectionOf(ws.instanceId()).isEmpty());
        return plan.refusals().get(ws.instanceId());
    }

    @Test
    void anEndOfAKindTheBinderDoesNotKnowIsRefusedNotCutSquare() throws Exception {
        String why = squareURefusal("#62=SLOT_END('','flat'", "#62=SLOT_END('','rounded'");
        assertTrue(why.startsWith("slot end not read: #62 SLOT_END 'rounded'"), why);
    }

    @Test
    void aWoodruffEndWithAFlatEndsRadiiAndNoRadiusIsRefused() throws Exception {
        String why = squareURefusal("#62=SLOT_END('','flat'", "#62=SLOT_END('','woodruff'");
        assertTrue(why.contains("SLOT_END 'woodruff' with 'first radius', 'second radius', not read"), why);
    }

    @Test
    void aSlotRelatingTwoEndsAtItsStartAndNoneAtItsEndIsRefused() throws Exception {
        String why = squareURefusal(
                "FEATURE_COMPONENT_RELATIONSHIP('course of travel end','slot end usage',#55,#296)",
                "FEATURE_COMPONENT_RELATIONSHIP('course of travel start','slot end usage',#55,#296)");
        assertTrue(why.contains("two SLOT_ENDs related as 'course of travel start'"), why);
    }

    @Test
    void aProfileParameterTheArmDoesNotHaveIsRefused() throws Exception {
        String text = Files.readString(AIM);
        String from = "SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#229,#238,#239,#240,#241,#242,#243),#7)";
        assertTrue(text.contains(from));
        // ISO 10303-113's tee has offsets, ISO 14649-10's does not: where they put the stem is not read
        String changed = text.replace(from, from.replace("#243)", "#243,#9000)"))
                .replace(
                        "ENDSEC;\nEND-ISO-10303-21;",
                        "#9000=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                                + " MEASURE_WITH_UNIT(LENGTH_MEASURE(3.0),#1) REPRESENTATION_ITEM('first offset'));\n"
                                + "ENDSEC;\nEND-ISO-10303-21;");
        StepNcProgram p = StepNcReader.read(new StringReader(changed), "offset.stp");
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(4, plan.planned(), plan.problems().toString());
        for (int k : new int[] {3, 4}) {
            String why = plan.refusals().get(p.workingsteps().get(k).instanceId());
            assertTrue(why != null && why.contains("TEE_PROFILE with 'first offset', not read"), String.valueOf(why));
        }
    }
}
