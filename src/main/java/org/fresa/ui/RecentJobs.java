package org.fresa.ui;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.io.AtomicFiles;

/** The recently opened job files, newest first, kept in a small text file. */
public final class RecentJobs {

    /** How many are kept. */
    public static final int MAX = 8;

    private final Path store;

    /** @param store the text file (one path per line), created when first written */
    public RecentJobs(Path store) {
        this.store = store;
    }

    /** The folder the store lives in (where the application keeps its other files too). */
    public Path folder() {
        Path parent = store.toAbsolutePath().getParent();
        return parent != null ? parent : store.toAbsolutePath();
    }

    /** The default store, {@code ~/.fresa/recent-jobs.txt}. */
    public static RecentJobs inUserHome() {
        return new RecentJobs(Path.of(System.getProperty("user.home"), ".fresa", "recent-jobs.txt"));
    }

    /** The list, newest first; files that no longer exist are left out. Never fails. */
    public List<Path> list() {
        try {
            if (!Files.isRegularFile(store)) {
                return List.of();
            }
            List<Path> out = new ArrayList<>();
            for (String line : Files.readAllLines(store, StandardCharsets.UTF_8)) {
                if (!line.isBlank()) {
                    Path p = Path.of(line.trim());
                    if (Files.isRegularFile(p) && !out.contains(p)) {
                        out.add(p);
                    }
                }
            }
            return out.subList(0, Math.min(MAX, out.size()));
        } catch (IOException | RuntimeException e) {
            return List.of();
        }
    }

    /** Puts the file first; errors writing the list are ignored (it is a convenience). */
    public void add(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> l = new ArrayList<>(list());
        l.remove(abs);
        l.add(0, abs);
        StringBuilder sb = new StringBuilder();
        for (Path p : l.subList(0, Math.min(MAX, l.size()))) {
            sb.append(p).append('\n');
        }
        try {
            AtomicFiles.writeString(store, sb.toString());
        } catch (IOException e) {
            // the list is a convenience; a read-only home must not stop the planner
        }
    }
}
