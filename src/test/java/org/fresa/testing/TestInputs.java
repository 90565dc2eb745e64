package org.fresa.testing;

import java.nio.file.Path;

/**
 * Where the tests find files written by other programs. Paths are relative to the project's
 * folder, where Maven runs the tests.
 */
public final class TestInputs {

    /**
     * The DXF drawings brought into the project (their licences allow it; the notices are beside
     * them): {@code ezdxf/} (MIT) and {@code dxf2gcode/} (GNU GPL).
     */
    public static final Path DXF_CORPUS = Path.of("src/test/resources/corpus/dxf");

    /**
     * The corpus beside the checkout ({@code ../shared/corpus}), read in place as an extra: the
     * ISO texts and the files with no stated licence (STEP-NC: {@code stepnc/grima},
     * {@code stepnc/ap238}, {@code stepnc/fdis}), which may not be copied into the project.
     */
    public static final Path SHARED_CORPUS = Path.of("../shared/corpus");

    /** The skip message of a test whose shared corpus folder is not beside the checkout. */
    public static String sharedCorpusAbsent(Path folder) {
        return folder.normalize() + " is not beside the checkout (files with no licence to copy, read in place only)";
    }

    private TestInputs() {}
}
