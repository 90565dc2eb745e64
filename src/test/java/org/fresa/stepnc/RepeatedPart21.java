package org.fresa.stepnc;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * A big Part 21 file made of a sample repeated with its instance names shifted, so every copy is
 * a complete, valid program (the low-memory test and the GUI responsiveness test read one).
 */
public final class RepeatedPart21 {
    private RepeatedPart21() {}

    /** Writes the sample's header once and its data section as often as it takes to pass targetBytes. */
    public static int write(Path sample, Path out, long targetBytes) throws IOException {
        List<String> lines = Files.readAllLines(sample, StandardCharsets.UTF_8);
        int data = lines.indexOf("DATA;");
        int endsec = lines.lastIndexOf("ENDSEC;");
        List<String> head = lines.subList(0, data + 1);
        List<String> body = lines.subList(data + 1, endsec);
        long stride = 1;
        for (String l : body) {
            if (l.startsWith("#")) {
                stride = Math.max(stride, Long.parseLong(l.substring(1, l.indexOf('='))));
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
            w.write("ENDSEC;\nEND-ISO-10303-21;\n");
        }
        return copies;
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
}
