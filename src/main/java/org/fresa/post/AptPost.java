package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * APT / CL data (cutter-location source, ISO 4343's statements as the thesis's APT macros write
 * them): {@code PARTNO}, {@code UNITS/MM}, per tool {@code LOADTL/n} and {@code CUTTER/d},
 * {@code SPINDL/rpm,CLW|CCLW} and {@code SPINDL/OFF}, {@code FEDRAT/f,MMPM}, {@code RAPID} before a
 * rapid {@code GOTO/x,y,z}, {@code DELAY/s}, {@code COOLNT/OFF} and {@code FINI} at the end.
 *
 * <p>Arcs stay arcs, in any plane: {@code CIRCLE/xc,yc,zc,i,j,k,r} followed by the {@code GOTO} of
 * the arc's end, the CL-data convention. The tool goes counter-clockwise about the axis (i,j,k)
 * (right hand), so a clockwise arc is written with its normal reversed; the centre is given in the
 * plane through the arc's start (a helix rises from there to the end's height); an end that
 * coincides with the start is a full turn, and each extra turn of a helix is its own
 * {@code CIRCLE}/{@code GOTO} pair, as the posts without a turn word write it.
 *
 * <p>Numbers as the G-code posts write them, so that an APT and a G-code program of the same
 * toolpath describe the same motions to the digit: coordinates with three decimals, the arc's
 * centre as the written start plus the centre offset rounded as a G-code post rounds I/J/K, feeds
 * with one decimal, spindle speeds as integers. {@code Locale.ROOT} throughout.
 */
final class AptPost implements NcPost {

    /** The longest part name PARTNO takes (the card's 72 columns less the word). */
    static final int PARTNO_CHARS = 66;

    @Override
    public String name() {
        return "apt";
    }

    @Override
    public String description() {
        return "APT / CL data: GOTO/, arcs as CIRCLE/ + GOTO/ in any plane, FEDRAT/, SPINDL/, LOADTL/, FINI";
    }

    @Override
    public String fileExtension() {
        return "apt";
    }

    @Override
    public NcPost.Program begin(String programName, Writer out) throws IOException {
        String title = plain(programName);
        Statements p = new Statements(out);
        p.add("PARTNO " + (title.length() > PARTNO_CHARS ? title.substring(0, PARTNO_CHARS) : title));
        p.add("UNITS/MM");
        return p;
    }

    /** The statements of one program as they are written, with the state it has left between sections. */
    private static final class Statements implements NcPost.Program {
        private final Writer out;
        private final List<String> lines = new ArrayList<>();
        private int tool = 0;
        private long rpm = -1;
        private boolean clockwise = true;
        private double feed = -1;

        Statements(Writer out) {
            this.out = out;
        }

        void add(String line) {
            lines.add(line);
        }

        /** Writes the statements gathered since the last call. */
        private void drain() throws IOException {
            for (String l : lines) {
                out.write(l);
                out.write('\n');
            }
            lines.clear();
        }

        @Override
        public void section(ToolpathSection s) throws IOException {
            lines.add("$$ " + plain(s.label()) + " tool " + s.toolNumber() + " D" + num(s.toolDiameterMm()));
            if (s.toolAxis().distance(Vec3.UNIT_Z) > 1e-9) {
                lines.add("$$ tool axis " + num(s.toolAxis().x()) + " "
                        + num(s.toolAxis().y()) + " " + num(s.toolAxis().z())
                        + " is not +Z: needs the part turned or a spindle along this axis");
            }
            if (s.toolNumber() != tool) {
                lines.add("SPINDL/OFF");
                lines.add("LOADTL/" + s.toolNumber());
                lines.add("CUTTER/" + num(s.toolDiameterMm()));
                tool = s.toolNumber();
                rpm = -1;
                feed = -1;
            }
            long sRpm = Math.round(s.spindleRpm());
            if (sRpm > 0 && (sRpm != rpm || !clockwise)) {
                lines.add(spindle(sRpm, true));
                rpm = sRpm;
                clockwise = true;
            }
            lines.add("RAPID");
            lines.add("GOTO/" + xyz(s.start()));
            Vec3 at = s.start();
            for (Move m : s.moves()) {
                if (m instanceof Move.Rapid r) {
                    lines.add("RAPID");
                    lines.add("GOTO/" + xyz(r.end()));
                } else if (m instanceof Move.Linear l) {
                    feed = feed(lines, l.feedMmPerMin(), feed);
                    lines.add("GOTO/" + xyz(l.end()));
                } else if (m instanceof Move.Circular c) {
                    feed = feed(lines, c.feedMmPerMin(), feed);
                    arc(lines, at, c);
                } else if (m instanceof Move.Dwell d) {
                    lines.add("DELAY/" + GcodePost.seconds(d.seconds()));
                } else if (m instanceof Move.SpindleStop) {
                    lines.add("SPINDL/OFF");
                    rpm = -1;
                } else if (m instanceof Move.SpindleStart on) {
                    rpm = Math.round(on.rpm());
                    clockwise = on.clockwise();
                    lines.add(spindle(rpm, clockwise));
                } else {
                    throw new IllegalStateException("no APT statement for " + m);
                }
                at = m.end();
            }
            drain();
        }

