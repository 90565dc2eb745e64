package org.fresa.stepnc;

import java.util.OptionalLong;
import org.fresa.model.CamInputException;

/**
 * A Part 21 file that cannot be read or bound: a syntax error, a dangling reference, a duplicate
 * instance name, an attribute of the wrong kind. Carries the line and column of the fault and,
 * where known, the instance (#id) it belongs to.
 */
public final class StepParseException extends CamInputException {

    private static final long serialVersionUID = 1L;

    private final long instanceId;

    /**
     * @param instanceId the instance the fault is in, or 0 when outside any instance
     */
    public StepParseException(String source, int line, int column, long instanceId, String problem) {
        super(source, line, column, instanceId > 0 ? "#" + instanceId + ": " + problem : problem);
        this.instanceId = instanceId;
    }

    public OptionalLong instanceId() {
        return instanceId > 0 ? OptionalLong.of(instanceId) : OptionalLong.empty();
    }
}
