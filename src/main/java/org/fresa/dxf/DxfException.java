package org.fresa.dxf;

import org.fresa.model.CamInputException;

/** A DXF file that cannot be read at all (not DXF, truncated group-code stream). */
public class DxfException extends CamInputException {
    private static final long serialVersionUID = 1L;

    public DxfException(String source, int line, String problem) {
        super(source, line, 0, problem);
    }
}
