package org.fresa.toolpath;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * {@code toolpath.csv} (spec/cli.md): the tool-tip path in the workpiece frame, one row per
 * point, columns {@code index,workingstep,move,x,y,z,i,j,k,feed}.
 *
 * <ul>
 * <li>index counts rows from 0; workingstep is the section's label (quoted when it holds a
 * comma, quote or line break).
 * <li>Each section begins with a {@code rapid} row at its start point (the posts write a rapid
 * there too), then one row per rapid or straight move ({@code feed}) and, for an arc, one row
 * per chord end at the chord tolerance ({@code arc-cw}/{@code arc-ccw}), the last at the arc's
 * exact end.
 * <li>The arc's sense is the one G02/G03 would have: seen from the tip of the principal axis
 * (+Z, +Y or +X) nearest to the arc's normal.
 * <li>(i,j,k) is the section's tool axis, from tip towards spindle; feed in mm/min, 0 on rapid
 * rows (the machine's traverse rate).
 * <li>A dwell (G04) is a {@code dwell} row at the point where the tool waits, its feed column
 * holding the dwell time in seconds: the columns stay those of the spec and a reader that does
 * not know the kind still sees a zero-length step. Spindle stops and starts have no row: the
 * file has no spindle column and they neither move the tool nor take time in this model.
 * <li>Every number is the shortest decimal that reads back as the same double
 * ({@link ExactDecimal}).
 * </ul>
 */
public final class ToolpathCsv {

    public static final String HEADER = "index,workingstep,move,x,y,z,i,j,k,feed";

    private ToolpathCsv() {}

    /**
     * One row.
     *
     * @param move {@code rapid}, {@code feed}, {@code arc-cw}, {@code arc-ccw} or {@code dwell}
     * @param feedMmPerMin 0 for rapids; for a dwell, its time in seconds
     */
    public record Row(int index, String workingstep, String move, Vec3 point, Vec3 toolAxis, double feedMmPerMin) {}

    /** The rows of a toolpath, arcs split at the chord tolerance (mm, > 0). */
    public static List<Row> rows(Toolpath path, double chordToleranceMm) {
        List<Row> rows = new ArrayList<>();
        for (ToolpathSection s : path.sections()) {
            rows.addAll(rows(s, chordToleranceMm, rows.size()));
        }
        return rows;
    }

    /** The rows of one section, numbered from {@code firstIndex} (the rows of the sections before it). */
    public static List<Row> rows(ToolpathSection s, double chordToleranceMm, int firstIndex) {
        List<Row> rows = new ArrayList<>();
        String ws = s.label();
        Vec3 axis = s.toolAxis();
        rows.add(new Row(firstIndex + rows.size(), ws, "rapid", s.start(), axis, 0));
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            if (m instanceof Move.Rapid r) {
                rows.add(new Row(firstIndex + rows.size(), ws, "rapid", r.end(), axis, 0));
            } else if (m instanceof Move.Linear l) {
                rows.add(new Row(firstIndex + rows.size(), ws, "feed", l.end(), axis, l.feedMmPerMin()));
            } else if (m instanceof Move.Circular c) {
                String kind = gSense(c) ? "arc-ccw" : "arc-cw";
                for (Vec3 p : ArcGeometry.of(at, c).points(chordToleranceMm)) {
                    rows.add(new Row(firstIndex + rows.size(), ws, kind, p, axis, c.feedMmPerMin()));
                }
            } else if (m instanceof Move.Dwell d) {
                rows.add(new Row(firstIndex + rows.size(), ws, "dwell", d.end(), axis, d.seconds()));
            } else if (!(m instanceof Move.SpindleStop) && !(m instanceof Move.SpindleStart)) {
                throw new IllegalStateException("no toolpath.csv row for " + m);
            }
            at = m.end();
        }
        return rows;
    }

    /** True when the arc is a G03 seen from the principal axis nearest its normal. */
    static boolean gSense(Move.Circular c) {
        Vec3 n = c.normal();
        double ax = Math.abs(n.x());
        double ay = Math.abs(n.y());
        double az = Math.abs(n.z());
        double along = az >= ax && az >= ay ? n.z() : (ay >= ax ? n.y() : n.x());
        return c.ccw() == (along > 0);
    }

    /** Writes the header and the rows. */
    public static void write(Toolpath path, double chordToleranceMm, Writer out) throws IOException {
        Sections w = begin(chordToleranceMm, out);
        for (ToolpathSection s : path.sections()) {
            w.section(s);
        }
        out.flush();
    }

    /**
     * Starts the file for a toolpath written a section at a time, for a toolpath too long to
     * hold whole: the header now, each section's rows when it is given.
     */
    public static Sections begin(double chordToleranceMm, Writer out) throws IOException {
        out.write(HEADER);
        out.write('\n');
        return new Sections(chordToleranceMm, out);
    }

    /** The rows of the sections written so far, numbered on from one section to the next. */
    public static final class Sections {
        private final double chordToleranceMm;
        private final Writer out;
        private final StringBuilder sb = new StringBuilder(128);
        private int rows;

        private Sections(double chordToleranceMm, Writer out) {
            this.chordToleranceMm = chordToleranceMm;
            this.out = out;
        }

        /** Writes the section's rows; returns how many. */
        public int section(ToolpathSection s) throws IOException {
            List<Row> these = ToolpathCsv.rows(s, chordToleranceMm, rows);
            for (Row r : these) {
                sb.setLength(0);
                sb.append(r.index())
                        .append(',')
                        .append(quote(r.workingstep()))
                        .append(',')
                        .append(r.move());
                for (double d : new double[] {
                    r.point().x(),
                    r.point().y(),
                    r.point().z(),
                    r.toolAxis().x(),
                    r.toolAxis().y(),
                    r.toolAxis().z(),
                    r.feedMmPerMin()
                }) {
                    ExactDecimal.append(sb.append(','), d);
                }
                out.write(sb.append('\n').toString());
            }
            rows += these.size();
            return these.size();
        }

        /** The rows written so far. */
        public int rows() {
            return rows;
        }
    }

    /** The whole file as text. */
    public static String toText(Toolpath path, double chordToleranceMm) {
        java.io.StringWriter w = new java.io.StringWriter();
        try {
            write(path, chordToleranceMm, w);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return w.toString();
    }

    private static String quote(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }

    /**
     * Reads a {@code toolpath.csv} back (quoted labels without line breaks).
     *
     * @throws CamInputException naming the line of a malformed row
     */
    public static List<Row> read(Reader in, String source) throws IOException, CamInputException {
        BufferedReader r = new BufferedReader(in);
        String header = r.readLine();
        if (header == null || !header.trim().equals(HEADER)) {
            throw new CamInputException(source, 1, 1, "expected the header " + HEADER);
        }
        List<Row> rows = new ArrayList<>();
        String line;
        int n = 1;
        while ((line = r.readLine()) != null) {
            n++;
            if (line.isBlank()) {
                continue;
            }
            List<String> f = split(line);
            if (f.size() != 10) {
                throw new CamInputException(source, n, 1, "expected 10 fields, found " + f.size());
            }
            try {
                rows.add(new Row(
                        Integer.parseInt(f.get(0)),
                        f.get(1),
                        f.get(2),
                        new Vec3(
                                Double.parseDouble(f.get(3)),
                                Double.parseDouble(f.get(4)),
                                Double.parseDouble(f.get(5))),
                        new Vec3(
                                Double.parseDouble(f.get(6)),
                                Double.parseDouble(f.get(7)),
                                Double.parseDouble(f.get(8))),
                        Double.parseDouble(f.get(9))));
            } catch (IllegalArgumentException e) {
                throw new CamInputException(source, n, 1, "not a number: " + e.getMessage());
            }
        }
        return rows;
    }

    private static List<String> split(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char ch = line.charAt(i);
            if (quoted) {
                if (ch == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    cur.append('"');
                    i++;
                } else if (ch == '"') {
                    quoted = false;
                } else {
                    cur.append(ch);
                }
            } else if (ch == '"') {
                quoted = true;
            } else if (ch == ',') {
                out.add(cur.toString());
                cur.setLength(0);
            } else {
                cur.append(ch);
            }
        }
        out.add(cur.toString());
        return out;
    }
}
