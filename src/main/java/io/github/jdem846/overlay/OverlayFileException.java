package io.github.jdem846.overlay;

import java.io.IOException;
import java.nio.file.Path;

/** A vector file that cannot be read as an overlay; the message is one line naming the file and what is wrong. */
public final class OverlayFileException extends IOException {

    private static final long serialVersionUID = 1L;

    /**
     * @param file    the file
     * @param problem what is wrong and what would be right
     */
    public OverlayFileException(Path file, String problem) {
        super(file + ": " + problem);
    }
}
