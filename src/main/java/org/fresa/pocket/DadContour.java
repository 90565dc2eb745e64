package org.fresa.pocket;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;

/**
 * A pocket contour as the thesis's {@code .dad} file holds it: its elements in the order of
 * travel, element i (from 0) numbered i + 1, each followed by the next and the last by the first.
 * The file writes the last (closing) element first, as GOTA.BAS does.
 *
 * @param elements the elements in the order of travel
 */
public record DadContour(List<DadElement> elements) {

    /** A contour needs two elements at least (a line closing an arc). */
    public static final int MIN_ELEMENTS = 2;
    /** At most 99 elements: the record has two columns for the element number. */
    public static final int MAX_ELEMENTS = 99;

    private static final int FIELD = 22;
    // two elements that meet closer than this to a third's extent cross it (drawing tolerance)
    private static final Tolerance CROSSING = Tolerance.ofLinear(1e-6);

    public DadContour {
        elements = List.copyOf(elements);
        if (elements.size() > MAX_ELEMENTS) {
            throw new IllegalArgumentException("a .dad contour has at most " + MAX_ELEMENTS + " elements");
        }
    }

    /**
     * Why this contour cannot be pocketed, naming the element (number from 1).
     *
     * @param element the element number the problem is at (1 to n), 0 for the contour as a whole
     * @param message the reason in the planner's words
     */
    public record Refusal(int element, String message) {}

