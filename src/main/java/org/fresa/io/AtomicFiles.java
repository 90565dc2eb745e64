package org.fresa.io;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import org.fresa.model.CamInputException;
import org.fresa.model.FileChecks;

/**
 * Writes a file so that it appears complete or not at all: the content goes to a hidden
 * temporary file in the same folder, which is renamed over the target when it is closed. An
 * interrupted run (kill, cancel, an exception while writing) leaves no truncated file under the
 * final name, and the temporary file is removed when the writer fails.
 *
 * <p>Temporary files: a normal end, an exception or a SIGTERM (a shutdown hook) removes them. A
 * SIGKILL or a power cut cannot, so they are hidden names ({@link #TEMP_PREFIX}) that the next
 * write into the same folder removes once they are older than {@link #STALE}; younger ones may
 * belong to another run writing into the folder at the same time and are left alone.
 */
public final class AtomicFiles {

    /** The prefix of temporary files, so leftovers of a killed JVM are recognisable. */
    public static final String TEMP_PREFIX = ".fresa-tmp-";
    /** The suffix of temporary files. */
    public static final String TEMP_SUFFIX = ".part";
    /** Age after which a temporary file is a leftover of a killed run. */
    public static final java.time.Duration STALE = java.time.Duration.ofHours(1);

    private static final java.util.Set<Path> IN_PROGRESS = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private static final java.util.Set<Path> CLEANED = java.util.concurrent.ConcurrentHashMap.newKeySet();
    /** Guards the creation of temporary files against the shutdown hook. */
    private static final Object GATE = new Object();

    private static boolean ending;

    static {
        Runtime.getRuntime()
                .addShutdownHook(new Thread(
                        () -> {
                            // the run's threads go on while the hook runs: from here no new temporary file is made,
                            // so every one that exists is in IN_PROGRESS and removed below
                            synchronized (GATE) {
                                ending = true;
                            }
                            for (Path p : IN_PROGRESS) {
                                try {
                                    Files.deleteIfExists(p);
                                } catch (IOException e) {
                                    // the JVM is ending: nothing better to do than leave the hidden file
                                }
                            }
                        },
                        "fresa-temp-files"));
    }

    private AtomicFiles() {}

    /** Produces a file's content. */
    @FunctionalInterface
    public interface Body {
        void writeTo(OutputStream out) throws IOException;
    }

    /** Looks at a file written in full before it is renamed into place; throwing keeps it from being renamed. */
    @FunctionalInterface
    public interface Inspection<E extends Exception> {
        void inspect(Path written) throws IOException, E;
    }

    /**
     * Checks that a file may be written there: nothing is there yet, or a regular file that the
     * write replaces. A directory, a named pipe, a device or a socket is refused: the rename would
     * replace the node itself (a FIFO another program reads, /dev/full) with a file.
     *
     * @param option how the user named the path ({@code --out}), for the message
     * @throws CamInputException naming the option, the path and what it is
     */
    public static Path requireWritable(Path target, String option) throws CamInputException {
        if (Files.exists(target) && !Files.isRegularFile(target)) {
            throw new CamInputException(
                    option,
                    target + " is " + FileChecks.kind(target)
                            + ", not a file: Fresa writes a new file and renames it into place, which would replace it");
        }
        return target;
    }

    /**
     * Writes the target atomically, creating its folder when needed.
     *
     * @throws IOException also when the target exists and is not a regular file (it is left as it is)
     */
    public static void write(Path target, Body body) throws IOException {
        write(target, body, written -> {});
    }

    /**
     * Writes the target atomically as {@link #write(Path, Body)}, inspecting the written temporary
     * file before the rename: when the inspection throws, the temporary file is removed and the
     * target left as it was.
     */
    public static <E extends Exception> void write(Path target, Body body, Inspection<E> before) throws IOException, E {
        try (Staged s = stage(target)) {
            body.writeTo(s.out());
            before.inspect(s.written());
            s.commit();
        }
    }

