package io.github.jdem846.output;

import io.github.jdem846.internal.IoMessages;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.DosFileAttributes;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes a group of files so that a failure leaves nothing behind: each file is first written to a hidden
 * temporary file in its target directory ({@link #stage}); only when all are written does {@link #commit} move them
 * into place, in the order staged, each by an atomic rename that replaces the old file (or a plain move where the
 * file system cannot rename atomically). {@link #close} deletes whatever was not committed.
 *
 * <p>A file written over time (a picture streamed band by band) is {@link #open opened} instead: its temporary file
 * is created at once and filled by the caller. {@link #scratch Scratch files} (the tiles of a COG waiting to be
 * copied into it) live next to the target too and are always deleted by {@link #close}, never moved.
 *
 * <p>Temporary files are created with the default permissions of new files (not the owner-only permissions of
 * {@link Files#createTempFile}), so the final files look like any other file the user writes.
 */
final class StagedFiles implements AutoCloseable {

    /** Writes the content of one file. */
    @FunctionalInterface
    interface Content {
        void writeTo(Path file) throws IOException;
    }

    private record Staged(Path temp, Path target) {
    }

    private final List<Staged> staged = new ArrayList<>();
    private final List<Path> scratch = new ArrayList<>();
    private int committed;

    /**
     * Fails early, before any work, when {@code target} cannot be written: its directory is missing, not a
     * directory or not writable, or the target is a directory or a read-only file.
     *
     * @throws IOException naming the file and what is wrong
     */
    static void checkWritable(Path target) throws IOException {
        Path dir = directoryOf(target);
        if (!Files.exists(dir)) {
            throw new NoSuchFileException(null, null,
                    "cannot write " + target + ": directory " + dir + " does not exist");
        }
        if (!Files.isDirectory(dir)) {
            throw new IOException("cannot write " + target + ": " + dir + " is not a directory");
        }
        if (!Files.isWritable(dir)) {
            throw new AccessDeniedException(null, null,
                    "cannot write " + target + ": directory " + dir + " is not writable");
        }
        if (Files.isDirectory(target)) {
            throw new FileAlreadyExistsException(null, null,
                    "cannot write " + target + ": a directory of that name exists");
        }
        if (Files.exists(target) && isReadOnly(target)) {
            throw new AccessDeniedException(null, null,
                    "cannot write " + target + ": the existing file is read-only and was left unchanged");
        }
    }

    /**
     * True when {@code file} is marked read-only: not writable by this process, or (also for a superuser, whom the
     * operating system lets write anyway) without the owner's write permission or with the DOS read-only flag.
     */
    static boolean isReadOnly(Path file) throws IOException {
        if (!Files.isWritable(file)) {
            return true;
        }
        try {
            PosixFileAttributes posix = Files.readAttributes(file, PosixFileAttributes.class);
            return !posix.permissions().contains(PosixFilePermission.OWNER_WRITE);
        } catch (UnsupportedOperationException notPosix) {
            return Files.readAttributes(file, DosFileAttributes.class).isReadOnly();
        }
    }

    /**
     * Writes {@code content} to a new temporary file next to {@code target}.
     *
     * @throws IOException naming {@code target} when the temporary file cannot be created or written; the
     *                     temporary file is then already deleted
     */
    void stage(Path target, Content content) throws IOException {
        checkWritable(target);
        Path temp = createTemp(target, "tmp");
        try {
            content.writeTo(temp);
        } catch (IOException | RuntimeException | Error e) {
            deleteQuietly(temp, e);
            if (e instanceof IOException io) {
                throw withTarget(io, target);
            }
            throw e;
        }
        staged.add(new Staged(temp, target));
    }

    /**
     * Creates the temporary file of {@code target} now, empty, for the caller to write; it is committed with the
     * others.
     *
     * @return the temporary file
     * @throws IOException naming {@code target} when it cannot be written or the file cannot be created
     */
    Path open(Path target) throws IOException {
        checkWritable(target);
        Path temp = createTemp(target, "tmp");
        staged.add(new Staged(temp, target));
        return temp;
    }

    /**
     * Creates an empty scratch file next to {@code target}, {@code .<name>.<random>.<purpose>.tmp}, deleted by
     * {@link #close} (or earlier by the caller).
     */
    Path scratch(Path target, String purpose) throws IOException {
        Path file = createTemp(target, purpose + ".tmp");
        scratch.add(file);
        return file;
    }

    /** Stages a small text file (UTF-8). */
    void stageText(Path target, String text) throws IOException {
        stage(target, file -> Files.writeString(file, text));
    }

    /**
     * Moves every staged file onto its target, in the order staged.
     *
     * @throws IOException naming the target that could not be replaced (files moved before it stay in place)
     */
    void commit() throws IOException {
        while (committed < staged.size()) {
            Staged s = staged.get(committed);
            try {
                try {
                    Files.move(s.temp(), s.target(), StandardCopyOption.ATOMIC_MOVE,
                            StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(s.temp(), s.target(), StandardCopyOption.REPLACE_EXISTING);
                }
            } catch (IOException e) {
                throw withTarget(e, s.target());
            }
            committed++;
        }
    }

    /** Deletes the temporary files that were not committed, and the scratch files. */
    @Override
    public void close() {
        for (int i = committed; i < staged.size(); i++) {
            deleteQuietly(staged.get(i).temp(), null);
        }
        for (Path file : scratch) {
            deleteQuietly(file, null);
        }
        staged.clear();
        scratch.clear();
        committed = 0;
    }

    private static Path createTemp(Path target, String suffix) throws IOException {
        Path dir = directoryOf(target);
        String name = target.getFileName().toString();
        for (int attempt = 0; ; attempt++) {
            Path temp = dir.resolve("." + name + "." + Long.toHexString(ThreadLocalRandom.current().nextLong())
                    + "." + suffix);
            try {
                Files.newOutputStream(temp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return temp;
            } catch (FileAlreadyExistsException e) {
                if (attempt > 100) {
                    throw withTarget(e, target);
                }
            } catch (IOException e) {
                throw new IOException("cannot write " + target + ": cannot create a file in " + dir + ": "
                        + IoMessages.reason(e), e);
            }
        }
    }

    private static Path directoryOf(Path target) {
        Path parent = target.toAbsolutePath().getParent();
        if (parent == null) {
            throw new IllegalArgumentException("not a file path: " + target);
        }
        return parent;
    }

    /** {@code e}, or an IOException wrapping it, whose one-line message names {@code target} ({@link IoMessages}). */
    static IOException withTarget(IOException e, Path target) {
        return IoMessages.naming(e, target);
    }

    private static void deleteQuietly(Path temp, Throwable cause) {
        try {
            Files.deleteIfExists(temp);
        } catch (IOException e) {
            if (cause != null) {
                cause.addSuppressed(e);
            }
        }
    }
}
