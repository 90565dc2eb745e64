package org.fresa.ui;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Pattern;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Curve2;
import org.fresa.pocket.DadContour;
import org.fresa.pocket.DadElement;

/**
 * The Pocket tab's contour editor without Swing: a table of the contour's elements as the
 * thesis's {@code .dad} file holds them (a line A·x + B·y = D, or a circle with centre x, y and
 * radius R, its S/L selector and for a circle its sense), one row per element in the order of
 * travel. Each cell is typed as text and checked at once: a bad cell keeps the element's last
 * valid value and says why in the planner's words. A contour whose consecutive elements do not
 * meet, or whose elements cross, is refused with the element named.
 */
public final class PocketContourEditor {

    /** The columns, in the order shown. */
    public enum Column {
        TYPE("Type"),
        A("A / centre x"),
        B("B / centre y"),
        D("D / radius"),
        SELECTOR("S/L"),
        SENSE("Sense");

        private final String title;

        Column(String title) {
            this.title = title;
        }

        public String title() {
            return title;
        }
    }

    /** A cell: the row (element number - 1) and the column. */
    public record Cell(int row, Column column) {}

    /** The words the Type and Sense columns show and take (the file's letters are taken too). */
    public static final String LINE = "line";

    public static final String ARC = "arc";
    public static final String CONVEX = "convex";
    public static final String CONCAVE = "concave";
    /** What a new row holds until typed over: the line y = 0. */
    public static final DadElement NEW_ELEMENT = DadElement.line(0, 1, 0);

    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([EeDd][+-]?\\d+)?");

    private final List<DadElement> elements = new ArrayList<>();
    // cells typed with what is not a value: the text as typed and why it is refused
    private final Map<Cell, String> badText = new HashMap<>();
    private final Map<Cell, String> problems = new HashMap<>();
    private int selected = -1;
    // the contour's own refusal and curves, worked out once per change of the elements: the table
    // asks for them for every row it paints
    private Optional<DadContour.Refusal> refusal;
    private Optional<List<Curve2>> curves;
    // rows added, deleted or moved since the contour was shown: an empty table nobody has touched
    // is no contour refused, the job reads its contour file
    private boolean rowsEdited;

    /** Shows a contour (a new one, read from its file or from the job); no cell is bad, nothing is selected. */
    public void load(DadContour contour) {
        elements.clear();
        elements.addAll(contour.elements());
        elementsChanged();
        badText.clear();
        problems.clear();
        selected = elements.isEmpty() ? -1 : 0;
        rowsEdited = false;
    }

    /** The contour of the valid values (a bad cell keeps the last valid one). */
    public DadContour contour() {
        return new DadContour(elements);
    }

    public int rows() {
        return elements.size();
    }

    public int selected() {
        return selected;
    }

    /** Selects a row (-1: none). */
    public void select(int row) {
        if (row < -1 || row >= elements.size()) {
            throw new IndexOutOfBoundsException("row " + row);
        }
        selected = row;
    }

    /** The cell's text: as typed when it is bad, else the element's value. */
    public String text(int row, Column c) {
        String bad = badText.get(new Cell(row, c));
        if (bad != null) {
            return bad;
        }
        DadElement e = elements.get(row);
        return switch (c) {
            case TYPE -> e.arc() ? ARC : LINE;
            case A -> DadContour.basic(e.a());
            case B -> DadContour.basic(e.b());
            case D -> DadContour.basic(e.d());
            case SELECTOR -> e.selector() == ' ' ? "" : String.valueOf(e.selector());
            case SENSE -> !e.arc() ? "" : e.sense() == 'F' ? CONVEX : CONCAVE;
        };
    }

    /** Why the cell's text is refused, if it is. */
    public Optional<String> problem(int row, Column c) {
        return Optional.ofNullable(problems.get(new Cell(row, c)));
    }

