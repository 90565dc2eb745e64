package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/** Feed units: ISO files in m/s, STEP Modeler's unitless chip loads. */
class FeedRateTest {

    static StepNcProgram read(String name) throws Exception {
        return StepNcReader.read(Path.of("samples/stepnc", name));
    }

    static MachiningWorkingstep first(StepNcProgram p, long instanceId) {
        return p.workingsteps().stream()
                .filter(w -> w.instanceId() == instanceId)
                .findFirst()
                .orElseThrow();
    }

    @Test
    void anIsoFeedInMetresPerSecondIsUsedAsConverted() throws Exception {
        // example 1: MILLING_TECHNOLOGY(0.040, ...) is 0.04 m/s = 2400 mm/min
        FeedRate f = FeedRate.of(
                read("iso14649-11-example1.stp").workingsteps().get(0).operation());
        assertAll(
                () -> assertEquals(2400, f.feedMmPerMin(), 1e-9),
                () -> assertEquals("m/s", f.readAs()),
                () -> assertEquals(false, f.inferred()),
                () -> assertEquals("feed 0.04 m/s = 2400 mm/min", f.note()));
    }

    @Test
    void stepModelersMillingFeedIsPerToothTimesTeethTimesSpindle() throws Exception {
        // example 2 #224 (workplan XY): FACEMILL Ø20, 4 teeth, feed 0.073, spindle 2307.7466748324823 rpm
        StepNcProgram p = read("example2.stp");
        FeedRate f = FeedRate.of(first(p, 224).operation());
        assertAll(
                () -> assertEquals("mm/tooth", f.readAs()),
                () -> assertEquals(0.073 * 4 * 2307.7466748324823, f.feedMmPerMin(), 1e-9),
                () -> assertEquals(4, f.teeth().getAsInt()),
                () -> assertEquals(
                        "feed 0.073 (no unit in the file) read as mm/tooth: 0.073 x 4 teeth x 2307.7467 rpm"
                                + " = 673.862 mm/min",
                        f.note()));
    }

    @Test
    void stepModelersDrillingFeedIsPerRevolutionTimesSpindle() throws Exception {
        // example 2 #59: DRILLING with a 2-tooth TWIST_DRILL Ø10, feed 0.245, spindle 3501.4087480216976 rpm;
        // per tooth it would be 0.49 mm/rev, far above a Ø10 drill's feed in 250 HB steel
        FeedRate f = FeedRate.of(first(read("example2.stp"), 59).operation());
        assertAll(
                () -> assertEquals("mm/rev", f.readAs()),
                () -> assertEquals(0.245 * 3501.4087480216976, f.feedMmPerMin(), 1e-9));
    }

    @Test
    void thePlanFeedsAtTheConvertedRateAndSaysSoOncePerDistinctReading() throws Exception {
        StepNcProgram p = read("example2.stp");
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        // #276: the top pocket with the Ø16 four-tooth mill, feed 0.0505, spindle 2884.683343540603 rpm
        ToolpathSection mill = plan.sectionOf(276).orElseThrow();
        double expected = 0.0505 * 4 * 2884.683343540603;
        List<Double> feeds = mill.moves().stream()
                .filter(m -> m instanceof Move.Linear || m instanceof Move.Circular)
                .map(m -> m instanceof Move.Linear l ? l.feedMmPerMin() : ((Move.Circular) m).feedMmPerMin())
                .distinct()
                .toList();
        // cutting at the feed, entering (down the helix) at half of it
        assertEquals(
                List.of(expected / 2, expected).stream().sorted().toList(),
                feeds.stream().sorted().toList());
        List<String> notes = plan.problems().stream()
                .filter(s -> s.contains("no unit in the file"))
                .toList();
        assertEquals(4, notes.size(), notes.toString());
        assertTrue(
                notes.stream()
                        .anyMatch(
                                s -> s.startsWith("12 workingsteps: feed 0.245 (no unit in the file) read as mm/rev")),
                notes.toString());
        assertTrue(
                plan.problems().stream().noneMatch(s -> s.contains("1000 mm/min")),
                plan.problems().toString());
    }
}
