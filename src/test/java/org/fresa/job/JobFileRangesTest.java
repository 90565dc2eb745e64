package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges;
import org.fresa.setting.SettingRanges.Cutting;
import org.fresa.setting.SettingRanges.Grading;
import org.fresa.setting.SettingRanges.Pocket;
import org.fresa.setting.SettingRanges.Sole;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.api.io.TempDir;

/**
 * A job file cannot bring a value the command-line option refuses: every numeric
 * attribute of the sample jobs, given values a typo or a script produces, is either refused by
 * the reader with the file, line and range, or read as a value inside the option's range.
 */
class JobFileRangesTest {

    static final List<String> VALUES = List.of(
            "0",
            "-1",
            "1e-9",
            "0.5",
            "7",
            "1000",
            "100001",
            "1e300",
            "-1e300",
            "1e308",
            "NaN",
            "INF",
            "2147483647",
            "-2147483648");

    @TempDir
    Path dir;

    /** One attribute: the sample job, the element it is on, its name, its range and how to read it back. */
    record Attribute(String job, String element, SettingRange range, java.util.function.ToDoubleFunction<Job> value) {}

    static List<Attribute> attributes() {
        List<Attribute> a = new ArrayList<>();
        String pocket = "pocket-cavity01.xml";
        a.add(new Attribute(
                pocket, "pocket", Pocket.TOOL_DIAMETER, j -> j.pocket().get().toolDiameterMm()));
        a.add(new Attribute(pocket, "pocket", Pocket.CUT, j -> j.pocket().get().cutFraction()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.FINISH, j -> j.pocket().get().finishFraction()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.Z_TOP, j -> j.pocket().get().zTopMm()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.Z_BOTTOM, j -> j.pocket().get().zBottomMm()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.MAX_DEPTH, j -> j.pocket().get().maxDepthPerPassMm()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.SPINDLE, j -> j.pocket().get().spindleRpm()));
        a.add(new Attribute(pocket, "pocket", Pocket.FEED, j -> j.pocket().get().feedMmPerMin()));
        a.add(new Attribute(
                pocket, "pocket", Pocket.FINISH_FEED, j -> j.pocket().get().finishFeedMmPerMin()));
        String cut = "cut-plate.xml";
        a.add(new Attribute(cut, "cutting", Cutting.KERF, j -> j.cutting().get().kerfMm()));
        a.add(new Attribute(
                cut, "cutting", Cutting.LEAD_IN, j -> j.cutting().get().leadInMm()));
        a.add(new Attribute(
                cut, "cutting", Cutting.LEAD_OUT, j -> j.cutting().get().leadOutMm()));
        a.add(new Attribute(
                cut, "cutting", Cutting.TOLERANCE, j -> j.cutting().get().toleranceMm()));
        a.add(new Attribute(
                cut, "cutting", Cutting.OVERCUT, j -> j.cutting().get().overcutMm()));
        String grade = "grade-sole40.xml";
        a.add(new Attribute(
                grade, "grading", Grading.BASE_SIZE, j -> j.grading().get().baseSize()));
        a.add(new Attribute(
                grade,
                "grading",
                Grading.LENGTH_STEP,
                j -> j.grading().get().lengthStepMm().getAsDouble()));
        a.add(new Attribute(
                grade,
                "grading",
                Grading.WIDTH_STEP,
                j -> j.grading().get().widthStepMm().getAsDouble()));
        a.add(new Attribute(
                grade, "grading", Grading.SHRINKAGE, j -> j.grading().get().shrinkage()));
        String robot = "example2-irb140.xml";
        a.add(new Attribute(
                robot,
                "stepnc",
                SettingRanges.StepNc.BREAKTHROUGH,
                j -> j.stepnc().get().breakthroughMm()));
        for (int i = 0; i < 6; i++) {
            int k = i;
            a.add(new Attribute(
                    robot,
                    "robotTable",
                    SettingRanges.Robot.placement("", i),
                    j -> placement(j.robot().get().robotTable(), k)));
            a.add(new Attribute(
                    robot,
                    "tablePiece",
                    SettingRanges.Robot.placement("", i),
                    j -> placement(j.robot().get().tablePiece(), k)));
        }
        String sole = "sole-men40.xml";
        a.add(new Attribute(sole, "sole", Sole.BASE_SIZE, j -> j.sole().get().baseSize()));
        a.add(new Attribute(sole, "sole", Sole.SHRINKAGE, j -> j.sole().get().shrinkage()));
        a.add(new Attribute(sole, "sole", Sole.CAVITY_DEPTH, j -> j.sole().get().cavityDepthMm()));
        a.add(new Attribute(sole, "sole", Sole.TREAD_DEPTH, j -> j.sole().get().treadDepthMm()));
        a.add(new Attribute(sole, "sole", Sole.CLEARANCE, j -> j.sole().get().clearanceMm()));
        a.add(new Attribute(sole, "sole", Sole.MARGIN, j -> j.sole().get().marginMm()));
        a.add(new Attribute(
                sole,
                "tool",
                Sole.TOOL_NUMBER,
                j -> j.sole().get().tools().get(0).number()));
        a.add(new Attribute(
                sole,
                "tool",
                Sole.TOOL_DIAMETER,
                j -> j.sole().get().tools().get(0).diameterMm()));
        a.add(new Attribute(
                sole,
                "tool",
                Sole.TOOL_SPINDLE,
                j -> j.sole().get().tools().get(0).spindleRpm()));
        a.add(new Attribute(
                sole, "tool", Sole.TOOL_FEED, j -> j.sole().get().tools().get(0).feedMmPerMin()));
        a.add(new Attribute(
                sole,
                "tool",
                Sole.TOOL_PLUNGE_FEED,
                j -> j.sole().get().tools().get(0).plungeFeedMmPerMin()));
        a.add(new Attribute(
                sole, "design", Sole.COUNT, j -> j.sole().get().designs().get(0).count()));
        a.add(new Attribute(
                sole, "design", Sole.ROWS, j -> j.sole().get().designs().get(0).rows()));
        a.add(new Attribute(
                sole, "design", Sole.DX, j -> j.sole().get().designs().get(0).dxMm()));
        a.add(new Attribute(
                sole, "design", Sole.STEP, j -> j.sole().get().designs().get(0).stepDeg()));
        a.add(new Attribute(
                sole,
                "design",
                Sole.CENTER_Y,
                j -> j.sole().get().designs().get(0).centerYMm()));
        a.add(new Attribute(
                sole, "block", Sole.BLOCK_D, j -> j.sole().get().block().get().dMm()));
        a.add(new Attribute(
                sole, "block", Sole.BLOCK_DLM, j -> j.sole().get().block().get().dlmMm()));
        a.add(new Attribute(
                sole, "block", Sole.BLOCK_E, j -> j.sole().get().block().get().eMm()));
        a.add(new Attribute(
                sole, "block", Sole.BLOCK_S, j -> j.sole().get().block().get().sMm()));
        a.add(new Attribute(
                sole, "block", Sole.BLOCK_CM, j -> j.sole().get().block().get().cmMm()));
        a.add(new Attribute(
                sole,
                "block",
                Sole.BLOCK_CP,
                j -> j.sole().get().block().get().cpMm().getAsDouble()));
        a.add(new Attribute(
                sole,
                "block",
                Sole.BLOCK_DPI,
                j -> j.sole().get().block().get().dpiMm().getAsDouble()));
        a.add(new Attribute(
                sole,
                "block",
                Sole.BLOCK_XTANP,
                j -> j.sole().get().block().get().xtanpMm().getAsDouble()));
        return a;
    }

