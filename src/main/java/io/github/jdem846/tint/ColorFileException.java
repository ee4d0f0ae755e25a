package io.github.jdem846.tint;

import java.io.IOException;

/**
 * A colour file that cannot be used: the message names the file, the line and what is wrong, and what would be
 * right. The CLI prints the message alone.
 */
public class ColorFileException extends IOException {

    private static final long serialVersionUID = 1L;

    /** A problem with line {@code lineNumber} (1-based) of {@code source}. */
    public ColorFileException(String source, int lineNumber, String problem) {
        super(source + ", line " + lineNumber + ": " + problem);
    }

    /** A problem with the file as a whole. */
    public ColorFileException(String source, String problem) {
        super(source + ": " + problem);
    }
}
