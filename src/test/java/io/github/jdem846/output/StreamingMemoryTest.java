package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.testing.TestJvm;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Streaming holds a band, not the picture: a JVM whose heap is smaller than the picture writes it as a PNG, a
 * stripped GeoTIFF and a COG band by band, and the files hold the picture's pixels. (Compressed on one thread, so
 * that the batches of compressed segments, which grow with the processors, stay small too.)
 */
class StreamingMemoryTest {

    static final int SIZE = 6144;
    static final int BAND = 200;

    /** A pixel of the picture: blocks of 64 × 64 (quick to compress) with a no-data corner, never held whole. */
    static int pixel(int x, int y) {
        return x + y < 300 ? 0 : 1 + (x / 64 * 7 + y / 64 * 13) % 254;
    }

    /** Runs in the small JVM: writes the three files given as arguments. */
    static final class Writer {
        public static void main(String[] args) throws IOException {
            WriteOptions serial = WriteOptions.defaults().withParallelCompression(false);
            WriteOptions cog = serial.withTiffLayout(WriteOptions.TiffLayout.COG).withNoData(0);
            List<WriteOptions> options = List.of(serial, serial.withNoData(0), cog);
            byte[] band = new byte[SIZE * BAND];
            for (int i = 0; i < args.length; i++) {
                try (ImageSink sink = ImageOutput.openGray(Path.of(args[i]), SIZE, SIZE, null, options.get(i))) {
                    for (int y0 = 0; y0 < SIZE; y0 += BAND) {
                        int rows = Math.min(BAND, SIZE - y0);
                        for (int r = 0; r < rows; r++) {
                            for (int x = 0; x < SIZE; x++) {
                                band[r * SIZE + x] = (byte) pixel(x, y0 + r);
                            }
                        }
                        sink.appendGray(band, rows);
                    }
                    sink.commit();
                }
            }
        }
    }

    @Test
    void aPictureLargerThanTheHeapIsWrittenBandByBand(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("big.png");
        Path strips = dir.resolve("big.tif");
        Path cog = dir.resolve("big-cog.tif");
        long heap = 16L << 20;
        Process p = new ProcessBuilder(List.of(TestJvm.java(), "-Xmx" + (heap >> 20) + "m", "-XX:+UseSerialGC",
                "-Djava.awt.headless=true", "-cp", TestJvm.classPath(), Writer.class.getName(), png.toString(),
                strips.toString(), cog.toString())).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        assertEquals(0, p.exitValue(), output);
        assertTrue((long) SIZE * SIZE > 1.4 * heap, "the picture is larger than the heap");
        try (var files = Files.list(dir)) {
            assertEquals(3, files.count(), "no temporary or scratch file left");
        }
        byte[] expected = new byte[SIZE * SIZE];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                expected[y * SIZE + x] = (byte) pixel(x, y);
            }
        }
        byte[] read = new byte[SIZE * SIZE];
        ImageIO.read(png.toFile()).getRaster().getDataElements(0, 0, SIZE, SIZE, read);
        assertArrayEquals(expected, read, "PNG");
        for (Path file : List.of(strips, cog)) {
            ImageReader reader = new TIFFImageReaderSpi().createReaderInstance(null);
            try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
                reader.setInput(in);
                reader.readRaster(0, null).getDataElements(0, 0, SIZE, SIZE, read);
                assertArrayEquals(expected, read, file.getFileName().toString());
                if (file == cog) {
                    assertEquals(1 + CogWriter.overviewCount(SIZE, SIZE, 512), reader.getNumImages(true));
                }
            } finally {
                reader.dispose();
            }
        }
    }
}
