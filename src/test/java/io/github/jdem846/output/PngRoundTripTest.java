package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Every PNG we write must decode with ImageIO to exactly the pixels we gave. */
class PngRoundTripTest {

    @TempDir
    Path dir;

    private static final WriteOptions OPTIONS = WriteOptions.defaults();

    /** Random ARGB including fully transparent pixels whose colour bits must survive too. */
    private static int[] randomArgb(int n, long seed) {
        Random random = new Random(seed);
        int[] argb = new int[n];
        for (int i = 0; i < n; i++) {
            argb[i] = random.nextInt();
            if (i % 3 == 0) {
                argb[i] &= 0x00FFFFFF; // alpha 0: a no-data pixel
            }
        }
        return argb;
    }

    private static byte[] randomGray(int n, long seed) {
        byte[] gray = new byte[n];
        new Random(seed).nextBytes(gray);
        return gray;
    }

    private static int[] readArgb(Path file, int width, int height) throws IOException {
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(width, back.getWidth());
        assertEquals(height, back.getHeight());
        assertEquals(4, back.getRaster().getNumBands());
        assertEquals(false, back.isAlphaPremultiplied());
        return back.getRGB(0, 0, width, height, null, 0, width);
    }

    private static byte[] readGray(Path file, int width, int height) throws IOException {
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(width, back.getWidth());
        assertEquals(height, back.getHeight());
        assertEquals(1, back.getRaster().getNumBands());
        int[] samples = back.getRaster().getSamples(0, 0, width, height, 0, (int[]) null);
        byte[] gray = new byte[samples.length];
        for (int i = 0; i < samples.length; i++) {
            gray[i] = (byte) samples[i];
        }
        return gray;
    }

    /** IHDR bit depth and colour type (PNG spec 11.2.2): bytes 24 and 25 of the file. */
    private static int[] bitDepthAndColourType(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] head = in.readNBytes(26);
            return new int[]{head[24], head[25]};
        }
    }

    @ParameterizedTest(name = "{0}×{1}")
    @CsvSource({"1, 1", "1, 97", "97, 1", "37, 23", "300, 200"})
    void rgbaRoundTripsExactly(int width, int height) throws IOException {
        int[] argb = randomArgb(width * height, width * 31L + height);
        Path file = dir.resolve("rgba.png");
        ImageOutput.writeRgba(file, argb, width, height, null, OPTIONS);
        assertArrayEquals(argb, readArgb(file, width, height));
        assertArrayEquals(new int[]{8, 6}, bitDepthAndColourType(file)); // 8-bit RGBA
    }

    @ParameterizedTest(name = "{0}×{1}")
    @CsvSource({"1, 1", "1, 97", "97, 1", "37, 23", "300, 200"})
    void grayRoundTripsExactly(int width, int height) throws IOException {
        byte[] gray = randomGray(width * height, width * 17L + height);
        Path file = dir.resolve("gray.png");
        ImageOutput.writeGray(file, gray, width, height, null, OPTIONS);
        assertArrayEquals(gray, readGray(file, width, height));
        assertArrayEquals(new int[]{8, 0}, bitDepthAndColourType(file)); // 8-bit gray
    }

    @Test
    void realisticReliefRoundTripsExactly() throws IOException {
        // Large enough (640 × 480 × 4 bytes) for the encoder to deflate several segments in parallel.
        ShadedRelief relief = SyntheticDems.shadedRelief(640, 480, 7);
        Path rgba = dir.resolve("relief.png");
        ImageOutput.writeRgba(rgba, relief.argb(), 640, 480, null, OPTIONS);
        assertArrayEquals(relief.argb(), readArgb(rgba, 640, 480));
        Path gray = dir.resolve("shade.png");
        ImageOutput.writeGray(gray, relief.gray(), 640, 480, null, OPTIONS);
        assertArrayEquals(relief.gray(), readGray(gray, 640, 480));
    }

    @ParameterizedTest(name = "level {0}")
    @ValueSource(ints = {0, 1, 5, 9})
    void everyCompressionLevelSerialOrParallelRoundTrips(int level) throws IOException {
        int[] argb = randomArgb(200 * 150, level);
        argb[0] = 0; // a transparent black corner
        for (boolean parallel : new boolean[]{false, true}) {
            Path file = dir.resolve("l" + level + parallel + ".png");
            ImageOutput.writeRgba(file, argb, 200, 150, null,
                    OPTIONS.withPngCompressionLevel(level).withParallelCompression(parallel));
            assertArrayEquals(argb, readArgb(file, 200, 150));
        }
    }

    @Test
    void bufferedImagesShareTheArrays() {
        int[] argb = {0x00123456, 0xFF000000, 0x80FFFFFF, 0x7F010203, 0xFFABCDEF, 0x00000000};
        BufferedImage image = ImageOutput.toBufferedImage(argb, 3, 2);
        assertEquals(BufferedImage.TYPE_INT_ARGB, image.getType());
        assertArrayEquals(argb, image.getRGB(0, 0, 3, 2, null, 0, 3));
        argb[4] = 0xFF00FF00;
        assertEquals(0xFF00FF00, image.getRGB(1, 1));

        byte[] gray = {0, 1, (byte) 128, (byte) 255};
        BufferedImage g = ImageOutput.toBufferedImage(gray, 4, 1);
        assertEquals(BufferedImage.TYPE_BYTE_GRAY, g.getType());
        assertArrayEquals(new int[]{0, 1, 128, 255}, g.getRaster().getSamples(0, 0, 4, 1, 0, (int[]) null));
    }
}