    /**
     * Takes a cell's text: a valid one changes the element (and clears the cell's problem), a bad
     * one is kept as typed with its problem and the element keeps its value.
     *
     * @return true when the contour changed
     */
    public boolean type(int row, Column c, String typed) {
        String t = typed.trim();
        Cell cell = new Cell(row, c);
        DadElement e = elements.get(row);
        String what = label(e, c);
        DadElement changed;
        try {
            changed = switch (c) {
                case TYPE -> e.withArc(arcOf(t));
                case A -> e.withA(number(t));
                case B -> e.withB(number(t));
                case D -> e.withD(number(t));
                case SELECTOR -> e.withSelector(selectorOf(t));
                case SENSE -> e.withSense(senseOf(e, t));
            };
        } catch (IllegalArgumentException ex) {
            badText.put(cell, typed);
            problems.put(cell, "Element " + (row + 1) + ", " + what + ": " + ex.getMessage() + ".");
            return false;
        }
        badText.remove(cell);
        problems.remove(cell);
        if (c == Column.TYPE) {
            // the other cells of the row mean something else now
            for (Column o : Column.values()) {
                badText.remove(new Cell(row, o));
                problems.remove(new Cell(row, o));
            }
        }
        if (changed.equals(e)) {
            return false;
        }
        elements.set(row, changed);
        elementsChanged();
        return true;
    }

    private static String label(DadElement e, Column c) {
        return switch (c) {
            case TYPE -> "type";
            case A -> e.arc() ? "centre x" : "A";
            case B -> e.arc() ? "centre y" : "B";
            case D -> e.arc() ? "radius" : "D";
            case SELECTOR -> "selector";
            case SENSE -> "sense";
        };
    }

    private static boolean arcOf(String t) {
        String w = t.toLowerCase(Locale.ROOT);
        if (w.equals(LINE) || w.equals("r")) {
            return false;
        }
        if (w.equals(ARC) || w.equals("c") || w.equals("circle")) {
            return true;
        }
        throw new IllegalArgumentException("'" + t + "' is neither line nor arc");
    }

    private static double number(String t) {
        if (!NUMBER.matcher(t).matches()) {
            throw new IllegalArgumentException("'" + t + "' is not a number"
                    + (t.contains(",") ? " (decimals take a point: " + t.replace(',', '.') + ")" : ""));
        }
        double v = Double.parseDouble(t.replace('D', 'E').replace('d', 'e'));
        if (!(Math.abs(v) <= DadElement.MAX_ABS_MM)) {
            throw new IllegalArgumentException("|value| must be at most 1e6 mm, found " + t);
        }
        return v;
    }

    private static char selectorOf(String t) {
        String w = t.toUpperCase(Locale.ROOT);
        if (w.isEmpty() || w.equals("S") || w.equals("L")) {
            return w.isEmpty() ? ' ' : w.charAt(0);
        }
        throw new IllegalArgumentException(
                "S (the junction with the smaller x), L (the larger x) or blank, found '" + t + "'");
    }

    private static char senseOf(DadElement e, String t) {
        String w = t.toLowerCase(Locale.ROOT);
        if (!e.arc()) {
            if (w.isEmpty()) {
                return ' ';
            }
            throw new IllegalArgumentException("a line has no sense, found '" + t + "'");
        }
        if (w.equals(CONVEX) || w.equals("f")) {
            return 'F';
        }
        if (w.equals(CONCAVE) || w.equals("m")) {
            return 'M';
        }
        throw new IllegalArgumentException("convex (centre inside the pocket, F) or concave (M), found '" + t + "'");
    }

    /**
     * Adds a new element after the selected one (at the end when none is) and selects it; false
     * when the contour already has the most elements a .dad file holds.
     */
    public boolean add() {
        return insertAt(selected < 0 ? elements.size() : selected + 1);
    }

    /** Inserts a new element before the selected one (at the start when none is) and selects it. */
    public boolean insert() {
        return insertAt(Math.max(0, selected));
    }

    private boolean insertAt(int row) {
        if (elements.size() >= DadContour.MAX_ELEMENTS) {
            return false;
        }
        structural();
        elements.add(row, NEW_ELEMENT);
        elementsChanged();
        selected = row;
        return true;
    }

