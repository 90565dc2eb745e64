package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.fresa.model.CamInputException;
import org.fresa.pocket.DadContour;
import org.fresa.pocket.DadElement;
import org.fresa.pocket.DadReader;
import org.fresa.ui.PocketContourEditor.Column;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The contour editor without a screen: typing, checking, row moves and the .dad round trip. */
class PocketContourEditorTest {

    static Stream<Path> thesisContours() throws IOException {
        try (Stream<Path> s = Files.list(Path.of("samples/pocket"))) {
            List<Path> files =
                    s.filter(p -> p.toString().endsWith(".dad")).sorted().toList();
            // the 8 contours of the thesis's Appendix B
            assertEquals(8, files.size(), files.toString());
            return files.stream();
        }
    }

    /**
     * Every record typed cell by cell, as the file spells it, in the order of travel: the
     * profile equals the file's, record for record, and the written .dad is the file again, but
     * for number spellings that BASIC's STR$ would not write (cavity02's {@code 68.2000}).
     */
    @ParameterizedTest
    @MethodSource("thesisContours")
    void aContourTypedElementByElementIsTheContourOfItsFile(Path file) throws IOException, CamInputException {
        String text = Files.readString(file, StandardCharsets.ISO_8859_1);
        List<String> records = text.lines().filter(l -> !l.isBlank()).toList();
        PocketContourEditor editor = new PocketContourEditor();
        // the first record closes the contour: it is typed last
        List<String> travel = new ArrayList<>(records.subList(1, records.size()));
        travel.add(records.get(0));
        for (String raw : travel) {
            String r = String.format("%-73s", raw);
            editor.add();
            int row = editor.selected();
            editor.type(row, Column.TYPE, r.charAt(2) == 'C' ? "arc" : "line");
            editor.type(row, Column.A, r.substring(3, 25));
            editor.type(row, Column.B, r.substring(25, 47));
            editor.type(row, Column.D, r.substring(47, 69));
            editor.type(row, Column.SELECTOR, r.substring(69, 70));
            editor.type(row, Column.SENSE, r.charAt(70) == 'F' ? "convex" : r.charAt(70) == 'M' ? "concave" : "");
            for (Column c : Column.values()) {
                assertEquals(java.util.Optional.empty(), editor.problem(row, c), file + " row " + row + " " + c);
            }
        }
        String name = file.getFileName().toString();
        assertEquals(DadReader.read(text, name), editor.contour().profile(name), name);
        assertEquals(DadReader.contour(text, name), editor.contour(), name);
        assertTrue(editor.valid(), () -> name + ": " + editor.refusal());

        List<String> written = editor.contour().toDad().lines().toList();
        assertEquals(records.size(), written.size());
        List<String> differ = new ArrayList<>();
        for (int i = 0; i < records.size(); i++) {
            if (!records.get(i).equals(written.get(i))) {
                differ.add(records.get(i).trim() + " | " + written.get(i).trim());
            }
        }
        if (name.equals("cavity02.dad")) {
            assertEquals(
                    List.of("1R                 .8852                  .461               68.2000S  2"
                            + " | 1R                 .8852                  .461                  68.2S  2"),
                    differ);
            assertEquals(
                    DadReader.read(text, name), DadReader.read(editor.contour().toDad(), name));
        } else {
            assertEquals(List.of(), differ, name);
            assertEquals(text, editor.contour().toDad(), name + ": byte for byte with its CR LF");
        }
    }

