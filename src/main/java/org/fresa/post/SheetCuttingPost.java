package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * Programs for sheet cutting machines (plasma, laser, waterjet): each section of the toolpath is
 * one pierce. The rapid moves of a section come first; the jet is switched on before its first
 * feed move, followed by the pierce dwell, and off after its last. Arcs are G02/G03 with I, J
 * relative to the arc start; coordinates absolute, millimetres, {@code Locale.ROOT}.
 *
 * <p>Dialects: {@code linuxcnc} (jet codes M3 S1/M5 for plasma, M64/M65 digital outputs P0 for
 * laser and P1 for waterjet, G4 P seconds), {@code iso} and {@code fanuc} (N numbers, O number,
 * M07/M08 jet, G04 X seconds with a decimal point for both), {@code 840d} (N numbers, {@code ;} comments, G4 F seconds).
 * Controller compensation: a section marked 41 or 42 switches G41/G42 on at its first feed move
 * (the lead-in, a straight line) and G40 off after its last.
 */
public final class SheetCuttingPost {

    /**
     * What the program needs besides the moves.
     *
     * @param process plasma, laser or waterjet (chooses the jet codes)
     * @param pierceDwellS dwell after the jet is switched on
     * @param compensation per section: 0 none, 41 left, 42 right
     * @param toolDiameterMm the kerf, for the D word of G41/G42 and the header comment
     */
    public record Job(String process, double pierceDwellS, List<Integer> compensation, double toolDiameterMm) {
        public Job {
            compensation = List.copyOf(compensation);
        }
    }

    private final Dialect d;
    private int n;

    private SheetCuttingPost(Dialect d) {
        this.d = d;
    }

    /** Writes the whole program. */
    public static void write(Toolpath path, String programName, Job job, CuttingPost post, Writer out)
            throws IOException {
        write(path.sections(), programName, job, post, out);
    }

    /**
     * Writes the whole program block by block as the sections come: a section is needed only while
     * its blocks are written, so a sheet of any size is posted without its toolpath held whole.
     */
    public static void write(
            Iterable<ToolpathSection> sections, String programName, Job job, CuttingPost post, Writer out)
            throws IOException {
        new SheetCuttingPost(post.dialect()).run(sections, programName, job, out);
    }

