package io.github.jdem846.internal;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;

/**
 * What went wrong in a file operation, in words for a person: the reason the operating system gave ("No space left
 * on device", "Read-only file system") or, for the exceptions that carry only a file name, what their type means,
 * never the exception's class name. Used to say why an output could not be written, in one line naming it.
 */
public final class IoMessages {

    private IoMessages() {
    }

    /**
     * The reason of {@code e} without its class name or file, e.g. "No space left on device" or "no such file or
     * directory".
     *
     * @param e what was thrown
     * @return one line
     */
    public static String reason(IOException e) {
        if (e instanceof FileSystemException fs) {
            String what = fs.getReason() != null ? fs.getReason() : typeReason(fs);
            return oneLine(what);
        }
        String message = e.getMessage();
        return oneLine(message == null || message.isBlank() ? "an I/O error" : message);
    }

    /**
     * {@code e}, or an IOException that wraps it, whose message names {@code target}: "cannot write TARGET:
     * REASON". Exceptions that already name it are returned as they are.
     *
     * @param e      what was thrown while writing
     * @param target the file the user asked for
     * @return an exception whose one-line message names {@code target}
     */
    public static IOException naming(IOException e, Path target) {
        String message = e.getMessage();
        if (message != null && message.contains(target.toString()) && !(e instanceof FileSystemException
                && ((FileSystemException) e).getReason() == null)) {
            return e;
        }
        return new IOException("cannot write " + target + ": " + reason(e), e);
    }

    private static String typeReason(FileSystemException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file or directory";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException) {
            return "it already exists";
        }
        if (e instanceof NotDirectoryException) {
            return "not a directory";
        }
        if (e instanceof DirectoryNotEmptyException) {
            return "the directory is not empty";
        }
        return "the file system refused";
    }

    private static String oneLine(String s) {
        return s.strip().replaceAll("\\s*\\R\\s*", " ");
    }
}
