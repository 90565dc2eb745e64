package org.fresa.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
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

    private static final Map<Path, Object> HELD = new ConcurrentHashMap<>();
    /** Marks a folder in HELD while its lock is being taken. */
    private static final Object RESERVED = new Object();

    private static final DateTimeFormatter TIME =
            DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss", Locale.ROOT).withZone(ZoneId.systemDefault());

    static {
        Runtime.getRuntime()
                .addShutdownHook(new Thread(
                        () -> {
                            for (Object l : HELD.values()) {
                                if (l instanceof FolderLock f) {
                                    f.removeFile();
                                }
                            }
                        },
                        "fresa-folder-locks"));
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
        // one run per folder in this JVM: the operating system's lock does not tell threads apart
        if (HELD.putIfAbsent(dir, RESERVED) != null) {
            throw new FolderBusyException(dir, "in this program");
        }
        boolean done = false;
        try {
            FolderLock l = lockFile(dir, file, created);
            HELD.put(dir, l);
            done = true;
            return l;
        } finally {
            if (!done) {
                HELD.remove(dir, RESERVED);
            }
        }
    }

    /**
     * Takes the lock file. No other descriptor of the file is ever opened by its holder, as
     * closing one would drop the holder's (POSIX) lock. The run before removes the file while it
     * still holds the lock: a run that opened the file just before that holds a lock on a removed
     * file, which is seen by the file's identity (device and inode) having changed, and tries again.
     */
    private static FolderLock lockFile(Path dir, Path file, boolean created) throws IOException {
        for (int attempt = 0; attempt < 100; attempt++) {
            Object before = null;
            FileChannel ch;
            try {
                ch = FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
            } catch (FileAlreadyExistsException e) {
                before = identity(file);
                try {
                    ch = before == null ? null : FileChannel.open(file, StandardOpenOption.WRITE);
                } catch (NoSuchFileException gone) {
                    ch = null;
                }
                if (ch == null) {
                    continue;
                }
            }
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
            if (before != null && !before.equals(identity(file))) {
                if (lock.isPresent()) {
                    lock.get().release();
                }
                ch.close();
                continue;
            }
            String holder = "process " + ProcessHandle.current().pid() + ", started " + TIME.format(Instant.now());
            ch.truncate(0);
            ch.write(ByteBuffer.wrap((holder + "\n").getBytes(StandardCharsets.UTF_8)), 0);
            ch.force(false);
            return new FolderLock(dir, file, ch, lock, created);
        }
        throw new FolderBusyException(dir, holder(file));
    }

    /** The file's identity (device and inode) without opening it, or null when it is gone. */
    private static Object identity(Path file) throws IOException {
        try {
            Object key = Files.readAttributes(file, BasicFileAttributes.class).fileKey();
            return key != null ? key : Files.getLastModifiedTime(file);
        } catch (NoSuchFileException e) {
            return null;
        }
    }

    /** Who holds the folder, as its lock file says (read by a run that does not hold it). */
    private static String holder(Path file) {
        try {
            String s = Files.readString(file, StandardCharsets.UTF_8).strip();
            return s.startsWith("process ") && s.indexOf('\n') < 0 ? s : "unknown process";
        } catch (IOException e) {
            return "unknown process";
        }
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
        release();
    }

    private synchronized void release() throws IOException {
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
            HELD.remove(dir, this);
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
