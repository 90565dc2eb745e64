package org.fresa.job;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * The output folder of a run ({@code --out DIR}): files are written atomically, their names are
 * checked so that nothing derived from an input (a workingstep id, a layer name) can escape the
 * folder, and the files written are listed for the summary.
 */
public final class OutputFolder {

    private static final Pattern SAFE_NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._+-]{0,127}");
    /** Names Windows takes for devices whatever the extension (NUL.ngc writes nowhere). */
    private static final Pattern WINDOWS_DEVICE = Pattern.compile("(?i)(CON|PRN|AUX|NUL|COM[0-9]|LPT[0-9])(\\..*)?");

    private final Path dir;
    private final List<Path> written = new ArrayList<>();

    public OutputFolder(Path dir) {
        this.dir = dir.toAbsolutePath().normalize();
    }

    public Path dir() {
        return dir;
    }

    /** Creates the folder (and its parents) if needed. */
    public void create() throws IOException {
        Files.createDirectories(dir);
    }

    /**
     * Writes one file in the folder atomically.
     *
     * @param fileName a plain file name: letters, digits, {@code . _ + -}, no separators
     * @throws IllegalArgumentException for a name that is not plain
     */
    public synchronized Path write(String fileName, AtomicFiles.Body body) throws IOException {
        Path target = resolve(fileName);
        AtomicFiles.write(target, body);
        written.add(target);
        return target;
    }

    public Path writeString(String fileName, String text) throws IOException {
        return write(fileName, out -> out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
    }

    /** The path a file of that name will have; checks the name as {@link #write} does. */
    public Path resolve(String fileName) {
        if (!SAFE_NAME.matcher(fileName).matches() || fileName.contains("..") || fileName.endsWith(".")
                || WINDOWS_DEVICE.matcher(fileName).matches()) {
            throw new IllegalArgumentException("not a plain output file name: " + fileName);
        }
        Path p = dir.resolve(fileName).normalize();
        if (!p.getParent().equals(dir)) {
            throw new IllegalArgumentException("output file outside the folder: " + fileName);
        }
        return p;
    }

    /** Turns any text (an id from an input file) into a safe file-name part. */
    public static String sanitize(String text) {
        String s = text.replaceAll("[^A-Za-z0-9._+-]", "_").replace("..", "_");
        if (s.isEmpty() || !Character.isLetterOrDigit(s.charAt(0)) || WINDOWS_DEVICE.matcher(s).matches()) {
            s = "x" + s;
        }
        s = s.length() > 100 ? s.substring(0, 100) : s;
        return s.endsWith(".") ? s.substring(0, s.length() - 1) + "_" : s;
    }

    public synchronized List<Path> written() {
        return List.copyOf(written);
    }
}
