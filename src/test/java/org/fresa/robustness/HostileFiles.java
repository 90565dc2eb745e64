package org.fresa.robustness;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Inputs built to exhaust a reader or a planner: absurd counts, deep nesting, cycles,
 * huge and degenerate numbers. Each is text written on the fly, so the repository holds none of
 * these files.
 */
final class HostileFiles {

    private HostileFiles() {}

    static final String P21_HEAD = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
            + "FILE_NAME('x','',(''),(''),'','','');\nFILE_SCHEMA(('MACHINING_SCHEMA'));\nENDSEC;\nDATA;\n";
    static final String P21_TAIL = "ENDSEC;\nEND-ISO-10303-21;\n";

    static String part21(String data) {
        return P21_HEAD + data + P21_TAIL;
    }

    /** A workplan chain #2 -> #3 -> ... of the given depth under a PROJECT #1. */
    static String workplanChain(int depth) {
        StringBuilder sb = new StringBuilder("#1=PROJECT('p',#2,(),$,$,$);\n");
        for (int i = 2; i < depth + 1; i++) {
            sb.append("#")
                    .append(i)
                    .append("=WORKPLAN('w")
                    .append(i)
                    .append("',(#")
                    .append(i + 1)
                    .append("),$,$,$);\n");
        }
        sb.append("#").append(depth + 1).append("=WORKPLAN('last',(),$,$,$);\n");
        return part21(sb.toString());
    }

    static String nested(String open, String inner, String close, int n) {
        return open.repeat(n) + inner + close.repeat(n);
    }

    static String dxf(List<String[]> blocks, String entities) {
        StringBuilder sb = new StringBuilder(
                "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n" + "0\nSECTION\n2\nBLOCKS\n");
        for (String[] b : blocks) {
            sb.append("0\nBLOCK\n2\n")
                    .append(b[0])
                    .append("\n10\n0\n20\n0\n")
                    .append(b[1])
                    .append("0\nENDBLK\n");
        }
        return sb.append("0\nENDSEC\n0\nSECTION\n2\nENTITIES\n")
                .append(entities)
                .append("0\nENDSEC\n0\nEOF\n")
                .toString();
    }

    static String insert(String block, double x) {
        return "0\nINSERT\n8\n0\n2\n" + block + "\n10\n" + x + "\n20\n0\n";
    }

    static String line(String x1, String y1, String x2, String y2) {
        return "0\nLINE\n8\n0\n10\n" + x1 + "\n20\n" + y1 + "\n11\n" + x2 + "\n21\n" + y2 + "\n";
    }

    static final String LINE = line("0", "0", "10", "0");

    static String lwpolyline(String extra, double[][] pts, double[] bulges) {
        StringBuilder sb =
                new StringBuilder("0\nLWPOLYLINE\n8\n0\n").append(extra).append("70\n1\n");
        for (int i = 0; i < pts.length; i++) {
            sb.append("10\n")
                    .append(pts[i][0])
                    .append("\n20\n")
                    .append(pts[i][1])
                    .append('\n');
            if (bulges != null) {
                sb.append("42\n").append(bulges[i]).append('\n');
            }
        }
        return sb.toString();
    }

    /** Blocks B0..B(levels-1), each inserting the next one fanOut times; the last level holds leaf. */
    static List<String[]> fanOut(int levels, int fanOut, String leaf) {
        List<String[]> blocks = new ArrayList<>();
        for (int i = 0; i < levels; i++) {
            StringBuilder body = new StringBuilder();
            for (int k = 0; k < fanOut; k++) {
                body.append(insert("B" + (i + 1), k));
            }
            blocks.add(new String[] {"B" + i, body.toString()});
        }
        if (leaf != null) {
            blocks.add(new String[] {"B" + levels, leaf});
        }
        return blocks;
    }

    static String contour(double[][] pts) {
        StringBuilder sb = new StringBuilder("contour\nmove ")
                .append(num(pts[0][0]))
                .append(' ')
                .append(num(pts[0][1]))
                .append('\n');
        for (int i = 1; i <= pts.length; i++) {
            double[] p = pts[i % pts.length];
            sb.append("line ").append(num(p[0])).append(' ').append(num(p[1])).append('\n');
        }
        return sb.toString();
    }

    static double[][] polygon(int n, double r) {
        double[][] p = new double[n][];
        for (int i = 0; i < n; i++) {
            double a = -2 * Math.PI * i / n;
            p[i] = new double[] {r * Math.cos(a), r * Math.sin(a)};
        }
        return p;
    }

    private static String num(double d) {
        return String.format(Locale.ROOT, "%s", d);
    }

    /** example 2 with one text replaced (the first occurrence), for numeric hazards in the binding. */
    static String example2With(String from, String to) throws IOException {
        String s = Files.readString(Path.of("samples/stepnc/example2.stp"), StandardCharsets.UTF_8);
        if (!s.contains(from)) {
            throw new IllegalStateException("example2.stp no longer contains " + from);
        }
        return s.replace(from, to);
    }

    static void write(Path file, String text) throws IOException {
        Files.writeString(file, text, StandardCharsets.ISO_8859_1);
    }
}
