package org.fresa.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** The benchmark inputs, from the project checkout named by {@code -Dfresa.root}. */
final class Inputs {
    private Inputs() {
    }

    static Path root() {
        return Path.of(System.getProperty("fresa.root", "."));
    }

    static byte[] bytes(String relative) {
        try {
            return Files.readAllBytes(root().resolve(relative).normalize());
        } catch (IOException e) {
            throw new UncheckedIOException("benchmark input missing (run from the project or set -Dfresa.root)", e);
        }
    }
}
