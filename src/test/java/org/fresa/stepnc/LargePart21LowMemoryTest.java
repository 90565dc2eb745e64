package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 11: a 100 MB Part 21 file is read and bound within a 512 MB heap. The file is example 2
 * repeated with its instance names shifted, so every copy is a complete, valid program. Runs in
 * the {@code low-memory} surefire execution ({@code -Xmx512m}); skipped in a larger heap, where
 * it would prove nothing.
 */
class LargePart21LowMemoryTest {

    private static final long MIB = 1024 * 1024;
    private static final long TARGET_BYTES = 100 * MIB;

    @TempDir
    Path dir;

    @Test
    void aHundredMegabyteFileIsReadAndBoundIn512Megabytes() throws Exception {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(maxHeap <= 520 * MIB, "needs -Xmx512m (the low-memory surefire execution), has "
                + maxHeap / MIB + " MiB");
        Path big = dir.resolve("big.stp");
        int copies = writeRepeated(Path.of("samples/stepnc/example2.stp"), big);
        assertTrue(Files.size(big) >= TARGET_BYTES, "generated " + Files.size(big) + " bytes");

        StepNcProgram p = StepNcReader.read(big);

        StepNcProgram one = StepNcReader.read(Path.of("samples/stepnc/example2.stp"));
        int perCopy = one.workingsteps().size() + one.skipped().size();
        assertAll(
                () -> assertEquals((long) copies * one.instanceCount(), p.instanceCount()),
                () -> assertEquals(one.workingsteps(), p.workingsteps()),
                () -> assertEquals((long) copies * perCopy, p.workingsteps().size() + p.skipped().size()),
                () -> assertEquals(one.projectId(), p.projectId()));
    }

    /** Writes the sample's header once and its data section as often as it takes to pass 100 MB. */
    static int writeRepeated(Path sample, Path out) throws IOException {
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
            while (written < TARGET_BYTES) {
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
