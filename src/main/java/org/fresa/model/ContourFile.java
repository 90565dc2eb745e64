package org.fresa.model;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * Fresa's own contour format ({@code .contour}), plain text in mm:
 *
 * <pre>
 * # a comment (also after a statement)
 * contour                  starts a closed contour; the first is the outer one, later ones islands
 * move X Y                 the start point
 * line X Y                 a straight element to (X, Y)
 * arc CX CY X Y ccw|cw     a circular element about (CX, CY) to (X, Y)
 * </pre>
 *
 * Each contour must end where it started (within 1e-6 mm); arcs must keep their radius (within
 * 1e-6 mm). A full circle is one {@code arc} back to the start point.
 */
public final class ContourFile {

    private static final Tolerance TOL = Tolerance.DEFAULT;

    private ContourFile() {}

    /**
     * Reads every contour of the text.
     *
     * @param source the file name for messages
     * @throws CamInputException with the line and what was expected
     */
    public static List<Contour> read(Reader in, String source) throws CamInputException {
        List<Contour> out = new ArrayList<>();
        List<Curve2> curves = null;
        Vec2 first = null;
        Vec2 at = null;
        int contourLine = 0;
        int lineNo = 0;
        try (BufferedReader r = new BufferedReader(in)) {
            String line;
            while ((line = r.readLine()) != null) {
                lineNo++;
                int hash = line.indexOf('#');
                String text = (hash >= 0 ? line.substring(0, hash) : line).trim();
                if (text.isEmpty()) {
                    continue;
                }
                String[] w = text.split("\\s+");
                String kw = w[0].toLowerCase(Locale.ROOT);
                switch (kw) {
                    case "contour" -> {
                        if (curves != null) {
                            out.add(close(curves, first, at, source, contourLine));
                        }
                        curves = new ArrayList<>();
                        first = null;
                        at = null;
                        contourLine = lineNo;
                    }
                    case "move" -> {
                        expectContour(curves, source, lineNo);
                        if (first != null) {
                            throw new CamInputException(
                                    source, lineNo, 1, "a contour has one 'move'; start a new 'contour' first");
                        }
                        first = point(w, 1, source, lineNo, "move X Y");
                        at = first;
                        expectCount(w, 3, source, lineNo, "move X Y");
                    }
                    case "line" -> {
                        expectStarted(curves, at, source, lineNo);
                        expectCount(w, 3, source, lineNo, "line X Y");
                        Vec2 to = point(w, 1, source, lineNo, "line X Y");
                        if (to.eq(at, TOL)) {
                            throw new CamInputException(source, lineNo, 1, "zero-length line");
                        }
                        curves.add(new Segment2(at, to));
                        at = to;
                    }
                    case "arc" -> {
                        expectStarted(curves, at, source, lineNo);
                        expectCount(w, 6, source, lineNo, "arc CX CY X Y ccw|cw");
                        Vec2 c = point(w, 1, source, lineNo, "arc CX CY X Y ccw|cw");
                        Vec2 to = point(w, 3, source, lineNo, "arc CX CY X Y ccw|cw");
                        String sense = w[5].toLowerCase(Locale.ROOT);
                        if (!sense.equals("ccw") && !sense.equals("cw")) {
                            throw new CamInputException(source, lineNo, 0, "expected ccw or cw, found '" + w[5] + "'");
                        }
                        double r1 = c.distance(at);
                        double r2 = c.distance(to);
                        if (!(r1 > TOL.linear()) || !TOL.eq(r1, r2)) {
                            throw new CamInputException(
                                    source,
                                    lineNo,
                                    0,
                                    String.format(
                                            Locale.ROOT,
                                            "arc radius at start %.6f and at end %.6f differ (or are zero)",
                                            r1,
                                            r2));
                        }
                        curves.add(new Arc2(c, at, to.eq(at, TOL) ? at : to, sense.equals("ccw")));
                        at = to.eq(at, TOL) ? at : to;
                    }
                    default ->
                        throw new CamInputException(
                                source, lineNo, 1, "expected contour, move, line or arc, found '" + w[0] + "'");
                }
            }
        } catch (IOException e) {
            throw new CamInputException(source, "cannot read (" + e.getMessage() + ")");
        }
        if (curves != null) {
            out.add(close(curves, first, at, source, contourLine));
        }
        if (out.isEmpty()) {
            throw new CamInputException(source, lineNo, 0, "no contour found (expected a line 'contour')");
        }
        return out;
    }

    private static Contour close(List<Curve2> curves, Vec2 first, Vec2 at, String source, int line)
            throws CamInputException {
        if (curves.isEmpty()) {
            throw new CamInputException(source, line, 0, "empty contour (expected move, then line or arc)");
        }
        if (!at.eq(first, TOL)) {
            throw new CamInputException(
                    source,
                    line,
                    0,
                    String.format(
                            Locale.ROOT,
                            "contour does not close: it ends at (%s, %s), expected its start (%s, %s)",
                            ExactDecimal.of(at.x()),
                            ExactDecimal.of(at.y()),
                            ExactDecimal.of(first.x()),
                            ExactDecimal.of(first.y())));
        }
        return new Contour(curves);
    }

    private static void expectContour(List<Curve2> curves, String source, int line) throws CamInputException {
        if (curves == null) {
            throw new CamInputException(source, line, 1, "expected 'contour' before the first element");
        }
    }

    private static void expectStarted(List<Curve2> curves, Vec2 at, String source, int line) throws CamInputException {
        expectContour(curves, source, line);
        if (at == null) {
            throw new CamInputException(source, line, 1, "expected 'move X Y' before the first element");
        }
    }

    private static void expectCount(String[] w, int n, String source, int line, String form) throws CamInputException {
        if (w.length != n) {
            throw new CamInputException(source, line, 0, "expected '" + form + "'");
        }
    }

    private static Vec2 point(String[] w, int i, String source, int line, String form) throws CamInputException {
        if (w.length < i + 2) {
            throw new CamInputException(source, line, 0, "expected '" + form + "'");
        }
        return Vec2.of(number(w[i], source, line), number(w[i + 1], source, line));
    }

    private static double number(String s, String source, int line) throws CamInputException {
        try {
            double d = Double.parseDouble(s);
            if (!Double.isFinite(d) || Math.abs(d) > 1e9) {
                throw new CamInputException(source, line, 0, "number out of range: " + s);
            }
            return d;
        } catch (NumberFormatException e) {
            throw new CamInputException(source, line, 0, "expected a number, found '" + s + "'");
        }
    }

    /** Writes contours in this format (exact numbers), the inverse of {@link #read}. */
    public static String write(List<Contour> contours) {
        StringBuilder sb = new StringBuilder("# Fresa contour, mm\n");
        for (Contour c : contours) {
            sb.append("contour\n");
            Vec2 s = c.get(0).start();
            sb.append("move ").append(xy(s)).append('\n');
            for (Curve2 k : c.curves()) {
                if (k instanceof Segment2 seg) {
                    sb.append("line ").append(xy(seg.end())).append('\n');
                } else {
                    Arc2 a = (Arc2) k;
                    sb.append("arc ")
                            .append(xy(a.center()))
                            .append(' ')
                            .append(xy(a.end()))
                            .append(a.ccw() ? " ccw" : " cw")
                            .append('\n');
                }
            }
        }
        return sb.toString();
    }

    /** A point as this format writes it: exact x and y, a space apart. */
    private static String xy(Vec2 p) {
        return ExactDecimal.of(p.x()) + " " + ExactDecimal.of(p.y());
    }
}
