package org.fresa.job;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * One run at a time per output folder. Two runs writing into the same folder at once left a
 * mixed set (one run's trajectory next to the other's program), so a run holds the folder's lock
 * file {@value #FILE_NAME} while it writes, and a second run is refused at once with the first
 * one's process and start time, before it reads its input.
 *
 * <p>Refused rather than kept waiting: the second run would only overwrite the first one's
 * files when it got the folder, which is never what the planner meant; a refusal says so at once,
 * where a wait would look like a hang (in a script or a second window) and end the same way.
 *
 * <p>The lock is the operating system's lock on that file, so a killed run (even SIGKILL) holds
 * it no longer; the file is removed when the run ends, on an exception and on SIGTERM, and a
 * leftover of a SIGKILL is taken over by the next run. Runs in the same JVM (two GUI runs) are
 * kept apart the same way.
 */
public final class FolderLock implements AutoCloseable {

    /** The lock file's name in the folder (hidden). */
    public static final String FILE_NAME = ".fresa-lock";

    private static final Map<Path, FolderLock> HELD = new ConcurrentHashMap<>();
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss", Locale.ROOT)
            .withZone(ZoneId.systemDefault());

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            for (FolderLock l : HELD.values()) {
                l.removeFile();
            }
        }, "fresa-folder-locks"));
    }

    private final Path dir;
    private final Path file;
    private final FileChannel channel;
    private final Optional<FileLock> lock;
    private final boolean createdFolder;
    private boolean closed;

    private FolderLock(Path dir, Path file, FileChannel channel, Optional<FileLock> lock, boolean createdFolder) {
        this.dir = dir;
        this.file = file;
        this.channel = channel;
        this.lock = lock;
        this.createdFolder = createdFolder;
    }

    /** A run's output folder is busy: another run writes into it. */
    public static final class FolderBusyException extends IOException {
        private static final long serialVersionUID = 1L;

        FolderBusyException(Path dir, String holder) {
            super(dir + ": another Fresa run (" + holder + ") is writing into this folder; wait for it to end or "
                    + "choose another folder");
        }
    }

    /**
     * Takes the folder for a run, creating it when needed.
     *
     * @throws FolderBusyException when another run (in this or another process) holds it
     * @throws IOException when the folder cannot be created or the lock file written
     */
    public static FolderLock acquire(OutputFolder folder) throws IOException {
        Path dir = folder.dir();
        boolean created = !Files.isDirectory(dir);
        Files.createDirectories(dir);
        Path file = dir.resolve(FILE_NAME);
        String token = "process " + ProcessHandle.current().pid() + ", started " + TIME.format(Instant.now());
        for (int attempt = 0; ; attempt++) {
            if (HELD.containsKey(dir)) {
                throw new FolderBusyException(dir, "in this program");
            }
            FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            Optional<FileLock> lock;
            try {
                FileLock l = ch.tryLock();
                if (l == null) {
                    ch.close();
                    throw new FolderBusyException(dir, holder(file));
                }
                lock = Optional.of(l);
            } catch (OverlappingFileLockException e) {
                ch.close();
                throw new FolderBusyException(dir, "in this program");
            } catch (FolderBusyException e) {
                throw e;
            } catch (IOException e) {
                // a file system without locks (some network shares): the lock file alone marks the folder
                lock = Optional.empty();
            }
            String mine = token + " #" + attempt + "-" + System.nanoTime();
            ch.truncate(0);
            ch.write(ByteBuffer.wrap((mine + "\n").getBytes(StandardCharsets.UTF_8)), 0);
            ch.force(false);
            // the run before may have removed the file between our open and our lock: then this
            // lock is on a deleted file and the folder's file is another run's (or none); try again
            if (mine.equals(holderLine(file))) {
                FolderLock l = new FolderLock(dir, file, ch, lock, created);
                if (HELD.putIfAbsent(dir, l) == null) {
                    return l;
                }
                l.release(false);
                throw new FolderBusyException(dir, "in this program");
            }
            if (lock.isPresent()) {
                lock.get().release();
            }
            ch.close();
            if (attempt > 100) {
                throw new FolderBusyException(dir, holder(file));
            }
        }
    }

    private static String holderLine(Path file) {
        try {
            String s = Files.readString(file, StandardCharsets.UTF_8);
            int nl = s.indexOf('\n');
            return nl < 0 ? s : s.substring(0, nl);
        } catch (NoSuchFileException e) {
            return "";
        } catch (IOException e) {
            return "";
        }
    }

    private static String holder(Path file) {
        String line = holderLine(file);
        int mark = line.indexOf(" #");
        return mark > 0 ? line.substring(0, mark) : "unknown process";
    }

    /** The folder held. */
    public Path dir() {
        return dir;
    }

    /**
     * Gives the folder back: removes the lock file, and the folder itself when this run created
     * it and left nothing in it (a refused input writes nothing).
     */
    @Override
    public void close() throws IOException {
        release(true);
    }

    private synchronized void release(boolean registered) throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            removeFile();
            if (lock.isPresent()) {
                lock.get().release();
            }
            channel.close();
        } finally {
            if (registered) {
                HELD.remove(dir, this);
            }
        }
        if (createdFolder) {
            try (var s = Files.list(dir)) {
                if (s.findAny().isEmpty()) {
                    Files.deleteIfExists(dir);
                }
            } catch (IOException e) {
                // another program wrote into it meanwhile: leave it
            }
        }
    }

    /** Removes the lock file while the lock is still held, so that no other run's file is removed. */
    private void removeFile() {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            // the folder went away or became read-only: the next run takes the file over
        }
    }
}