    /**
     * Starts writing the target atomically, for a writer that fills several files at once: the
     * content goes to a temporary file until {@link Staged#commit}; closing without committing
     * removes it and leaves the target as it was.
     *
     * @throws IOException also when the target exists and is not a regular file (it is left as it is)
     */
    public static Staged stage(Path target) throws IOException {
        Path abs = target.toAbsolutePath();
        if (Files.exists(abs) && !Files.isRegularFile(abs)) {
            throw new IOException(abs + " is " + FileChecks.kind(abs) + ", not a regular file: not replaced");
        }
        Path dir = abs.getParent();
        Files.createDirectories(dir);
        if (CLEANED.add(dir)) {
            removeStale(dir);
        }
        Path tmp;
        synchronized (GATE) {
            if (ending) {
                throw new java.io.InterruptedIOException(
                        "the program is ending: " + abs.getFileName() + " not written");
            }
            tmp = createTemporary(dir);
            IN_PROGRESS.add(tmp);
        }
        try {
            return new Staged(abs, tmp, new BufferedOutputStream(Files.newOutputStream(tmp), 1 << 16));
        } catch (IOException | RuntimeException e) {
            IN_PROGRESS.remove(tmp);
            Files.deleteIfExists(tmp);
            throw e;
        }
    }

    /** A file being written under a temporary name, renamed over its target only when committed. */
    public static final class Staged implements AutoCloseable {
        private final Path target;
        private final Path tmp;
        private final OutputStream out;
        private boolean streamClosed;
        private boolean done;

        private Staged(Path target, Path tmp, OutputStream out) {
            this.target = target;
            this.tmp = tmp;
            this.out = out;
        }

        /** Where the content goes (buffered). */
        public OutputStream out() {
            return out;
        }

        /** Ends the content and gives the temporary file, to be read before it is committed. */
        public Path written() throws IOException {
            if (!streamClosed) {
                streamClosed = true;
                out.close();
            }
            return tmp;
        }

        /** Ends the content and renames the temporary file over the target. */
        public void commit() throws IOException {
            written();
            // temporary files are created private (0600); the result is an ordinary file (0644)
            if (Files.getFileStore(tmp)
                    .supportsFileAttributeView(java.nio.file.attribute.PosixFileAttributeView.class)) {
                Files.setPosixFilePermissions(
                        tmp, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
            }
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            done = true;
            IN_PROGRESS.remove(tmp);
        }

        /** Removes the temporary file unless it was committed. */
        @Override
        public void close() throws IOException {
            if (done) {
                return;
            }
            try {
                if (!streamClosed) {
                    streamClosed = true;
                    out.close();
                }
            } finally {
                IN_PROGRESS.remove(tmp);
                Files.deleteIfExists(tmp);
            }
        }
    }

    static final java.util.concurrent.atomic.AtomicLong COUNTER = new java.util.concurrent.atomic.AtomicLong();

    /**
     * A new hidden file named for this process and a counter. {@code Files.createTempFile} would
     * do, but its random names start the JDK's SecureRandom and security providers, a noticeable
     * part of a short command's start-up; a name taken already (a killed run's leftover under a
     * reused process id) is skipped.
     */
    private static Path createTemporary(Path dir) throws IOException {
        String pid = Long.toString(ProcessHandle.current().pid());
        while (true) {
            Path p = dir.resolve(TEMP_PREFIX + pid + "-" + COUNTER.incrementAndGet() + TEMP_SUFFIX);
            try {
                return Files.createFile(p);
            } catch (java.nio.file.FileAlreadyExistsException e) {
                // try the next number
            }
        }
    }

    /**
     * Removes the temporary files older than {@link #STALE} that killed runs left in the folder.
     *
     * @return how many were removed
     */
    public static int removeStale(Path dir) throws IOException {
        java.nio.file.attribute.FileTime limit =
                java.nio.file.attribute.FileTime.from(java.time.Instant.now().minus(STALE));
        int n = 0;
        try (java.nio.file.DirectoryStream<Path> ds = Files.newDirectoryStream(dir, TEMP_PREFIX + "*" + TEMP_SUFFIX)) {
            for (Path p : ds) {
                try {
                    if (Files.isRegularFile(p)
                            && Files.getLastModifiedTime(p).compareTo(limit) < 0
                            && Files.deleteIfExists(p)) {
                        n++;
                    }
                } catch (IOException e) {
                    // another run removed it, or it is not ours to remove: leave it
                }
            }
        }
        return n;
    }

    /** Writes text as UTF-8 atomically. */
    public static void writeString(Path target, String text) throws IOException {
        write(target, out -> out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
    }
}
