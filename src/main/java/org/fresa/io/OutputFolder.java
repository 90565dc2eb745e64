package org.fresa.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.regex.Pattern;
import org.fresa.model.CamInputException;
import org.fresa.model.FileChecks;

/**
 * The output folder of a run ({@code --out DIR}): files are written atomically, their names are
 * checked so that nothing derived from an input (a workingstep id, a layer name) can escape the
 * folder, and the files written are listed for the summary.
 *
 * <p>Between {@link #beginParallel} and {@link #finishParallel} each file's body is rendered into
 * memory on an executor while the caller goes on; the files are then written in the order they
 * were asked for, so the folder and {@link #written} are the same as without it.
 */
public final class OutputFolder {

    private static final Pattern SAFE_NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._+-]{0,127}");
    /** Names Windows takes for devices whatever the extension (NUL.ngc writes nowhere). */
    private static final Pattern WINDOWS_DEVICE = Pattern.compile("(?i)(CON|PRN|AUX|NUL|COM[0-9]|LPT[0-9])(\\..*)?");

    private final Path dir;
    private final List<Path> written = new ArrayList<>();
    private ExecutorService renderer;
    private final List<Pending> pending = new ArrayList<>();

    private record Pending(Path target, Future<byte[]> bytes) {}

    public OutputFolder(Path dir) {
        this.dir = dir.toAbsolutePath().normalize();
    }

    public Path dir() {
        return dir;
    }

    /**
     * An output folder that is a folder or does not exist yet (it is created when written).
     *
     * @param option how the user named it ({@code --out}), for the message
     * @throws CamInputException for a path that names a file, a named pipe, a device or a socket
     */
    public static OutputFolder of(Path dir, String option) throws CamInputException {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new CamInputException(option, dir + " is " + FileChecks.kind(dir) + ", not a folder");
        }
        return new OutputFolder(dir);
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
        if (renderer != null) {
            pending.add(new Pending(target, renderer.submit(() -> {
                java.io.ByteArrayOutputStream buf = new java.io.ByteArrayOutputStream(1 << 16);
                body.writeTo(buf);
                Timing.mark("rendered " + fileName);
                return buf.toByteArray();
            })));
        } else {
            AtomicFiles.write(target, body);
        }
        written.add(target);
        return target;
    }

    /**
     * From now on {@link #write} renders each body on {@code executor} and returns at once; the
     * files appear at {@link #finishParallel}.
     *
     * @throws IllegalStateException when already rendering in parallel
     */
    public synchronized void beginParallel(ExecutorService executor) {
        if (renderer != null) {
            throw new IllegalStateException("already rendering in parallel");
        }
        renderer = java.util.Objects.requireNonNull(executor, "executor");
    }

    /**
     * Waits for the bodies rendered since {@link #beginParallel} and writes their files in the
     * order they were asked for; afterwards writes are immediate again.
     *
     * @throws IOException the first body's or write's failure (the files after it are not written)
     */
    public void finishParallel() throws IOException {
        List<Pending> todo;
        synchronized (this) {
            todo = List.copyOf(pending);
            pending.clear();
            renderer = null;
        }
        for (int i = 0; i < todo.size(); i++) {
            Pending p = todo.get(i);
            byte[] bytes;
            try {
                bytes = p.bytes().get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                cancel(todo, i);
                throw new java.io.InterruptedIOException(
                        "interrupted while rendering " + p.target().getFileName());
            } catch (ExecutionException | CancellationException e) {
                cancel(todo, i);
                Throwable c = e.getCause() != null ? e.getCause() : e;
                if (c instanceof IOException io) {
                    throw io;
                }
                if (c instanceof RuntimeException re) {
                    throw re;
                }
                if (c instanceof Error err) {
                    throw err;
                }
                throw new IOException("cannot render " + p.target().getFileName() + ": " + c.getMessage(), c);
            }
            AtomicFiles.write(p.target(), out -> out.write(bytes));
        }
    }

    /** Drops what was asked for since {@link #beginParallel} without writing it. */
    public void abandonParallel() {
        List<Pending> todo;
        synchronized (this) {
            todo = List.copyOf(pending);
            pending.clear();
            renderer = null;
        }
        cancel(todo, 0);
    }

    /** Cancels the renderings from {@code from} on and takes their files off {@link #written}. */
    private void cancel(List<Pending> todo, int from) {
        for (int i = from; i < todo.size(); i++) {
            todo.get(i).bytes().cancel(true);
        }
        synchronized (this) {
            written.removeAll(todo.subList(from, todo.size()).stream()
                    .map(Pending::target)
                    .toList());
        }
    }

    /**
     * Writes one file in the folder atomically, inspected before it is renamed into place
     * ({@link AtomicFiles#write(Path, AtomicFiles.Body, AtomicFiles.Inspection)}). Written at once,
     * also between {@link #beginParallel} and {@link #finishParallel}: the inspection reads the file.
     */
    public synchronized <E extends Exception> Path write(
            String fileName, AtomicFiles.Body body, AtomicFiles.Inspection<E> before) throws IOException, E {
        Path target = resolve(fileName);
        AtomicFiles.write(target, body, before);
        written.add(target);
        return target;
    }

    /**
     * Starts a file of the folder written atomically a part at a time, for several files filled at
     * once ({@link AtomicFiles#stage}); it is listed in {@link #written} when committed. Written
     * at once, also between {@link #beginParallel} and {@link #finishParallel}.
     */
    public Staged stage(String fileName) throws IOException {
        Path target = resolve(fileName);
        return new Staged(target, AtomicFiles.stage(target));
    }

    /** A file of the folder being written; see {@link AtomicFiles.Staged}. */
    public final class Staged implements AutoCloseable {
        private final Path target;
        private final AtomicFiles.Staged file;

        private Staged(Path target, AtomicFiles.Staged file) {
            this.target = target;
            this.file = file;
        }

        public java.io.OutputStream out() {
            return file.out();
        }

        /** Ends the content and gives the temporary file, to be read before it is committed. */
        public Path written() throws IOException {
            return file.written();
        }

        /** Renames the file into place and lists it as written. */
        public Path commit() throws IOException {
            file.commit();
            synchronized (OutputFolder.this) {
                written.add(target);
            }
            return target;
        }

        /** Removes the file unless it was committed. */
        @Override
        public void close() throws IOException {
            file.close();
        }
    }

    public Path writeString(String fileName, String text) throws IOException {
        return write(fileName, out -> out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
    }

    /** The path a file of that name will have; checks the name as {@link #write} does. */
    public Path resolve(String fileName) {
        if (!SAFE_NAME.matcher(fileName).matches()
                || fileName.contains("..")
                || fileName.endsWith(".")
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
        if (s.isEmpty()
                || !Character.isLetterOrDigit(s.charAt(0))
                || WINDOWS_DEVICE.matcher(s).matches()) {
            s = "x" + s;
        }
        s = s.length() > 100 ? s.substring(0, 100) : s;
        return s.endsWith(".") ? s.substring(0, s.length() - 1) + "_" : s;
    }

    public synchronized List<Path> written() {
        return List.copyOf(written);
    }
}
