package org.fresa.pocket;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.fresa.model.CamInputException;

/**
 * Reads the thesis's {@code .dad} files (Appendix B): one 73-column record per element, columns
 * 1-2 number, 3 type (R line, C circle), 4-25 A or centre x, 26-47 B or centre y, 48-69 D or
 * radius, 70 selector S/L, 71 arc sense F (convex) / M (concave), 72-73 next element. The first
 * record is the closing element N (next 1). Numbers are BASIC {@code STR$} text ({@code .2315189},
 * {@code -.565}, {@code 5.255885E-02}); line coefficients are kept raw. CR LF or LF line ends;
 * blank lines are ignored; short records are read as if padded with blanks.
 */
public final class DadReader {

    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([EeDd][+-]?\\d+)?");

    private DadReader() {}

    /** Parses the text of a {@code .dad} file; source names the file in messages. */
    public static PocketProfile read(String text, String source) throws CamInputException {
        Parsed p = parse(text, source);
        List<PocketElement> loop = new ArrayList<>();
        for (int i = 0; i < p.loop().size(); i++) {
            loop.add(p.loop().get(i).element(p.numbers().get(i)));
        }
        return profile(loop, source);
    }

    /**
     * The records of a {@code .dad} file as they are typed in the Pocket tab's contour editor: in
     * the order of travel from the element the closing element leads to, numbered from 1 there.
     */
    public static DadContour contour(String text, String source) throws CamInputException {
        List<DadElement> loop = parse(text, source).loop();
        if (loop.size() > DadContour.MAX_ELEMENTS) {
            throw new CamInputException(source, "a contour has at most " + DadContour.MAX_ELEMENTS + " records");
        }
        return new DadContour(loop);
    }

    /** The profile of numbered elements in the order of travel: the thesis's COMPAR and the lines' k. */
    static PocketProfile profile(List<PocketElement> loop, String source) throws CamInputException {
        double compar = PocketProfile.comparOf(loop);
        List<PocketElement> withK = PocketProfile.withLineDirections(loop, compar)
                .orElseThrow(() -> new CamInputException(source, "consecutive elements do not intersect"));
        return new PocketProfile(withK, compar, List.of());
    }

    /** The records in the order of travel with their numbers in the file. */
    private record Parsed(List<DadElement> loop, List<Integer> numbers) {}

    private static Parsed parse(String text, String source) throws CamInputException {
        String[] lines = text.split("\r?\n|\r", -1);
        Map<Integer, DadElement> byNumber = new HashMap<>();
        Map<Integer, Integer> next = new HashMap<>();
        Map<Integer, Integer> lineOf = new HashMap<>();
        List<Integer> order = new ArrayList<>();
        for (int li = 0; li < lines.length; li++) {
            String raw = lines[li];
            if (raw.isBlank()) {
                continue;
            }
            int lineNo = li + 1;
            if (raw.length() > 73 && !raw.substring(73).isBlank()) {
                throw new CamInputException(source, lineNo, 74, "record longer than 73 columns");
            }
            String r = String.format("%-73s", raw);
            int number = integer(r, 0, 2, source, lineNo, "element number");
            char type = r.charAt(2);
            if (type != 'R' && type != 'C') {
                throw new CamInputException(
                        source, lineNo, 3, "element type must be R (line) or C (circle), found '" + type + "'");
            }
            double f1 = number(r, 3, 25, source, lineNo, type == 'R' ? "A = sin(k)" : "centre x");
            double f2 = number(r, 25, 47, source, lineNo, type == 'R' ? "B = cos(k)" : "centre y");
            double f3 = number(r, 47, 69, source, lineNo, type == 'R' ? "D" : "radius");
            char sel = r.charAt(69);
            if (sel != ' ' && sel != 'S' && sel != 'L') {
                throw new CamInputException(source, lineNo, 70, "selector must be S, L or blank, found '" + sel + "'");
            }
            char sense = r.charAt(70);
            if (type == 'C') {
                if (sense != 'F' && sense != 'M') {
                    throw new CamInputException(
                            source, lineNo, 71, "arc sense must be F (convex) or M (concave), found '" + sense + "'");
                }
                if (!(f3 >= 0)) {
                    throw new CamInputException(source, lineNo, 48, "radius must be >= 0");
                }
            } else {
                if (sense != ' ') {
                    throw new CamInputException(source, lineNo, 71, "a line has no arc sense, found '" + sense + "'");
                }
                if (f1 == 0 && f2 == 0) {
                    throw new CamInputException(source, lineNo, 4, "line coefficients A and B are both zero");
                }
            }
            int nx = integer(r, 71, 73, source, lineNo, "next element number");
            if (byNumber.containsKey(number)) {
                throw new CamInputException(source, lineNo, 1, "element " + number + " appears twice");
            }
            byNumber.put(number, new DadElement(type == 'C', f1, f2, f3, sel, sense));
            next.put(number, nx);
            lineOf.put(number, lineNo);
            order.add(number);
        }
        if (order.size() < 2) {
            throw new CamInputException(source, Math.max(1, lines.length), 1, "a contour needs at least 2 records");
        }
        int first = order.get(1);
        int closing = order.get(0);
        if (next.get(closing) != first) {
            throw new CamInputException(
                    source,
                    lineOf.get(closing),
                    72,
                    "the first record is the closing element, whose next element must be " + first);
        }
        List<DadElement> loop = new ArrayList<>();
        List<Integer> numbers = new ArrayList<>();
        int cur = first;
        for (int i = 0; i < order.size(); i++) {
            loop.add(byNumber.get(cur));
            numbers.add(cur);
            int nx = next.get(cur);
            if (!byNumber.containsKey(nx)) {
                throw new CamInputException(source, lineOf.get(cur), 72, "next element " + nx + " does not exist");
            }
            cur = nx;
        }
        if (cur != first || numbers.stream().distinct().count() != order.size()) {
            throw new CamInputException(
                    source, lineOf.get(closing), 72, "the next-element numbers do not form one closed contour");
        }
        return new Parsed(loop, numbers);
    }

    private static int integer(String r, int from, int to, String source, int line, String what)
            throws CamInputException {
        String s = r.substring(from, to).trim();
        if (!s.matches("\\d+")) {
            throw new CamInputException(
                    source,
                    line,
                    from + 1,
                    what + " expected in columns " + (from + 1) + "-" + to + ", found '" + s + "'");
        }
        return Integer.parseInt(s);
    }

    private static double number(String r, int from, int to, String source, int line, String what)
            throws CamInputException {
        String s = r.substring(from, to).trim();
        if (!NUMBER.matcher(s).matches()) {
            throw new CamInputException(
                    source,
                    line,
                    from + 1,
                    what + " expected in columns " + (from + 1) + "-" + to + ", found '" + s + "'");
        }
        double v = Double.parseDouble(s.replace('D', 'E').replace('d', 'e'));
        // a pocket is smaller than a kilometre; larger values overflow the squares of the geometry
        if (!Double.isFinite(v) || Math.abs(v) > 1e6) {
            throw new CamInputException(source, line, from + 1, what + " out of range (|value| <= 1e6 mm): " + s);
        }
        return v;
    }
}
