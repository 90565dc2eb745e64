package org.fresa.pocket;

/**
 * The tool does not suit the pocket: it (plus its finishing allowance) does not fit, the thesis's
 * "DIMINUIR O DIAMETRO DA FERR", or the pocket is so large for it that the plan would need more
 * than a bounded number of passes, or its program more than a bounded number of moves over all
 * depth passes. The job cannot be done as asked (exit status 1).
 */
public final class ToolTooLargeException extends Exception {
    private static final long serialVersionUID = 1L;

    public ToolTooLargeException(String message) {
        super(message);
    }
}