    private void run(Iterable<ToolpathSection> sections, String programName, Job job, Writer out) throws IOException {
        String[] jet = jetCodes(job.process());
        String name = programName.replaceAll("[^A-Za-z0-9 ._-]", "_");
        boolean anyComp = job.compensation().stream().anyMatch(c -> c != 0);
        switch (d) {
            case LINUXCNC -> {
                line(out, "(" + name + ": " + job.process() + ", kerf " + num(job.toolDiameterMm()) + " mm)");
                line(out, "G21 G90 G17 G40 G94");
                if (anyComp) {
                    line(out, "T1 M6");
                }
            }
            case ISO, FANUC -> {
                out.write("%\n");
                out.write("O0001 (" + name.toUpperCase(Locale.ROOT) + ")\n");
                line(out, "G21 G90 G17 G40 G94");
            }
            case SIEMENS_840D -> {
                out.write("; " + name + ": " + job.process() + "\n");
                line(out, "G71 G90 G17 G40 G94");
            }
        }
        Vec3 at = Vec3.ZERO;
        double feed = -1;
        int s = -1;
        for (ToolpathSection sec : sections) {
            s++;
            int comp = s < job.compensation().size() ? job.compensation().get(s) : 0;
            comment(out, sec.label());
            boolean on = false;
            int lastFeed = -1;
            for (int k = 0; k < sec.moves().size(); k++) {
                Move mk = sec.moves().get(k);
                if (mk instanceof Move.Linear || mk instanceof Move.Circular) {
                    lastFeed = k;
                }
            }
            for (int k = 0; k < sec.moves().size(); k++) {
                Move m = sec.moves().get(k);
                if (m instanceof Move.SpindleStop || m instanceof Move.SpindleStart) {
                    throw new IllegalArgumentException("a sheet-cutting head has no spindle: " + m);
                }
                if (m instanceof Move.Rapid r) {
                    line(out, "G0 X" + num(r.end().x()) + " Y" + num(r.end().y()));
                } else if (m instanceof Move.Dwell w) {
                    line(out, dwell(w.seconds()));
                } else {
                    String pre = "";
                    if (!on) {
                        line(out, jet[0]);
                        if (job.pierceDwellS() > 0) {
                            line(out, dwell(job.pierceDwellS()));
                        }
                        on = true;
                        if (comp != 0) {
                            pre = d == Dialect.LINUXCNC ? "G" + comp + " " : "G" + comp + " D1 ";
                        }
                    }
                    if (m instanceof Move.Linear l) {
                        line(
                                out,
                                pre + "G1 X" + num(l.end().x()) + " Y"
                                        + num(l.end().y()) + feed(l.feedMmPerMin(), feed));
                        feed = l.feedMmPerMin();
                    } else {
                        Move.Circular c = (Move.Circular) m;
                        boolean ccw = c.ccw() == (c.normal().z() > 0);
                        line(
                                out,
                                pre + (ccw ? "G3" : "G2") + " X" + num(c.end().x()) + " Y"
                                        + num(c.end().y())
                                        + " I" + num(c.center().x() - at.x()) + " J"
                                        + num(c.center().y() - at.y())
                                        + feed(c.feedMmPerMin(), feed));
                        feed = c.feedMmPerMin();
                    }
                    if (k == lastFeed) {
                        if (comp != 0) {
                            line(out, "G40");
                        }
                        line(out, jet[1]);
                        on = false;
                    }
                }
                at = m.end();
            }
        }
        switch (d) {
            case LINUXCNC -> line(out, "M2");
            case ISO, FANUC -> {
                line(out, "M30");
                out.write("%\n");
            }
            case SIEMENS_840D -> line(out, "M30");
        }
    }

    private String[] jetCodes(String process) {
        return jetWords(d, process);
    }

    /** As {@link #jetWords(Dialect, String)} for the post's dialect. */
    public static String[] jetWords(CuttingPost post, String process) {
        return jetWords(post.dialect(), process);
    }

    /**
     * The words that switch the process on and off in the dialect ({@code M07}/{@code M08}, or on
     * LinuxCNC {@code M3 S1}/{@code M5} for plasma and the digital outputs for laser and waterjet).
     */
    public static String[] jetWords(Dialect d, String process) {
        if (d != Dialect.LINUXCNC) {
            return new String[] {"M07", "M08"};
        }
        return switch (process.toLowerCase(Locale.ROOT)) {
            case "laser" -> new String[] {"M64 P0", "M65 P0"};
            case "waterjet" -> new String[] {"M64 P1", "M65 P1"};
            default -> new String[] {"M3 S1", "M5"};
        };
    }

    /**
     * The dialect's dwell block; seconds with three decimals where the control needs the point
     * (without it a Fanuc reads X2 as 2 ms), else in the program's own number format.
     */
    private String dwell(double s) {
        return d.dwell(d.dwellNeedsPoint() ? String.format(Locale.ROOT, "%.3f", s) : num(s));
    }

    private static String feed(double f, double current) {
        return f == current ? "" : " F" + num(f);
    }

    private void comment(Writer out, String text) throws IOException {
        line(out, d.comment(text.replaceAll("[()\\r\\n;]", " ")));
    }

    private void line(Writer out, String text) throws IOException {
        if (!d.numbered()) {
            out.write(text);
        } else {
            n += 10;
            out.write("N" + n + " " + text);
        }
        out.write('\n');
    }

    /** Four decimals, trailing zeros dropped, never "-0". */
    static String num(double v) {
        BigDecimal b = BigDecimal.valueOf(v).setScale(4, RoundingMode.HALF_EVEN).stripTrailingZeros();
        if (b.signum() == 0) {
            return "0";
        }
        String s = b.toPlainString();
        return s;
    }
}