    @Test
    void aBadCellKeepsTheLastValidValueAndSaysWhyInThePlannersWords() throws CamInputException {
        PocketContourEditor editor = new PocketContourEditor();
        editor.load(DadReader.contour(read("examplepart.dad"), "examplepart.dad"));
        DadContour before = editor.contour();
        assertFalse(editor.type(1, Column.D, "5,5"));
        assertEquals(
                "Element 2, radius: '5,5' is not a number (decimals take a point: 5.5).",
                editor.problem(1, Column.D).orElseThrow());
        assertEquals("5,5", editor.text(1, Column.D));
        assertEquals(before, editor.contour());
        assertFalse(editor.valid());
        assertFalse(editor.type(1, Column.D, "-5"));
        assertEquals("Element 2, radius: radius must be >= 0.", editor.refusal().orElseThrow());
        assertFalse(editor.type(0, Column.SENSE, "convex"));
        assertEquals(
                "Element 1, sense: a line has no sense, found 'convex'.",
                editor.problem(0, Column.SENSE).orElseThrow());
        assertFalse(editor.type(0, Column.SELECTOR, "X"));
        assertTrue(editor.problem(0, Column.SELECTOR).orElseThrow().startsWith("Element 1, selector: S (the junction"));
        assertFalse(editor.type(3, Column.TYPE, "spline"));
        assertEquals(
                "Element 4, type: 'spline' is neither line nor arc.",
                editor.problem(3, Column.TYPE).orElseThrow());
        assertFalse(editor.type(2, Column.A, "1e7"));
        assertEquals(
                "Element 3, A: |value| must be at most 1e6 mm, found 1e7.",
                editor.problem(2, Column.A).orElseThrow());
        // typed right, the cell is good again and the value changes
        assertTrue(editor.type(1, Column.D, "5.5"));
        assertEquals("5.5", editor.text(1, Column.D));
        assertEquals(5.5, editor.contour().elements().get(1).d(), 0);
        // the first bad cell is the one reported
        assertEquals(
                "Element 1, selector: S (the junction with the smaller x), L (the larger x) or blank, found 'X'.",
                editor.refusal().orElseThrow());
    }

    @Test
    void aContourThatDoesNotCloseOrCrossesItselfIsRefusedWithTheElementNamed() {
        PocketContourEditor editor = new PocketContourEditor();
        // a 40 x 30 rectangle, clockwise, with its right side an arc bulging out
        editor.load(rectangleWithArc());
        assertTrue(editor.valid(), () -> editor.refusal().toString());
        // the right arc moved far away meets neither neighbour
        assertTrue(editor.type(1, Column.B, "500"));
        assertEquals(
                "Element 2 does not meet element 1: the contour does not close there.",
                editor.refusal().orElseThrow());
        assertEquals(1, editor.refusedRow().orElseThrow());
        assertEquals("The contour does not close", editor.scene().title());
        assertTrue(editor.type(1, Column.B, "15"));
        assertTrue(editor.valid());

        // a bow tie (0, 0), (40, 30), (40, 0), (0, 30): its diagonals cross at (20, 15)
        PocketContourEditor bow = new PocketContourEditor();
        bow.load(new DadContour(List.of(
                DadElement.line(3, -4, 0),
                DadElement.line(1, 0, 40),
                DadElement.line(3, 4, 120),
                DadElement.line(1, 0, 0))));
        assertEquals(
                "Element 3 crosses element 1: the contour intersects itself.",
                bow.refusal().orElseThrow());
        assertEquals(2, bow.refusedRow().orElseThrow());

        // the left side as x + y = 100 turns the contour round: counter-clockwise, refused
        PocketContourEditor ccw = new PocketContourEditor();
        ccw.load(rectangleWithArc());
        assertTrue(ccw.type(3, Column.B, "1"));
        assertTrue(ccw.type(3, Column.D, "100"));
        assertTrue(
                ccw.refusal().orElseThrow().startsWith("The contour runs counter-clockwise"),
                ccw.refusal().toString());

        PocketContourEditor one = new PocketContourEditor();
        one.add();
        assertEquals("A contour needs at least 2 elements.", one.refusal().orElseThrow());
    }

