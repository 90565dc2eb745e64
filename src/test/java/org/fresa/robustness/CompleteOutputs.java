package org.fresa.robustness;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
import org.fresa.model.CamInputException;

/** Checks that the grading files under final names are whole, for the interruption tests. */
public final class CompleteOutputs {

    private CompleteOutputs() {}

    /** The final-named files of the folder that are truncated or unreadable (empty when all are whole). */
    public static List<String> incomplete(Path dir) throws IOException {
        List<String> bad = new ArrayList<>();
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(p -> !p.getFileName().toString().startsWith("."))
                    .sorted()
                    .toList();
        }
        for (Path f : files) {
            String name = f.getFileName().toString();
            byte[] b = Files.readAllBytes(f);
            String text = new String(b, StandardCharsets.ISO_8859_1);
            boolean ok;
            if (name.endsWith(".dxf")) {
                ok = (text.endsWith("EOF\n") || text.endsWith("EOF\r\n")) && readable(b, name);
            } else if (name.endsWith(".csv")) {
                // a header and rows of the same width, ending with a line break
                String[] lines = text.split("\n", -1);
                ok = text.endsWith("\n") && lines.length > 2;
                for (int i = 1; ok && i < lines.length - 1; i++) {
                    ok = lines[i].split(",", -1).length == lines[0].split(",", -1).length;
                }
            } else if (name.endsWith(".png")) {
                ok = b.length > 12 && text.substring(b.length - 8, b.length - 4).equals("IEND");
            } else {
                ok = b.length > 0;
            }
            if (!ok) {
                bad.add(name + " (" + b.length + " bytes)");
            }
        }
        return bad;
    }

    private static boolean readable(byte[] b, String name) {
        try {
            return !DxfReader.read(b, name, DxfReadOptions.DEFAULT).curves().isEmpty();
        } catch (CamInputException e) {
            return false;
        }
    }
}