    /**
     * The first reason the contour is refused: fewer than two elements, two consecutive elements
     * that do not meet (the contour does not close there), or two elements that cross.
     */
    public Optional<Refusal> refusal() {
        int n = elements.size();
        if (n < MIN_ELEMENTS) {
            return Optional.of(new Refusal(0, "A contour needs at least " + MIN_ELEMENTS + " elements."));
        }
        List<PocketElement> els = numbered();
        double compar = PocketProfile.comparOf(els);
        List<Vec2> v = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int p = (i + n - 1) % n;
            Optional<Vec2> j = ElementGeometry.junction(els.get(p), els.get(i), 0, compar);
            if (j.isEmpty()) {
                return Optional.of(new Refusal(
                        i + 1,
                        "Element " + (i + 1) + " does not meet element " + (p + 1)
                                + ": the contour does not close there."));
            }
            v.add(j.get());
        }
        List<Curve2> curves = curves(els, v);
        for (int i = 0; i < n; i++) {
            for (int j = i + 2; j < n; j++) {
                if (i == 0 && j == n - 1 || curves.get(i) == null || curves.get(j) == null) {
                    continue;
                }
                if (!Intersections.of(curves.get(i), curves.get(j), CROSSING).isEmpty()) {
                    return Optional.of(new Refusal(
                            j + 1,
                            "Element " + (j + 1) + " crosses element " + (i + 1) + ": the contour intersects itself."));
                }
            }
        }
        List<Curve2> drawn = curves.stream().filter(java.util.Objects::nonNull).toList();
        if (drawn.isEmpty() || new org.fresa.geom.Contour(drawn).signedArea() >= 0) {
            return Optional.of(new Refusal(
                    0,
                    "The contour runs counter-clockwise (or encloses nothing): the"
                            + " thesis's contours run clockwise, the pocket on the right of each element; check the S/L"
                            + " selectors and the order of the elements."));
        }
        return Optional.empty();
    }

    /** The elements as drawn (junction to junction); empty when two consecutive elements do not meet. */
    public Optional<List<Curve2>> curves() {
        if (elements.size() < MIN_ELEMENTS) {
            return Optional.empty();
        }
        List<PocketElement> els = numbered();
        double compar = PocketProfile.comparOf(els);
        int n = els.size();
        List<Vec2> v = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Optional<Vec2> j = ElementGeometry.junction(els.get((i + n - 1) % n), els.get(i), 0, compar);
            if (j.isEmpty()) {
                return Optional.empty();
            }
            v.add(j.get());
        }
        return Optional.of(curves(els, v));
    }

    /** Element i from junction i to junction i + 1; null where it has no length. */
    private static List<Curve2> curves(List<PocketElement> els, List<Vec2> v) {
        int n = els.size();
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            PocketElement e = els.get(i);
            Vec2 a = v.get(i);
            Vec2 b = v.get((i + 1) % n);
            if (a.distance(b) < 1e-9) {
                out.add(null);
            } else if (e.arc()
                    && e.d() > 0
                    && Math.abs(a.distance(e.center()) - b.distance(e.center())) < 1e-6 * (1 + e.d())) {
                // concave arcs turn counter-clockwise in the thesis's clockwise contour
                out.add(new Arc2(e.center(), a, b, e.k() == 1));
            } else {
                out.add(new Segment2(a, b));
            }
        }
        return out;
    }

    private List<PocketElement> numbered() {
        List<PocketElement> out = new ArrayList<>();
        for (int i = 0; i < elements.size(); i++) {
            out.add(elements.get(i).element(i + 1));
        }
        return out;
    }

    /**
     * The thesis's profile of the contour, exactly as {@link DadReader} builds it from the file.
     *
     * @param source names the contour in messages
     */
    public PocketProfile profile(String source) throws CamInputException {
        if (elements.size() < MIN_ELEMENTS) {
            throw new CamInputException(source, "a contour needs at least " + MIN_ELEMENTS + " records");
        }
        return DadReader.profile(numbered(), source);
    }

    /**
     * The {@code .dad} text: 73-column records, CR LF, the closing element first (next 1), then
     * elements 1 to n - 1; numbers in BASIC's spelling ({@link #basic(double)}).
     */
    public String toDad() {
        int n = elements.size();
        StringBuilder sb = new StringBuilder();
        for (int r = 0; r < n; r++) {
            int i = (r + n - 1) % n;
            DadElement e = elements.get(i);
            sb.append(String.format(
                    Locale.ROOT,
                    "%2d%c%22s%22s%22s%c%c%2d\r\n",
                    i + 1,
                    e.arc() ? 'C' : 'R',
                    basic(e.a()),
                    basic(e.b()),
                    basic(e.d()),
                    e.selector(),
                    e.sense(),
                    (i + 1) % n + 1));
        }
        return sb.toString();
    }

    /**
     * A number as GOTA.BAS's files spell it: BASIC {@code STR$} with 7 significant digits
     * ({@code .2315189}, {@code -43.82693}, {@code 5.255885E-02}, {@code 14}) when those digits
     * read back as the same number; otherwise the shortest decimal that does, so that a written
     * file reads back exactly what was typed.
     */
    public static String basic(double v) {
        if (v == 0) {
            return "0";
        }
        BigDecimal seven = new BigDecimal(v).round(new MathContext(7)).stripTrailingZeros();
        if (seven.doubleValue() == v) {
            return basicSpelling(seven);
        }
        BigDecimal shortest = BigDecimal.valueOf(v).stripTrailingZeros();
        String plain = dropLeadingZero(shortest.toPlainString());
        return plain.length() < FIELD ? plain : shortest.toString();
    }

    private static String basicSpelling(BigDecimal x) {
        String digits = x.unscaledValue().abs().toString();
        int exponent = digits.length() - 1 - x.scale();
        String sign = x.signum() < 0 ? "-" : "";
        // STR$ writes a fixed point while the number fits in 7 digit places, else E notation
        boolean fixed = exponent >= 0 ? exponent < 7 : digits.length() - exponent - 1 <= 7;
        if (fixed) {
            return sign + dropLeadingZero(x.abs().toPlainString());
        }
        String mantissa = digits.length() == 1 ? digits : digits.charAt(0) + "." + digits.substring(1);
        return String.format(Locale.ROOT, "%s%sE%c%02d", sign, mantissa, exponent < 0 ? '-' : '+', Math.abs(exponent));
    }

    private static String dropLeadingZero(String s) {
        if (s.startsWith("0.")) {
            return s.substring(1);
        }
        if (s.startsWith("-0.")) {
            return "-" + s.substring(2);
        }
        return s;
    }
}
