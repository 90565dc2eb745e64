package org.fresa.stepnc;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.nio.file.Path;

/**
 * Reads an ISO 14649 (STEP-NC) Part 21 file into a {@link StepNcProgram}: the Part 21 layer
 * ({@link Part21Reader}) then the binding driven by {@link Iso14649Schema}, or, for AP238 in its
 * integrated form (AIM), {@link Ap238AimBinder}.
 */
public final class StepNcReader {
    private StepNcReader() {}

    /**
     * @throws StepParseException for a file that is not valid Part 21 or whose workingsteps
     *                            cannot be bound (line, column and #id in the message)
     */
    public static StepNcProgram read(Path file) throws IOException, StepParseException {
        return bind(Part21Reader.read(file));
    }

    public static StepNcProgram read(InputStream in, String source) throws IOException, StepParseException {
        return bind(Part21Reader.read(in, source));
    }

    public static StepNcProgram read(Reader in, String source) throws IOException, StepParseException {
        return bind(Part21Reader.read(in, source));
    }

    /** Binds an already parsed file. */
    public static StepNcProgram bind(StepFile file) throws StepParseException {
        if (Ap238AimBinder.isIntegrated(file.schemas())) {
            return new Ap238AimBinder(file).bind();
        }
        return new Iso14649Binder(file).bind();
    }
}
