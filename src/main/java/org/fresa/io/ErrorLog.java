package org.fresa.io;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;

/** Appends full stack traces of internal errors to {@code ~/.fresa/fresa.log}, never to the user's screen. */
public final class ErrorLog {
    private ErrorLog() {}

    /** The log file, or null when it cannot be written. */
    public static Path record(Throwable t) {
        try {
            Path dir = Path.of(System.getProperty("user.home"), ".fresa");
            Files.createDirectories(dir);
            Path log = dir.resolve("fresa.log");
            StringWriter sw = new StringWriter();
            try (PrintWriter pw = new PrintWriter(sw)) {
                pw.println(Instant.now() + " " + t);
                t.printStackTrace(pw);
            }
            Files.writeString(
                    log, sw.toString(), StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
            return log;
        } catch (IOException | SecurityException e) {
            return null;
        }
    }
}
