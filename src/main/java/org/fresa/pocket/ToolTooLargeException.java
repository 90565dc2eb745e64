package org.fresa.pocket;

/** The tool (plus its finishing allowance) does not fit the pocket: the thesis's "DIMINUIR O DIAMETRO DA FERR". */
public final class ToolTooLargeException extends Exception {
    private static final long serialVersionUID = 1L;

    public ToolTooLargeException(String message) {
        super(message);
    }
}
