package io.github.jdem846.io.source;

import io.github.jdem846.io.DemFormatException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * Only regular files are opened: reading a FIFO without a writer, or a character device, can wait forever. Says
 * what a path is when it is something else (POSIX file type from {@code unix:mode} where the platform has it).
 */
public final class RegularFiles {

    private RegularFiles() {
    }

    /**
     * What {@code path} is when it exists and is not a regular file (after following symbolic links), e.g.
     * "a FIFO (named pipe)"; null for a regular file or a path that does not exist.
     */
    public static String otherKind(Path path) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (IOException | UnsupportedOperationException e) {
            return null; // missing or unreadable: left to the caller's own message
        }
        if (a.isRegularFile()) {
            return null;
        }
        if (a.isDirectory()) {
            return "a directory";
        }
        try {
            return switch ((Integer) Files.getAttribute(path, "unix:mode") & 0xF000) {
                case 0x1000 -> "a FIFO (named pipe)";
                case 0x2000 -> "a character device";
                case 0x6000 -> "a block device";
                case 0xC000 -> "a socket";
                default -> "a special file";
            };
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            return "a special file (a device, FIFO or socket)";
        }
    }

    /**
     * Refuses a {@code path} that exists and is not a regular file, before anything opens it.
     *
     * @param role what the file is for, e.g. "a DEM file" or "the header"
     */
    public static void require(Path path, String role) throws DemFormatException {
        String kind = otherKind(path);
        if (kind != null) {
            throw new DemFormatException(path, "is " + kind + ", not a regular file; " + role
                    + " must be a regular file");
        }
    }
}
