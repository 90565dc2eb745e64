package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Function;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * The shared body of the word-address G-code posts (ISO 6983 family): a safe start block,
 * per section a comment, tool change and spindle start when they change, a rapid to the
 * section's start, its moves, then a safe end block. The {@link Dialect} gives the control's words
 * (block numbers, comments, tool change, spindle, dwell, turns), the {@link Frame} the program's
 * start and end; {@link NcPosts} names the posts.
 *
 * <p>Conventions shared by every dialect here:
 * <ul>
 * <li>Coordinates are written in the toolpath's frame as absolute values (G90) in mm, always
 * all three axes, with a fixed number of decimals ({@link #decimals()}, 3 for mm) and
 * {@code Locale.ROOT}; feeds with one decimal, spindle speeds as integers.
 * <li>Every section begins with a rapid to its {@code start} (one block), so the program's
 * motions are exactly: per section, the start then the moves. The generators put the start at
 * the security plane, so this diagonal rapid after a tool change is above the part.
 * <li>Arcs whose normal is along +-Z, +-Y, +-X are written as G02/G03 in G17, G18, G19 with
 * incremental centre words (I, J, K from the start point); a normal along a negative axis
 * flips the sense. A helix is the same block with the third axis changed. Arcs in any other
 * plane are replaced by straight G01 chords within {@link #chordToleranceMm()} of the arc.
 * <li>Dwells are the dialect's dwell block with the time in seconds ({@link #dwell}); spindle
 * stops and starts inside a section are M5 and S.. M3/M4 blocks, and a section whose spindle
 * was stopped starts it again even at an unchanged speed.
 * <li>Extra full turns use the dialect's turn word when it has one ({@link Dialect#turnsWord}),
 * otherwise each turn is written as its own full-circle block.
 * <li>The tool axis of a section is not used for motion: a 3-axis machine has its spindle along
 * +Z. A section whose axis is not +Z is written as is with a comment saying so.
 * </ul>
 */
final class GcodePost implements NcPost {

    /**
     * What a program holds besides its moves, the same for every toolpath of a post.
     *
     * @param header lines before the first numbered block (tape start, program number), unnumbered,
     *     of the program's name
     * @param safeStart the safe start block(s): units, absolute, plane, cancellations
     * @param safeEnd blocks of the safe end: stop the spindle, cancel modes, end the program
     * @param trailer lines after the last numbered block (tape end), unnumbered
     */
    record Frame(
            Function<String, List<String>> header, List<String> safeStart, List<String> safeEnd, List<String> trailer) {
        Frame {
            safeStart = List.copyOf(safeStart);
            safeEnd = List.copyOf(safeEnd);
            trailer = List.copyOf(trailer);
        }
    }

    /** Chord tolerance for arcs outside the three principal planes, in mm. */
    public static final double DEFAULT_CHORD_TOLERANCE_MM = 0.001;

    private final String name;
    private final String description;
    private final Dialect dialect;
    private final Frame frame;
    private final double chordToleranceMm;

    GcodePost(String name, String description, Dialect dialect, Frame frame, double chordToleranceMm) {
        this.name = name;
        this.description = description;
        this.dialect = java.util.Objects.requireNonNull(dialect, "dialect");
        this.frame = java.util.Objects.requireNonNull(frame, "frame");
        if (!(chordToleranceMm > 0)) {
            throw new IllegalArgumentException("chord tolerance must be > 0: " + chordToleranceMm);
        }
        this.chordToleranceMm = chordToleranceMm;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public String description() {
        return description;
    }

    /** Chord tolerance used for arcs outside the principal planes (mm). */
    public double chordToleranceMm() {
        return chordToleranceMm;
    }

    /** Decimals for coordinates and centre offsets. */
    int decimals() {
        return 3;
    }

    /** The dialect's words. */
    public Dialect dialect() {
        return dialect;
    }

    /**
     * A whole comment block in the dialect's syntax; upper case on a Fanuc, whose tape code has no
     * lower-case letters.
     */
    String comment(String text) {
        String t = plain(text);
        return dialect.comment(dialect == Dialect.FANUC ? t.toUpperCase(Locale.ROOT) : t);
    }

    /** The block of a dwell of the given time, in seconds written with {@link #seconds(double)}. */
    private String dwell(double seconds) {
        return dialect.dwell(seconds(seconds));
    }

    /** A time in seconds with three decimals (the controls' millisecond resolution), Locale.ROOT. */
    static String seconds(double s) {
        return String.format(Locale.ROOT, "%.3f", s);
    }

    @Override
    public NcPost.Program begin(String programName, Writer out) throws IOException {
        Blocks p = new Blocks(dialect.numbered(), out);
        for (String h : frame.header().apply(programName)) {
            p.raw(h);
        }
        p.raw(comment(programName));
        for (String b : frame.safeStart()) {
            p.block(b);
        }
        return new Sections(p);
    }

    /** The sections of one program, with the modal state the program has left between them. */
    private final class Sections implements NcPost.Program {
        private final Blocks p;
        private int tool = 0;
        // the spindle as the program has left it: -1 when stopped or unknown
        private long rpm = -1;
        private boolean clockwise = true;
        private Plane plane = Plane.XY;
        private double feed = -1;

        Sections(Blocks p) {
            this.p = p;
        }

        @Override
        public void section(ToolpathSection s) throws IOException {
            p.raw(comment(s.label() + " tool " + s.toolNumber() + " D" + num(s.toolDiameterMm())));
            if (s.toolAxis().distance(Vec3.UNIT_Z) > 1e-9) {
                p.raw(comment("tool axis " + num(s.toolAxis().x()) + " "
                        + num(s.toolAxis().y()) + " " + num(s.toolAxis().z())
                        + " is not +Z: needs the part turned or a spindle along this axis"));
            }
            if (s.toolNumber() != tool) {
                for (String b : dialect.toolChange(s.toolNumber())) {
                    p.block(b);
                }
                tool = s.toolNumber();
                rpm = -1;
                feed = -1;
            }
            long sRpm = Math.round(s.spindleRpm());
            if (sRpm > 0 && (sRpm != rpm || !clockwise)) {
                p.block(dialect.spindleOn(sRpm, true));
                rpm = sRpm;
                clockwise = true;
            }
            p.block("G0 " + xyz(s.start()));
            Vec3 at = s.start();
            for (Move m : s.moves()) {
                if (m instanceof Move.Rapid r) {
                    p.block("G0 " + xyz(r.end()));
                } else if (m instanceof Move.Linear l) {
                    p.block("G1 " + xyz(l.end()) + feedWord(l.feedMmPerMin(), feed));
                    feed = l.feedMmPerMin();
                } else if (m instanceof Move.Circular c) {
                    plane = arc(p, at, c, plane, feed);
                    feed = c.feedMmPerMin();
                } else if (m instanceof Move.Dwell d) {
                    p.block(dwell(d.seconds()));
                } else if (m instanceof Move.SpindleStop) {
                    p.block(dialect.spindleOff());
                    rpm = -1;
                } else if (m instanceof Move.SpindleStart on) {
                    rpm = Math.round(on.rpm());
                    clockwise = on.clockwise();
                    p.block(dialect.spindleOn(rpm, clockwise));
                } else {
                    throw new IllegalStateException("no G-code for " + m);
                }
                at = m.end();
            }
        }

        @Override
        public void end() throws IOException {
            if (plane != Plane.XY) {
                p.block("G17");
            }
            for (String b : frame.safeEnd()) {
                p.block(b);
            }
            for (String t : frame.trailer()) {
                p.raw(t);
            }
            p.flush();
        }
    }

    private Plane arc(Blocks p, Vec3 start, Move.Circular c, Plane current, double feed) throws IOException {
        Optional<Plane> found = Plane.of(c.normal());
        if (found.isEmpty()) {
            ArcGeometry g = ArcGeometry.of(start, c);
            boolean first = true;
            for (Vec3 q : g.points(chordToleranceMm)) {
                p.block("G1 " + xyz(q) + (first ? feedWord(c.feedMmPerMin(), feed) : ""));
                first = false;
            }
            return current;
        }
        Plane plane = found.get();
        boolean ccw = c.ccw() == plane.positive(c.normal());
        String g = ccw ? "G3" : "G2";
        String prefix = plane == current ? "" : plane.word + " ";
        Vec3 off = c.center().minus(start);
        String centre = plane.centreWords(off, this);
        Optional<String> turns = c.turns() == 0 ? Optional.of("") : dialect.turnsWord(c.turns());
        if (turns.isPresent()) {
            String t = turns.get().isEmpty() ? "" : " " + turns.get();
            p.block(prefix + g + " " + xyz(c.end()) + " " + centre + t + feedWord(c.feedMmPerMin(), feed));
            return plane;
        }
        // no turn word: one full-circle block per extra turn, rising in proportion to the angle
        ArcGeometry geo = ArcGeometry.of(start, c);
        double perTurn = 2 * Math.PI / Math.abs(geo.sweepRad());
        boolean first = true;
        for (int k = 1; k <= c.turns(); k++) {
            Vec3 q = start.plus(c.normal().times(geo.riseMm() * perTurn * k));
            p.block((first ? prefix : "") + g + " " + xyz(q) + " " + centre
                    + (first ? feedWord(c.feedMmPerMin(), feed) : ""));
            first = false;
            off = c.center().minus(q);
            centre = plane.centreWords(off, this);
        }
        p.block(g + " " + xyz(c.end()) + " " + centre);
        return plane;
    }

    private String feedWord(double f, double current) {
        return f == current ? "" : " F" + String.format(Locale.ROOT, "%.1f", f);
    }

    String xyz(Vec3 v) {
        return "X" + num(v.x()) + " Y" + num(v.y()) + " Z" + num(v.z());
    }

    /** A coordinate with the dialect's fixed decimals, never "-0.000". */
    String num(double v) {
        return fixed(v, decimals());
    }

    /** A number with fixed decimals, never a negative zero ("-0.000" is written "0.000"). */
    static String fixed(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        if (s.startsWith("-") && s.chars().skip(1).allMatch(ch -> ch == '0' || ch == '.')) {
            return s.substring(1);
        }
        return s;
    }

    /** Text safe inside a parenthesised comment: no parentheses, printable ASCII only. */
    static String plain(String text) {
        StringBuilder sb = new StringBuilder();
        for (char ch : text.toCharArray()) {
            if (ch == '(' || ch == ')') {
                sb.append(ch == '(' ? '[' : ']');
            } else if (ch >= 32 && ch < 127) {
                sb.append(ch);
            } else {
                sb.append('_');
            }
        }
        return sb.toString();
    }

    /** The principal planes: their G word and the centre words of an arc in them. */
    enum Plane {
        XY("G17", Vec3.UNIT_Z),
        XZ("G18", Vec3.UNIT_Y),
        YZ("G19", Vec3.UNIT_X);

        final String word;
        final Vec3 axis;

        Plane(String word, Vec3 axis) {
            this.word = word;
            this.axis = axis;
        }

        static Optional<Plane> of(Vec3 normal) {
            for (Plane p : values()) {
                if (normal.distance(p.axis) <= 1e-9 || normal.distance(p.axis.negated()) <= 1e-9) {
                    return Optional.of(p);
                }
            }
            return Optional.empty();
        }

        boolean positive(Vec3 normal) {
            return normal.dot(axis) > 0;
        }

        String centreWords(Vec3 off, GcodePost post) {
            return switch (this) {
                case XY -> "I" + post.num(off.x()) + " J" + post.num(off.y());
                case XZ -> "I" + post.num(off.x()) + " K" + post.num(off.z());
                case YZ -> "J" + post.num(off.y()) + " K" + post.num(off.z());
            };
        }
    }

    /** The program's lines as they are written, with block numbers when the dialect wants them. */
    static final class Blocks {
        private final boolean numbered;
        private final Writer out;
        private int n;

        Blocks(boolean numbered, Writer out) {
            this.numbered = numbered;
            this.out = out;
        }

        void raw(String line) throws IOException {
            out.write(line);
            out.write('\n');
        }

        void block(String words) throws IOException {
            if (numbered) {
                // RS274/NGC and Fanuc take at most five digits; N words are labels, so repeating is harmless
                n = n >= 99990 ? 10 : n + 10;
                out.write("N" + n + " ");
            }
            raw(words);
        }

        void flush() throws IOException {
            out.flush();
        }
    }
}
