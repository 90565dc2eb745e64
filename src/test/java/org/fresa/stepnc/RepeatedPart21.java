package org.fresa.stepnc;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A big Part 21 file made of a sample repeated with its instance names shifted, so every copy is
 * a complete, valid program (the low-memory tests and the GUI responsiveness test read one).
 *
 * <p>{@link #write} keeps each copy's PROJECT: the first one is executed, the other copies'
 * workingsteps are in the file but skipped. {@link #writeExecuted} makes one project of all the
 * copies: each copy's PROJECT is left out, and one PROJECT at the end names every copy's
 * workpiece and a main workplan that runs every copy's main workplan in turn, so every
 * workingstep of every copy is executed (the same part machined again and again, as a
 * production run of one file would).
 *
 * <p>{@code java -cp target/test-classes org.fresa.stepnc.RepeatedPart21 SAMPLE OUT MB} writes
 * the executed form of at least MB * 10^6 bytes (to measure {@code fresa toolpath} by hand).
 */
public final class RepeatedPart21 {
    private RepeatedPart21() {}

    /** A PROJECT record: name, its_id, main_workplan, its_workpieces, the rest. */
    private static final Pattern PROJECT =
            Pattern.compile("#(\\d+)\\s*=\\s*PROJECT\\s*\\(('[^']*')\\s*,\\s*#(\\d+)\\s*,\\s*\\(([^)]*)\\)(.*)");

    /** Writes the sample's header once and its data section as often as it takes to pass targetBytes. */
    public static int write(Path sample, Path out, long targetBytes) throws IOException {
        return write(sample, out, targetBytes, false);
    }

    /**
     * As {@link #write}, every copy executed: one project whose main workplan runs each copy's
     * main workplan, in copy order.
     *
     * @return the number of copies
     */
    public static int writeExecuted(Path sample, Path out, long targetBytes) throws IOException {
        return write(sample, out, targetBytes, true);
    }

    private static int write(Path sample, Path out, long targetBytes, boolean executeAll) throws IOException {
        List<String> lines = Files.readAllLines(sample, StandardCharsets.UTF_8);
        int data = lines.indexOf("DATA;");
        int endsec = lines.lastIndexOf("ENDSEC;");
        List<String> head = lines.subList(0, data + 1);
        List<String> body = new ArrayList<>(lines.subList(data + 1, endsec));
        long stride = 1;
        for (String l : body) {
            if (l.startsWith("#")) {
                stride = Math.max(stride, Long.parseLong(l.substring(1, l.indexOf('='))));
            }
        }
        Matcher project = null;
        if (executeAll) {
            for (int i = 0; i < body.size(); i++) {
                Matcher m = PROJECT.matcher(body.get(i));
                if (m.matches()) {
                    project = m;
                    body.remove(i);
                    break;
                }
            }
            if (project == null) {
                throw new IllegalArgumentException(sample + " has no PROJECT on one line");
            }
        }
        int copies = 0;
        long written = 0;
        try (BufferedWriter w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
            for (String l : head) {
                w.write(l);
                w.write('\n');
            }
            StringBuilder sb = new StringBuilder();
            while (written < targetBytes) {
                long offset = copies * stride;
                for (String l : body) {
                    sb.setLength(0);
                    shiftNames(l, offset, sb);
                    sb.append('\n');
                    w.append(sb);
                    written += sb.length();
                }
                copies++;
            }
            if (project != null) {
                writeProject(project, stride, copies, w);
            }
            w.write("ENDSEC;\nEND-ISO-10303-21;\n");
        }
        return copies;
    }

    /** The one PROJECT of every copy, and its main workplan running each copy's, ten names a line. */
    private static void writeProject(Matcher p, long stride, int copies, BufferedWriter w) throws IOException {
        long projectName = copies * stride + 1;
        long mainName = projectName + 1;
        long mainWorkplan = Long.parseLong(p.group(3));
        List<Long> workpieces = new ArrayList<>();
        for (String ref : p.group(4).split(",")) {
            if (!ref.isBlank()) {
                workpieces.add(Long.parseLong(ref.trim().substring(1)));
            }
        }
        w.write("#" + projectName + "=PROJECT(" + p.group(2) + ",#" + mainName + ",(");
        int n = 0;
        for (int c = 0; c < copies; c++) {
            for (long wp : workpieces) {
                w.write((n > 0 ? "," : "") + (n > 0 && n % 10 == 0 ? "\n" : "") + "#" + (wp + c * stride));
                n++;
            }
        }
        w.write(")" + p.group(5) + "\n");
        w.write("#" + mainName + "=WORKPLAN('every copy',(");
        for (int c = 0; c < copies; c++) {
            w.write((c > 0 ? "," : "") + (c > 0 && c % 10 == 0 ? "\n" : "") + "#" + (mainWorkplan + c * stride));
        }
        w.write("),$,$,$);\n");
    }

    /** Adds offset to every #name outside strings. */
    private static void shiftNames(String line, long offset, StringBuilder out) {
        boolean inString = false;
        int i = 0;
        while (i < line.length()) {
            char c = line.charAt(i);
            if (c == '\'') {
                inString = !inString;
            }
            if (c == '#' && !inString) {
                int j = i + 1;
                while (j < line.length() && Character.isDigit(line.charAt(j))) {
                    j++;
                }
                out.append('#').append(Long.parseLong(line.substring(i + 1, j)) + offset);
                i = j;
                continue;
            }
            out.append(c);
            i++;
        }
    }

    /** SAMPLE OUT MB: the executed form of at least MB * 10^6 bytes; prints the copies. */
    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            System.err.println("usage: RepeatedPart21 SAMPLE OUT MB");
            System.exit(2);
        }
        int copies = writeExecuted(Path.of(args[0]), Path.of(args[1]), Long.parseLong(args[2]) * 1_000_000L);
        System.out.println(copies + " copies, " + Files.size(Path.of(args[1])) + " bytes");
    }
}
