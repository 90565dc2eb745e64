package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;

class DadReaderTest {

    @Test
    void readsTheClosingElementFirstAndKeepsRawCoefficients() throws Exception {
        PocketProfile p = RecognitionTest.sample("cavity01.dad");
        assertEquals(6, p.elements().size());
        assertEquals(1, p.elements().get(0).number());
        assertEquals(6, p.elements().get(5).number());
        PocketElement l4 = p.elements().get(3);
        assertEquals(0.7, l4.a(), 0);
        assertEquals(-0.75, l4.b(), 0);
        // K from the direction of travel (seed §5.4): 6 +1, 1 +1, 2 -1, 3 -1, 4 -1, 5 +1
        assertEquals(
                java.util.List.of(1, -1, -1, -1, 1, 1),
                p.elements().stream().map(PocketElement::k).toList());
    }

    @Test
    void readsBasicExponentSpelling() throws Exception {
        PocketProfile p = RecognitionTest.sample("cavity05.dad");
        PocketElement l10 = p.elements().get(9);
        assertEquals(5.255885E-02, l10.a(), 0);
        assertEquals('M', l10.arc() ? 'x' : 'M');
    }

    @Test
    void aBadNumberIsReportedWithLineAndColumn() {
        String text = " 2R                     0                     1                    64   1\r\n"
                + " 1R                     1                     0                   1x4   2\r\n";
        CamInputException e = assertThrows(CamInputException.class, () -> DadReader.read(text, "bad.dad"));
        assertEquals(2, e.line().orElseThrow());
        assertEquals(48, e.column().orElseThrow());
    }

    @Test
    void anArcWithoutSenseIsRefused() {
        String text = " 2R                     0                     1                    64   1\n"
                + " 1C                     1                     0                    14S  2\n";
        CamInputException e = assertThrows(CamInputException.class, () -> DadReader.read(text, "bad.dad"));
        assertEquals(71, e.column().orElseThrow());
    }
}
