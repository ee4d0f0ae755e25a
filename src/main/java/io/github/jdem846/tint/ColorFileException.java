package io.github.jdem846.tint;

import java.io.IOException;

/**
 * A colour file that cannot be used: the message names the file, the line and what is wrong, and what would be
 * right. The CLI prints the message alone.
 */
public class ColorFileException extends IOException {

    private static final long serialVersionUID = 1L;

    /**
     * A problem with line {@code lineNumber} (1-based) of {@code source}.
     *
     * @param source the file's name or path, as shown to the user
     * @param lineNumber the line, from 1
     * @param problem what is wrong with the line and what would be right
     */
    public ColorFileException(String source, int lineNumber, String problem) {
        super(source + ", line " + lineNumber + ": " + problem);
    }

    /**
     * A problem with the file as a whole.
     *
     * @param source the file's name or path, as shown to the user
     * @param problem what is wrong with the file
     */
    public ColorFileException(String source, String problem) {
        super(source + ": " + problem);
    }
}