    @Test
    void rowsAreAddedInsertedDeletedAndMovedAroundTheSelection() {
        PocketContourEditor editor = new PocketContourEditor();
        editor.load(rectangleWithArc());
        DadContour start = editor.contour();
        editor.select(1);
        assertTrue(editor.moveDown());
        assertEquals(2, editor.selected());
        assertEquals(start.elements().get(1), editor.contour().elements().get(2));
        assertTrue(editor.moveUp());
        assertEquals(start, editor.contour());
        assertFalse(new PocketContourEditor().moveUp());
        editor.select(0);
        assertFalse(editor.moveUp());
        editor.insert();
        assertEquals(0, editor.selected());
        assertEquals(
                PocketContourEditor.NEW_ELEMENT, editor.contour().elements().get(0));
        assertEquals(5, editor.rows());
        assertTrue(editor.delete());
        assertEquals(start, editor.contour());
        editor.select(3);
        editor.add();
        assertEquals(4, editor.selected());
        assertEquals(5, editor.rows());
        editor.delete();
        assertEquals(3, editor.selected());
        assertEquals(start, editor.contour());
        // a bad cell goes back to its value when rows move
        editor.type(0, Column.D, "x");
        editor.moveUp();
        assertEquals(java.util.Optional.empty(), editor.problem(0, Column.D));
    }

    @Test
    void thePlotShowsTheContourAsTypedWithTheSelectedElementHighlighted() {
        PocketContourEditor editor = new PocketContourEditor();
        editor.load(rectangleWithArc());
        editor.select(1);
        var scene = editor.scene();
        var contour = scene.layers().stream()
                .filter(l -> l.name().equals("contour"))
                .findFirst()
                .orElseThrow();
        assertEquals(4, contour.curves().size());
        var selected = scene.layers().stream()
                .filter(l -> l.name().equals("selected element"))
                .findFirst()
                .orElseThrow();
        assertEquals(1, selected.curves().size());
        assertTrue(selected.curves().get(0) instanceof org.fresa.geom.Arc2);
        assertEquals(
                List.of("1", "2", "3", "4"),
                scene.labels().stream().map(l -> l.text()).toList());
    }

    /**
     * A clockwise 40 x 30 rectangle whose right side bulges out: the top, the arc of radius 25
     * about (20, 15) from (40, 30) to (40, 0), the bottom (starting at the larger x), the left side.
     */
    static DadContour rectangleWithArc() {
        return new DadContour(List.of(
                DadElement.line(0, 1, 30),
                DadElement.arc(20, 15, 25, 'L', true),
                DadElement.line(0, 1, 0).withSelector('L'),
                DadElement.line(1, 0, 0)));
    }

    private static String read(String name) {
        try {
            return Files.readString(Path.of("samples/pocket", name), StandardCharsets.ISO_8859_1);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void aContourOfTheMostElementsTakesNoMore() {
        PocketContourEditor full = new PocketContourEditor();
        for (int i = 0; i < org.fresa.pocket.DadContour.MAX_ELEMENTS; i++) {
            assertTrue(full.add());
        }
        assertFalse(full.add());
        assertFalse(full.insert());
        assertEquals(org.fresa.pocket.DadContour.MAX_ELEMENTS, full.rows());
    }

    @Test
    void anEmptyTableShownForAContourFileIsNoRefusalUntilRowsAreEdited() {
        PocketContourEditor editor = new PocketContourEditor();
        // a .contour file (or none) loads no records: its contour is read at Compute
        editor.load(new DadContour(List.of()));
        assertTrue(editor.note().orElseThrow().startsWith("No elements typed: Compute pockets the contour file."));
        assertFalse(editor.valid());
        // once the planner starts typing, too few elements is the contour's refusal again
        assertTrue(editor.add());
        assertTrue(editor.note().isEmpty());
        assertEquals("A contour needs at least 2 elements.", editor.refusal().orElseThrow());
        assertTrue(editor.delete());
        assertTrue(editor.note().isEmpty());
        // a contour with elements says nothing of a file
        editor.load(rectangleWithArc());
        assertTrue(editor.note().isEmpty());
    }
}
