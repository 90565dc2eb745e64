package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.List;
import org.fresa.geom.Contour;
import org.junit.jupiter.api.Test;

class ContourFileTest {

    static final String SLOT = """
            # a 40 x 20 slot with round ends, and a round island
            contour
            move 10 0
            line 30 0
            arc 30 10 30 20 ccw
            line 10 20
            arc 10 10 10 0 ccw   # back to the start
            contour
            move 22 10
            arc 20 10 22 10 cw
            """;

    @Test
    void readsContoursWithArcsAndIslands() throws CamInputException {
        List<Contour> cs = ContourFile.read(new StringReader(SLOT), "slot.contour");
        assertAll(
                () -> assertEquals(2, cs.size()),
                () -> assertEquals(20 * 20 + Math.PI * 100, cs.get(0).signedArea(), 1e-9),
                () -> assertEquals(-Math.PI * 4, cs.get(1).signedArea(), 1e-12));
    }

    @Test
    void writeThenReadGivesTheSameContours() throws CamInputException {
        List<Contour> cs = ContourFile.read(new StringReader(SLOT), "slot.contour");
        assertEquals(cs, ContourFile.read(new StringReader(ContourFile.write(cs)), "again"));
    }

    @Test
    void anOpenContourNamesItsLine() {
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> ContourFile.read(new StringReader("contour\nmove 0 0\nline 10 0\nline 10 10\n"), "open.contour"));
        assertTrue(e.getMessage().startsWith("open.contour: line 1"), e.getMessage());
        assertTrue(e.getMessage().contains("does not close"), e.getMessage());
    }

    @Test
    void aBadNumberNamesLineAndText() {
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> ContourFile.read(new StringReader("contour\nmove 0 0\nline 1O 0\n"), "typo.contour"));
        assertEquals("typo.contour: line 3: expected a number, found '1O'", e.getMessage());
    }

    @Test
    void anArcWhoseRadiiDifferIsRefused() {
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> ContourFile.read(
                        new StringReader("contour\nmove 0 0\narc 5 0 10 1 ccw\nline 0 0\n"), "arc.contour"));
        assertTrue(e.getMessage().contains("line 3"), e.getMessage());
    }
}