    /** Deletes the selected element; the next one (or the new last) is selected. */
    public boolean delete() {
        if (selected < 0) {
            return false;
        }
        structural();
        elements.remove(selected);
        elementsChanged();
        selected = Math.min(selected, elements.size() - 1);
        return true;
    }

    /** Moves the selected element one place earlier in the order of travel. */
    public boolean moveUp() {
        return swap(selected - 1);
    }

    /** Moves the selected element one place later in the order of travel. */
    public boolean moveDown() {
        return swap(selected + 1);
    }

    private boolean swap(int other) {
        if (selected < 0 || other < 0 || other >= elements.size()) {
            return false;
        }
        structural();
        DadElement e = elements.get(selected);
        elements.set(selected, elements.get(other));
        elements.set(other, e);
        elementsChanged();
        selected = other;
        return true;
    }

    private void elementsChanged() {
        refusal = null;
        curves = null;
    }

    private Optional<DadContour.Refusal> contourRefusal() {
        if (refusal == null) {
            refusal = contour().refusal();
        }
        return refusal;
    }

    private Optional<List<Curve2>> contourCurves() {
        if (curves == null) {
            curves = contour().curves();
        }
        return curves;
    }

    /** Rows move: a cell typed badly goes back to its element's value. */
    private void structural() {
        badText.clear();
        problems.clear();
        rowsEdited = true;
    }

    /**
     * What the editor says of itself when it refuses nothing yet: nothing typed since it was
     * shown empty means the contour file is pocketed, which is no error of that file.
     */
    public Optional<String> note() {
        if (elements.isEmpty() && !rowsEdited) {
            return Optional.of("No elements typed: Compute pockets the contour file."
                    + " Add (Insert) starts a typed contour instead.");
        }
        return Optional.empty();
    }

    /** Whether every cell holds a value and the contour closes without crossing itself. */
    public boolean valid() {
        return problems.isEmpty() && contourRefusal().isEmpty();
    }

    /** The first reason the contour is not taken: a bad cell first, then the contour as a whole. */
    public Optional<String> refusal() {
        Optional<Cell> first = problems.keySet().stream()
                .min((x, y) -> x.row() != y.row()
                        ? Integer.compare(x.row(), y.row())
                        : x.column().compareTo(y.column()));
        if (first.isPresent()) {
            return Optional.of(problems.get(first.get()));
        }
        return contourRefusal().map(DadContour.Refusal::message);
    }

    /** The element the contour's refusal names (row = element - 1), when it names one. */
    public OptionalInt refusedRow() {
        Optional<DadContour.Refusal> r = contourRefusal();
        return r.isPresent() && r.get().element() > 0 ? OptionalInt.of(r.get().element() - 1) : OptionalInt.empty();
    }

    /**
     * The contour as typed, element numbers at their middles, the selected element drawn over it
     * in the warning style; empty of curves while two consecutive elements do not meet.
     */
    public PlotScene scene() {
        Optional<List<Curve2>> curves = contourCurves();
        if (curves.isEmpty()) {
            return PlotScene.empty(
                    elements.size() < DadContour.MIN_ELEMENTS
                            ? "Type the contour's elements"
                            : "The contour does not close");
        }
        List<Curve2> all = new ArrayList<>();
        PlotScene scene = PlotScene.empty("contour as typed");
        for (int i = 0; i < curves.get().size(); i++) {
            Curve2 c = curves.get().get(i);
            if (c != null) {
                all.add(c);
                scene = scene.withLabel(c.pointAt(0.5), Integer.toString(i + 1));
            }
        }
        scene = scene.with(new PlotScene.Layer("contour", PlotScene.Style.OUTLINE, all));
        if (selected >= 0 && curves.get().get(selected) != null) {
            scene = scene.with(new PlotScene.Layer(
                    "selected element",
                    PlotScene.Style.WARNING,
                    List.of(curves.get().get(selected))));
        }
        return scene;
    }
}