    static double placement(org.fresa.model.Placement p, int i) {
        return new double[] {p.xMm(), p.yMm(), p.zMm(), p.rxDeg(), p.ryDeg(), p.rzDeg()}[i];
    }

    /** The sample job with the attribute set to the value on the first element of that name. */
    static String withValue(String xml, String element, String attribute, String value) {
        Matcher m =
                Pattern.compile("<" + element + "\\b[^>]*?>", Pattern.DOTALL).matcher(xml);
        if (!m.find()) {
            throw new IllegalArgumentException(element);
        }
        String tag = m.group();
        Matcher a = Pattern.compile("\\b" + attribute + "=\"[^\"]*\"").matcher(tag);
        String newTag = a.find()
                ? a.replaceFirst(attribute + "=\"" + value + "\"")
                : tag.replaceFirst("<" + element, "<" + element + " " + attribute + "=\"" + value + "\"");
        return xml.substring(0, m.start()) + newTag + xml.substring(m.end());
    }

    @Test
    void aJobFileValueIsReadOnlyInsideTheOptionsRange() throws Exception {
        List<Executable> checks = new ArrayList<>();
        int read = 0;
        int refused = 0;
        for (Attribute at : attributes()) {
            String sample = Files.readString(Path.of("samples/jobs", at.job()));
            for (String v : VALUES) {
                Path job = dir.resolve(at.job());
                Files.writeString(
                        job, withValue(sample, at.element(), at.range().attribute(), v));
                String what = at.element() + " " + at.range().attribute() + "=\"" + v + "\"";
                try {
                    double got = at.value().applyAsDouble(JobXml.read(job));
                    read++;
                    checks.add(() -> assertTrue(
                            at.range().contains(got),
                            what + " read as " + got + ", outside " + at.range().expected()));
                } catch (CamInputException e) {
                    refused++;
                    checks.add(() -> assertAll(
                            what + ": " + e.getMessage(),
                            () -> assertTrue(e.line().isPresent(), "with its line"),
                            () -> assertTrue(
                                    e.getMessage().contains(at.range().attribute())
                                            || e.getMessage().contains("schemas/job.xsd"),
                                    "names the attribute or the schema")));
                }
            }
        }
        assertEquals(attributes().size() * VALUES.size(), read + refused);
        assertTrue(read > 0 && refused > 0, read + " read, " + refused + " refused");
        assertAll(checks.stream());
    }

    @Test
    void aValueTheSchemaAllowsButTheRangeDoesNotIsRefusedAtItsLine() throws Exception {
        Path job = dir.resolve("job.xml");
        Files.writeString(
                job,
                withValue(Files.readString(Path.of("samples/jobs/cut-plate.xml")), "cutting", "leadInMm", "1e300"));
        CamInputException e =
                org.junit.jupiter.api.Assertions.assertThrows(CamInputException.class, () -> JobXml.read(job));
        assertAll(
                () -> assertEquals(4, e.line().getAsInt()),
                () -> assertEquals("leadInMm: expected a number from 0 to 1000 mm, found 1E300", e.problem()));
    }
}
