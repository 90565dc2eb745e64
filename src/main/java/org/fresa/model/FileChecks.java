package org.fresa.model;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Locale;

/**
 * What a path names before Fresa reads or replaces it. Readers take regular files only: a
 * directory, a named pipe, a device or a socket is refused with a sentence saying what it is
 * (reading a pipe would wait for a writer that never comes, a device may never end), and so is
 * a file larger than the reader's stated limit, before a byte is read, so that a large file
 * never ends in an OutOfMemoryError.
 */
public final class FileChecks {

    private static final long MIB = 1024 * 1024;

    /** Files read as text into memory whole (contours, job and robot XML): at most this many bytes. */
    public static final long MAX_TEXT_FILE_BYTES = 16 * MIB;

    // st_mode's file type bits (POSIX)
    private static final int S_IFMT = 0170000;
    private static final int S_IFIFO = 0010000;
    private static final int S_IFCHR = 0020000;
    private static final int S_IFBLK = 0060000;
    private static final int S_IFSOCK = 0140000;

    private FileChecks() {}

    /**
     * Checks that an input is a regular file of at most {@code maxBytes}.
     *
     * @param what what the reader expects, with its article: "a DXF drawing"
     * @return the file's size in bytes
     * @throws CamInputException naming the file: it does not exist, is not a regular file (what
     *     it is instead), or is larger than the limit
     */
    public static long requireInput(Path file, String what, long maxBytes) throws CamInputException {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (NoSuchFileException e) {
            throw new CamInputException(file.toString(), "no such file (expected " + what + ")");
        } catch (IOException e) {
            throw new CamInputException(file.toString(), "cannot be read (" + e.getMessage() + ")");
        }
        if (!a.isRegularFile()) {
            throw new CamInputException(file.toString(), "is " + kind(file) + ", not " + what);
        }
        if (a.size() > maxBytes) {
            throw new CamInputException(
                    file.toString(),
                    "is " + megabytes(a.size()) + "; " + what + " may have at most " + megabytes(maxBytes)
                            + tooLargeAdvice(maxBytes));
        }
        return a.size();
    }

    private static String tooLargeAdvice(long maxBytes) {
        return maxBytes < Runtime.getRuntime().maxMemory() / 2
                ? " here, a share of the Java heap (give Java more memory, e.g. FRESA_JAVA_OPTS=-Xmx4g)"
                : "";
    }

    /**
     * The largest input a reader that holds the whole file in memory may take: a share of the
     * Java heap, so that it fits with what the run builds from it.
     *
     * @param divisor how many times the heap must exceed the file
     */
    public static long heapShare(int divisor) {
        return Runtime.getRuntime().maxMemory() / divisor;
    }

    /**
     * What a path names, with its article: "a regular file", "a directory", "a named pipe
     * (FIFO)", "a character device", "a block device", "a socket", or "nothing" when it does not
     * exist. Symbolic links are followed.
     */
    public static String kind(Path p) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(p, BasicFileAttributes.class);
        } catch (IOException e) {
            return "nothing";
        }
        if (a.isRegularFile()) {
            return "a regular file";
        }
        if (a.isDirectory()) {
            return "a directory";
        }
        try {
            int mode = (Integer) Files.getAttribute(p, "unix:mode");
            switch (mode & S_IFMT) {
                case S_IFIFO:
                    return "a named pipe (FIFO)";
                case S_IFCHR:
                    return "a character device";
                case S_IFBLK:
                    return "a block device";
                case S_IFSOCK:
                    return "a socket";
                default:
                    break;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            // no unix view (Windows): the generic word below
        }
        return "a special file (a device, pipe or socket)";
    }

    /** A size in MB for messages: "70 MB", "0.5 MB". */
    static String megabytes(long bytes) {
        double mb = bytes / (double) MIB;
        return (mb >= 10 ? String.format(Locale.ROOT, "%.0f", mb) : String.format(Locale.ROOT, "%.1f", mb)) + " MB";
    }
}
