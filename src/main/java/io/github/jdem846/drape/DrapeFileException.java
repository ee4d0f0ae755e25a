package io.github.jdem846.drape;

import java.io.IOException;
import java.nio.file.Path;

/**
 * An image to drape that cannot be used: its message names the file, what is wrong and, where possible, what would
 * be right. The CLI prints the message alone and exits with status 1.
 */
public class DrapeFileException extends IOException {

    private static final long serialVersionUID = 1L;

    /**
     * An image that cannot be used.
     *
     * @param file    the file at fault
     * @param problem what is wrong with it (and what would be right)
     */
    public DrapeFileException(Path file, String problem) {
        super(file + ": " + problem);
    }

    /**
     * An image that cannot be used, for a lower-level cause.
     *
     * @param file    the file at fault
     * @param problem what is wrong with it (and what would be right)
     * @param cause   the exception that revealed it
     */
    public DrapeFileException(Path file, String problem, Throwable cause) {
        super(file + ": " + problem, cause);
    }
}
