package org.fresa.pocket.compat;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketPass;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.Recognition;
import org.junit.jupiter.api.Test;

class ThesisPassesTest {

    static PocketPlan plan(String dad, PocketTechnology t) throws Exception {
        Path p = Path.of("samples/pocket", dad);
        return PassPlanner.plan(Recognition.of(DadReader.read(Files.readString(p), dad)), t);
    }

    @Test
    void comparIsTheMeanOfTheInputDistancesInSinglePrecision() throws Exception {
        PocketPlan plan = plan("examplepart.dad", new PocketTechnology(4, 0.62, 0.18, 8, 6, 2, 3250, 278, 115));
        // GOTA.BAS line 57, D/N·.0001 over 3, 25.48066, 5, 1.1437, 3 and 16
        assertEquals(" 8.937393E-04", BasicNumbers.str(ThesisPasses.compar(plan)));
    }

    @Test
    void passOffsetsAreTheProgramsSinglePrecisionChain() throws Exception {
        // cavity 05: R = 5, a = 1.7; DTESTE = 1.7 + .72·10 = 8.900001 in single precision, the
        // third pass at 13.9, the sub-area's last pass at (leaf + DTESTE)/2 = 20.96666; GOTA.BAS
        // run in an emulated GW-BASIC prints the same DPERC at its passes
        PocketPlan plan = plan("cavity05.dad", new PocketTechnology(10, 0.72, 0.17, 15, 12, 4, 3250, 295, 90));
        List<String> offsets = ThesisPasses.of(plan).orElseThrow().generated().stream()
                .map(PocketPass::offsetMm)
                .map(d -> BasicNumbers.str(Mbf.of(d.floatValue())))
                .toList();
        assertEquals(List.of(" 5", " 6.7", " 13.9", " 20.96666"), offsets);
    }

    @Test
    void passesKeepTheirElementsAndOnlyMoveTheirJunctions() throws Exception {
        PocketPlan plan = plan("cavity01.dad", new PocketTechnology(6, 0.62, 0.13, 30, 27, 3, 3200, 290, 100));
        PocketPlan thesis = ThesisPasses.of(plan).orElseThrow();
        assertEquals(plan.generated().size(), thesis.generated().size());
        for (int i = 0; i < plan.generated().size(); i++) {
            PocketPass a = plan.generated().get(i);
            PocketPass b = thesis.generated().get(i);
            assertEquals(a.nodePath(), b.nodePath());
            assertEquals(a.pieces().size(), b.pieces().size());
            assertEquals(a.offsetMm(), b.offsetMm(), 1e-5);
            for (int k = 0; k < a.pieces().size(); k++) {
                assertEquals(a.pieces().get(k).element(), b.pieces().get(k).element());
                assertEquals(
                        0, a.pieces().get(k).start().distance(b.pieces().get(k).start()), 1e-3);
            }
        }
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"clover.contour", "rooms.contour", "slot-ccw.contour"})
    void contoursBeyondTheThesisGetTheSamePassesInItsArithmetic(String name) throws Exception {
        // Fresa's own test contours: several sub-areas, a four-way split; every pass is recomputed
        var contours = org.fresa.pocket.PocketProfile.fromContours(org.fresa.model.ContourFile.read(
                new java.io.StringReader(Files.readString(Path.of("samples/pocket", name))), name));
        PocketPlan plan =
                PassPlanner.plan(Recognition.of(contours), new PocketTechnology(2, 0.6, 0.1, 5, 0, 5, 3000, 300, 100));
        PocketPlan thesis = ThesisPasses.of(plan).orElseThrow();
        assertEquals(plan.generated().size(), thesis.generated().size());
        for (int i = 0; i < plan.generated().size(); i++) {
            assertEquals(
                    plan.generated().get(i).offsetMm(),
                    thesis.generated().get(i).offsetMm(),
                    1e-4);
        }
    }
}
