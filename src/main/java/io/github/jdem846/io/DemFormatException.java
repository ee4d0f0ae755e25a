package io.github.jdem846.io;

import java.io.IOException;
import java.nio.file.Path;

/**
 * A DEM file that cannot be read: its message names the file, what is wrong and, where possible, what would be
 * right. The CLI prints the message alone (no stack trace) and exits with status 1.
 */
public class DemFormatException extends IOException {

    private static final long serialVersionUID = 1L;

    /**
     * A file that cannot be read.
     *
     * @param file    the file at fault
     * @param problem what is wrong with it (and what would be right)
     */
    public DemFormatException(Path file, String problem) {
        super(file + ": " + problem);
    }

    /**
     * A file that cannot be read, for a lower-level cause.
     *
     * @param file    the file at fault
     * @param problem what is wrong with it (and what would be right)
     * @param cause   the exception that revealed it
     */
    public DemFormatException(Path file, String problem, Throwable cause) {
        super(file + ": " + problem, cause);
    }
}
