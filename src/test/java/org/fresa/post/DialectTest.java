package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.fresa.check.NcDialect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The one table of the controls' words, as the posts write them and the check reads them. */
class DialectTest {

    @ParameterizedTest
    @EnumSource(Dialect.class)
    void theCheckReadsEachDialectWithItsTurnWordAndUnit(Dialect d) {
        NcDialect read = NcDialect.byPost(d.id()).orElseThrow();
        assertEquals(d.mmPerUnit(), read.mmPerUnit());
        assertEquals(
                d,
                Dialect.byName(" " + d.id().toUpperCase(java.util.Locale.ROOT) + " ")
                        .orElseThrow());
        // a turn word is written exactly where the dialect names its address, behind that address
        assertEquals(d.turnAddress().isPresent(), d.turnsWord(2).isPresent());
        d.turnAddress()
                .ifPresent(a -> assertTrue(
                        d.turnsWord(2).orElseThrow().startsWith(a),
                        d.turnsWord(2).get()));
    }

    @Test
    void dwellsAreSecondsBehindEachControlsAddress() {
        assertEquals("G4 P1.5", Dialect.LINUXCNC.dwell("1.5"));
        assertEquals("G04 X2.000", Dialect.FANUC.dwell("2.000"));
        assertEquals("G4 F0.5", Dialect.SIEMENS_840D.dwell("0.5"));
        // the Fanuc-like controls read an X without a point as milliseconds
        assertTrue(Dialect.FANUC.dwellNeedsPoint() && Dialect.ISO.dwellNeedsPoint());
        assertFalse(Dialect.LINUXCNC.dwellNeedsPoint() || Dialect.SIEMENS_840D.dwellNeedsPoint());
        assertThrows(IllegalStateException.class, () -> Dialect.SINUMERIK_7M.dwell("1"));
    }

    @Test
    void everyCuttingPostIsADialectAndTheSevenMIsNone() {
        assertEquals(
                Arrays.stream(Dialect.values())
                        .filter(d -> d != Dialect.SINUMERIK_7M)
                        .toList(),
                Arrays.stream(CuttingPost.values()).map(CuttingPost::dialect).toList());
        for (CuttingPost p : CuttingPost.values()) {
            assertEquals(p, CuttingPost.byName(p.id()).orElseThrow());
        }
    }

    @Test
    void everyMillingGcodePostWritesInTheDialectOfItsName() {
        for (NcPost p : NcPosts.all()) {
            if (p instanceof GcodePost g) {
                assertEquals(Dialect.byName(p.name()).orElseThrow(), g.dialect());
            }
        }
    }
}