        @Override
        public void end() throws IOException {
            lines.add("SPINDL/OFF");
            lines.add("COOLNT/OFF");
            lines.add("FINI");
            drain();
            out.flush();
        }
    }

    private static String spindle(long rpm, boolean clockwise) {
        return "SPINDL/" + rpm + (clockwise ? ",CLW" : ",CCLW");
    }

    private static double feed(List<String> lines, double f, double current) {
        if (f != current) {
            lines.add("FEDRAT/" + String.format(Locale.ROOT, "%.1f", f) + ",MMPM");
        }
        return f;
    }

    /** One CIRCLE/GOTO pair per turn: the extra full turns first (a helix rising in proportion), then the end. */
    private static void arc(List<String> lines, Vec3 start, Move.Circular c) {
        Vec3 n = c.ccw() ? c.normal() : c.normal().negated();
        ArcGeometry geo = ArcGeometry.of(start, c);
        Vec3 from = start;
        if (c.turns() > 0) {
            double perTurn = 2 * Math.PI / Math.abs(geo.sweepRad());
            for (int k = 1; k <= c.turns(); k++) {
                Vec3 q = start.plus(c.normal().times(geo.riseMm() * perTurn * k));
                lines.add(circle(from, q, c.center(), c.normal(), n));
                lines.add("GOTO/" + xyz(q));
                from = q;
            }
        }
        lines.add(circle(from, c.end(), c.center(), c.normal(), n));
        lines.add("GOTO/" + xyz(c.end()));
    }

    /**
     * The CIRCLE statement of an arc from {@code from} to {@code to}: the centre in the plane
     * through the start, written as the rounded start plus the rounded offset (the centre a G-code
     * post's I/J/K give), the radius the mean of the distances from that centre to the written
     * start and end. Rounded to the micrometre, the start, the end and the centre each move up to
     * 0.7 um in the plane: a radius taken to the start alone left the end up to 2.6 um off the
     * circle, more than a reader allows (2 um); the mean leaves each at most half of that.
     */
    private static String circle(Vec3 from, Vec3 to, Vec3 center, Vec3 planeNormal, Vec3 axis) {
        Vec3 onPlane = center.plus(planeNormal.times(from.minus(center).dot(planeNormal)));
        Vec3 off = onPlane.minus(from);
        double cx = round(from.x()) + round(off.x());
        double cy = round(from.y()) + round(off.y());
        double cz = round(from.z()) + round(off.z());
        Vec3 c = new Vec3(cx, cy, cz);
        double toStart = inPlane(new Vec3(round(from.x()), round(from.y()), round(from.z())).minus(c), planeNormal);
        double toEnd = inPlane(new Vec3(round(to.x()), round(to.y()), round(to.z())).minus(c), planeNormal);
        return "CIRCLE/" + num(cx) + "," + num(cy) + "," + num(cz) + "," + unit(axis.x()) + "," + unit(axis.y()) + ","
                + unit(axis.z()) + "," + num((toStart + toEnd) / 2);
    }

    /** The length of v's part in the plane of the normal. */
    private static double inPlane(Vec3 v, Vec3 planeNormal) {
        return v.minus(planeNormal.times(v.dot(planeNormal))).norm();
    }

    private static double round(double v) {
        return Double.parseDouble(num(v));
    }

    private static String xyz(Vec3 v) {
        return num(v.x()) + "," + num(v.y()) + "," + num(v.z());
    }

    /** A coordinate with three decimals, never "-0.000". */
    static String num(double v) {
        return GcodePost.fixed(v, 3);
    }

    /** A component of a unit vector: six decimals, trailing zeros dropped ("0", "1", "-0.707107"). */
    static String unit(double v) {
        String s = String.format(Locale.ROOT, "%.6f", v).replaceFirst("\\.?0+$", "");
        return s.equals("-0") ? "0" : s;
    }

    /** Text safe in a PARTNO or a $$ comment: printable ASCII, no $ (the continuation mark). */
    static String plain(String text) {
        StringBuilder sb = new StringBuilder();
        for (char ch : text.toCharArray()) {
            sb.append(ch >= 32 && ch < 127 && ch != '$' ? ch : '_');
        }
        return sb.toString();
    }
}
