package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The draft standard's spellings (ISO/FDIS 14649-11) are read as the standard's and reported,
 * on the project's own file (the draft's text itself is read from ../shared/corpus only, as an
 * extra: see StepNcReaderTest).
 */
class DraftSpellingsTest {

    static final Path DRAFT = Path.of("src/test/resources/org/fresa/stepnc/example1-draft-spellings.stp");

    @Test
    void exampleOneInTheDraftsSpellingIsReadWithEachSpellingReported() throws Exception {
        StepNcProgram p = StepNcReader.read(DRAFT);
        String seen = String.join("\n", p.spellings());
        assertAll(
                seen,
                () -> assertEquals(5, p.workingsteps().size()),
                () -> assertTrue(seen.contains("BIDIRECTIONAL read as BIDIRECTIONAL_MILLING")),
                () -> assertTrue(seen.contains("TOOL_DIMENSION read as MILLING_TOOL_DIMENSION")),
                () -> assertTrue(seen.contains("ELEMENTARY_SURFACE read as PLANE")),
                () -> assertTrue(seen.contains("CUTTING_COMPONENT written with 4 attributes")),
                () -> assertTrue(seen.contains("percentage")));
    }

    @Test
    void thePercentagesOfTheDraftBecomeFractions() throws Exception {
        StepNcProgram p = StepNcReader.read(DRAFT);
        // DRILLING_TYPE_STRATEGY(75.000, 50.000, 2.000, 50.000, 75.000, 8.000)
        DrillingStrategy d = p.workingsteps()
                .get(1)
                .operation()
                .strategy()
                .orElseThrow()
                .drilling()
                .orElseThrow();
        Strategy bidir = p.workingsteps().get(0).operation().strategy().orElseThrow();
        assertAll(
                () -> assertEquals(0.5, d.reducedFeedAtStart().orElseThrow(), 1e-12),
                () -> assertEquals(0.75, d.reducedFeedAtEnd().orElseThrow(), 1e-12),
                () -> assertEquals(8.0, d.depthOfEndMm().orElseThrow(), 1e-12),
                () -> assertEquals(Strategy.StrategyType.BIDIRECTIONAL, bidir.type()),
                () -> assertEquals("BIDIRECTIONAL", bidir.entity()),
                () -> assertEquals(0.05, bidir.overlapFraction().orElseThrow(), 1e-12));
    }

    @Test
    void theGeneralPocketProfileAndTheRampsOfTheDraftAreKept() throws Exception {
        StepNcProgram p = StepNcReader.read(DRAFT);
        Profile.General outline =
                (Profile.General) p.workingsteps().get(3).feature().profile().orElseThrow();
        assertAll(
                () -> assertEquals(4, outline.segments().size()),
                () -> assertTrue(outline.closed()),
                () -> assertEquals(
                        Strategy.StrategyType.CONTOUR_BIDIRECTIONAL,
                        p.workingsteps()
                                .get(3)
                                .operation()
                                .strategy()
                                .orElseThrow()
                                .type()),
                () -> assertEquals(
                        ApproachRetract.Kind.PLUNGE_RAMP,
                        p.workingsteps()
                                .get(0)
                                .operation()
                                .approach()
                                .orElseThrow()
                                .kind()));
    }
}
