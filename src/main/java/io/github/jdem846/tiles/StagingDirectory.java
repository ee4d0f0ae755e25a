package io.github.jdem846.tiles;

import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.concurrent.ThreadLocalRandom;

/** Hidden staging names next to a target, and the moves and deletes of staged trees. */
final class StagingDirectory {

    /** Marks a staging file or directory: {@code .NAME.jdem846-partial-NNNN}. */
    static final String MARK = ".jdem846-partial-";

    private StagingDirectory() {
    }

    /** A fresh hidden sibling name of {@code target} (not created). */
    static Path siblingOf(Path target) {
        Path name = target.getFileName();
        String n = "." + (name != null ? name : "tiles") + MARK
                + Long.toHexString(ThreadLocalRandom.current().nextLong() & 0xFFFFFFFFFFFFL);
        return parentOf(target).resolve(n);
    }

    /** The directory {@code target} is in. */
    static Path parentOf(Path target) {
        Path parent = target.toAbsolutePath().getParent();
        return parent != null ? parent : target.toAbsolutePath();
    }

    /** Renames {@code staged} to {@code target}, atomically where the file system can. */
    static void move(Path staged, Path target, boolean replace) throws IOException {
        try {
            if (replace) {
                Files.move(staged, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } else {
                Files.move(staged, target, StandardCopyOption.ATOMIC_MOVE);
            }
        } catch (AtomicMoveNotSupportedException e) {
            if (replace) {
                Files.move(staged, target, StandardCopyOption.REPLACE_EXISTING);
            } else {
                Files.move(staged, target);
            }
        }
    }

    /** Deletes {@code root} and everything under it, if it exists. */
    static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        Files.walkFileTree(root, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.deleteIfExists(file);
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult postVisitDirectory(Path dir, IOException e) throws IOException {
                if (e != null) {
                    throw e;
                }
                Files.deleteIfExists(dir);
                return FileVisitResult.CONTINUE;
            }
        });
    }
}
