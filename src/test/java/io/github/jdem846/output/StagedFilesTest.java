package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** All-or-nothing writing: a failure part-way leaves old files intact and no temporary files behind. */
class StagedFilesTest {

    @TempDir
    Path dir;

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void failureWhileWritingLeavesTheOldFileAndNoTemporaryFile() throws IOException {
        Path target = dir.resolve("out.png");
        Files.writeString(target, "previous image");
        IOException failure = new IOException("disk full (simulated) while writing " + target);
        try (StagedFiles staged = new StagedFiles()) {
            IOException e = assertThrows(IOException.class, () -> staged.stage(target, temp -> {
                try (OutputStream out = Files.newOutputStream(temp)) {
                    out.write(new byte[1000]); // half an image
                }
                throw failure;
            }));
            assertSame(failure, e);
        }
        assertEquals(List.of("out.png"), listing());
        assertEquals("previous image", Files.readString(target));
    }

    @Test
    void failureInALaterFileCommitsNothing() throws IOException {
        Path image = dir.resolve("out.png");
        Path sidecar = dir.resolve("out.pgw");
        try (StagedFiles staged = new StagedFiles()) {
            staged.stageText(image, "image");
            assertEquals(1, listing().size()); // the hidden temporary file only
            assertTrue(listing().get(0).startsWith(".out.png.") && listing().get(0).endsWith(".tmp"));
            assertThrows(IllegalStateException.class, () -> staged.stage(sidecar, temp -> {
                throw new IllegalStateException("bug in a sidecar writer");
            }));
        }
        assertEquals(List.of(), listing());
    }

    @Test
    void commitReplacesInOrderAndLeavesNoTemporaryFiles() throws IOException {
        Path image = dir.resolve("out.png");
        Path sidecar = dir.resolve("out.pgw");
        Files.writeString(image, "old");
        try (StagedFiles staged = new StagedFiles()) {
            staged.stageText(image, "new image");
            staged.stageText(sidecar, "world");
            assertEquals("old", Files.readString(image), "nothing visible before commit");
            staged.commit();
        }
        assertEquals(List.of("out.pgw", "out.png"), listing());
        assertEquals("new image", Files.readString(image));
        assertEquals("world", Files.readString(sidecar));
    }

    @Test
    void aDirectoryInTheWayIsReported() throws IOException {
        Path target = Files.createDirectory(dir.resolve("out.png"));
        IOException e = assertThrows(IOException.class, () -> StagedFiles.checkWritable(target));
        assertTrue(e.getMessage().contains("directory"), e.getMessage());
    }
}
