package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A sink writes all or nothing: closed without a commit, or after a failure, it leaves no file behind (temporary or
 * scratch) and an existing file of the target's name unchanged; misuse is refused before it can break the file.
 */
class ImageSinkTest {

    @TempDir
    Path dir;

    private static final WriteOptions COG = WriteOptions.defaults().withTiffLayout(WriteOptions.TiffLayout.COG)
            .withCogTileSize(16);

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private ImageSink open(String layout, Path file, int w, int h) throws IOException {
        return switch (layout) {
            case "png", "strips" -> ImageOutput.openGray(file, w, h, null, WriteOptions.defaults());
            default -> ImageOutput.openGray(file, w, h, null, COG);
        };
    }

    @ParameterizedTest
    @ValueSource(strings = {"png", "strips", "cog"})
    void closedWithoutCommitTheOldFileStaysAndNothingElse(String layout) throws IOException {
        Path file = dir.resolve(layout.equals("png") ? "out.png" : "out.tif");
        Files.writeString(file, "old");
        int w = 100;
        int h = 90;
        try (ImageSink sink = open(layout, file, w, h)) {
            sink.appendGray(new byte[w * 40], 40);
            assertEquals(40, sink.rowsWritten());
            List<String> during = listing();
            assertTrue(during.size() >= 2, "a temporary file next to the target: " + during);
            if (layout.equals("cog")) {
                assertTrue(during.stream().anyMatch(n -> n.startsWith(".out.tif.") && n.endsWith(".level0.tmp"))
                        && during.stream().anyMatch(n -> n.endsWith(".level2.tmp")), "the levels' tiles: " + during);
            }
        }
        assertEquals(List.of(file.getFileName().toString()), listing());
        assertEquals("old", Files.readString(file));
    }

    @ParameterizedTest
    @ValueSource(strings = {"png", "strips", "cog"})
    void aCommitWithRowsMissingFailsAndLeavesTheOldFile(String layout) throws IOException {
        Path file = dir.resolve(layout.equals("png") ? "out.png" : "out.tif");
        Files.writeString(file, "old");
        try (ImageSink sink = open(layout, file, 20, 20)) {
            sink.appendGray(new byte[20 * 19], 19);
            IllegalStateException e = assertThrows(IllegalStateException.class, sink::commit);
            assertTrue(e.getMessage().contains("19 of 20 rows"), e.getMessage());
        }
        assertEquals(List.of(file.getFileName().toString()), listing());
        assertEquals("old", Files.readString(file));
    }

    @Test
    void misuseIsRefusedAndTheSinkStaysUsable() throws IOException {
        Path file = dir.resolve("m.png");
        try (ImageSink sink = ImageOutput.openRgba(file, 4, 3, null, WriteOptions.defaults())) {
            assertThrows(IllegalStateException.class, () -> sink.appendGray(new byte[4], 1), "gray into RGBA");
            IllegalArgumentException shortArray = assertThrows(IllegalArgumentException.class,
                    () -> sink.appendRgba(new int[7], 2));
            assertTrue(shortArray.getMessage().contains("need 8"), shortArray.getMessage());
            sink.appendRgba(new int[8], 2);
            sink.appendRgba(new int[0], 0);
            IllegalStateException pastBottom = assertThrows(IllegalStateException.class,
                    () -> sink.appendRgba(new int[8], 2));
            assertTrue(pastBottom.getMessage().contains("pass the bottom"), pastBottom.getMessage());
            sink.appendRgba(new int[]{-1, -1, -1, -1}, 1);
            WriteResult result = sink.commit();
            assertEquals(file, result.image());
            assertThrows(IllegalStateException.class, sink::commit, "twice");
            assertThrows(IllegalStateException.class, () -> sink.appendRgba(new int[4], 1), "after the commit");
        }
        assertEquals(List.of("m.png"), listing());
        assertEquals(0xFFFFFFFF, javax.imageio.ImageIO.read(file.toFile()).getRGB(3, 2));
    }

    @Test
    void aMissingDirectoryIsReportedAtOpenAndNothingIsCreated() {
        Path file = dir.resolve("no/such/out.tif");
        IOException e = assertThrows(IOException.class, () -> ImageOutput.openGray(file, 10, 10, null, COG));
        assertTrue(e.getMessage().contains(file.toString()) && e.getMessage().contains("does not exist"),
                e.getMessage());
        assertFalse(Files.exists(dir.resolve("no")));
    }

    @Test
    void theCogLayoutIsForGeoTiffsOfEightBitSamples() throws IOException {
        Path png = dir.resolve("c.png");
        IllegalArgumentException files = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.filesWritten(png, COG));
        assertTrue(files.getMessage().contains(".tif or .tiff") && files.getMessage().contains("c.png"),
                files.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ImageOutput.openRgba(png, 2, 2, null, COG));
        assertThrows(IllegalArgumentException.class, () -> ImageOutput.writeGray(png, new byte[4], 2, 2, null, COG));
        IllegalArgumentException floats = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.writeFloat(dir.resolve("f.tif"), new float[4], 2, 2, null, COG));
        assertTrue(floats.getMessage().contains("float32") && floats.getMessage().contains("strip"),
                floats.getMessage());
        assertThrows(IllegalArgumentException.class, () -> COG.withCogTileSize(500), "not a multiple of 16");
        assertEquals(List.of(), listing());
    }
}
