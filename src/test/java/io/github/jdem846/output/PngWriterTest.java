package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.pngencoder.PngEncoder;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import io.github.jdem846.testing.TestDems;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ForkJoinPool;
import java.util.zip.Adler32;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * The PNG file depends only on the image and the compression level: the same bytes on one thread or many, for any
 * pool; a valid zlib stream of several segments; rows filtered exactly as PngEncoder's predictor encoding filters
 * them, with the same IHDR and iCCP chunks.
 */
class PngWriterTest {

    private static final int W = 1100;
    private static final int H = 1000;
    private static final ShadedRelief RELIEF = SyntheticDems.shadedRelief(W, H, 21);
    @RegisterExtension
    static final PoolExtension POOLS = new PoolExtension(1, 2, 3, 5);

    @TempDir
    Path dir;

    private static List<BufferedImage> images() {
        return List.of(Rasters.argbImage(RELIEF.argb(), W, H), Rasters.grayImage(RELIEF.gray(), W, H));
    }

    private static byte[] encode(BufferedImage image, int level, boolean parallel) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            PngWriter.write(image, out, level, parallel);
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        return out.toByteArray();
    }

    @Test
    void theFileIsTheSameOnOneThreadOrMany() throws Exception {
        for (BufferedImage image : images()) {
            for (int level : new int[] {0, 1, 6}) {
                byte[] one = encode(image, level, false);
                String what = (image.getType() == BufferedImage.TYPE_BYTE_GRAY ? "gray" : "RGBA") + " level " + level;
                assertArrayEquals(one, encode(image, level, true), what + ", common pool");
                for (ForkJoinPool pool : POOLS.all()) {   // parallel streams run in the caller's pool
                    assertArrayEquals(one, pool.submit(() -> encode(image, level, true)).get(),
                            what + ", " + pool.getParallelism() + " threads");
                }
            }
        }
    }

    @Test
    void imageOutputWritesTheSameFileWithAndWithoutParallelCompression() throws IOException {
        Path serial = dir.resolve("serial.png");
        Path parallel = dir.resolve("parallel.png");
        WriteOptions options = WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE);
        ImageOutput.writeRgba(serial, RELIEF.argb(), W, H, null, options.withParallelCompression(false));
        ImageOutput.writeRgba(parallel, RELIEF.argb(), W, H, null, options.withParallelCompression(true));
        assertArrayEquals(Files.readAllBytes(serial), Files.readAllBytes(parallel));
        BufferedImage back = ImageIO.read(parallel.toFile());
        assertArrayEquals(RELIEF.argb(), back.getRGB(0, 0, W, H, null, 0, W));

        ImageOutput.writeGray(serial, RELIEF.gray(), W, H, null, options.withParallelCompression(false));
        ImageOutput.writeGray(parallel, RELIEF.gray(), W, H, null, options.withParallelCompression(true));
        assertArrayEquals(Files.readAllBytes(serial), Files.readAllBytes(parallel));
        int[] samples = ImageIO.read(parallel.toFile()).getRaster().getSamples(0, 0, W, H, 0, (int[]) null);
        for (int i = 0; i < samples.length; i++) {
            assertEquals(RELIEF.gray()[i] & 0xFF, samples[i], "sample " + i);
        }
    }

    @Test
    void theImageDataIsOneCompleteZlibStreamOfSeveralSegments() throws DataFormatException {
        for (BufferedImage image : images()) {
            int rowBytes = 1 + (image.getType() == BufferedImage.TYPE_BYTE_GRAY ? 1 : 4) * W;
            int rowsPerSegment = Math.max(1, PngWriter.SEGMENT_BYTES / rowBytes);
            assertTrue(H > rowsPerSegment, "the image spans several segments");
            Chunks png = Chunks.of(encode(image, 1, true));
            for (int i = 0; i < png.idatLengths.size() - 1; i++) {
                assertEquals(PngWriter.IDAT_BYTES, png.idatLengths.get(i), "IDAT " + i);
            }
            byte[] rows = inflate(png.idat);                 // zlib checks the Adler-32 at the end
            assertEquals(H * rowBytes, rows.length);
        }
    }

    @Test
    void rowsAreFilteredAndChunksWrittenAsPngEncoderDoes() throws DataFormatException, IOException {
        for (BufferedImage image : images()) {
            ByteArrayOutputStream reference = new ByteArrayOutputStream();
            new PngEncoder().withBufferedImage(image).withCompressionLevel(1).withPredictorEncoding(true)
                    .withMultiThreadedCompressionEnabled(false).toStream(reference);
            Chunks theirs = Chunks.of(reference.toByteArray());
            Chunks ours = Chunks.of(encode(image, 1, true));
            List<String> expected = theirs.others.stream().filter(c -> !c.startsWith("iCCP")).toList();
            assertEquals(expected, ours.others, "IHDR and IEND as PngEncoder's, no iCCP (gray values are display"
                    + " values, as gdaldem writes them)");
            assertArrayEquals(inflate(theirs.idat), inflate(ours.idat), "the filtered rows");
        }
    }

    @Test
    void grayShadingIsDeflatedSmallerThanWithStringMatching() throws Exception {
        Dem bt = TestDems.load(TestDems.BIG_TUJUNGA);
        byte[] gray = new Renderer(new RenderSettings(2, 256)).hillshadeGray(bt, HillshadeMethod.HORN,
                HillshadeOptions.DEFAULTS, LightField.uniform(new LightDirection(315, 45)), RenderProgress.NONE);
        BufferedImage image = Rasters.grayImage(gray, bt.width(), bt.height());
        byte[] png = encode(image, 1, true);
        BufferedImage back = ImageIO.read(new java.io.ByteArrayInputStream(png));
        assertArrayEquals(gray, ((java.awt.image.DataBufferByte) back.getRaster().getDataBuffer()).getData(),
                "decodes to the samples");
        byte[] idat = Chunks.of(png).idat;
        byte[] rows = inflate(idat);
        Deflater matching = new Deflater(1);
        matching.setInput(rows);
        matching.finish();
        byte[] buffer = new byte[rows.length + 1024];
        int matched = 0;
        while (!matching.finished()) {
            matched += matching.deflate(buffer, matched, buffer.length - matched);
        }
        matching.end();
        // Huffman coding alone: 410 kB for Big Tujunga's hillshade, against 462 kB with level-1 string matching
        assertTrue(idat.length < 0.95 * matched, idat.length + " bytes, string matching " + matched);
    }

    @Test
    void entropyIsTheHuffmanBoundInBits() {
        byte[] data = new byte[1024];
        assertEquals(0, PngWriter.entropyBits(data, 1024), 1e-9, "one value: no information");
        for (int i = 0; i < 1024; i++) {
            data[i] = (byte) i;
        }
        assertEquals(8 * 1024, PngWriter.entropyBits(data, 1024), 1e-6, "all 256 values alike: 8 bits each");
        assertEquals(8 * 256, PngWriter.entropyBits(data, 256), 1e-6, "only the first n bytes count");
        assertEquals(4 * 2, PngWriter.entropyBits(data, 4), 1e-6, "4 distinct bytes: 2 bits each");
        Arrays.fill(data, 0, 512, (byte) 7);
        Arrays.fill(data, 512, 1024, (byte) -1);
        assertEquals(1024, PngWriter.entropyBits(data, 1024), 1e-6, "two values, half each: 1 bit");
        Arrays.fill(data, 0, 768, (byte) 7);                           // p = 3/4 and 1/4
        double expected = 768 * Math.log(4.0 / 3) / Math.log(2) + 256 * 2;
        assertEquals(expected, PngWriter.entropyBits(data, 1024), 1e-6);
    }

    @Test
    void grayRunsAreDeflatedWithStringMatching() throws Exception {
        byte[] mask = new byte[W * H];
        for (int r = 200; r < 700; r++) {
            Arrays.fill(mask, r * W + 300, r * W + 300 + r, (byte) 255);       // a shadow, lit elsewhere
        }
        for (boolean parallel : new boolean[] {false, true}) {
            byte[] png = encode(Rasters.grayImage(mask, W, H), 1, parallel);
            byte[] rows = inflate(Chunks.of(png).idat);
            assertEquals(H * (W + 1), rows.length);
            int idat = Chunks.of(png).idat.length;
            // Huffman coding alone needs at least one bit per filtered byte: a quarter of that is string matching
            assertTrue(idat * 8L * 4 < rows.length, idat + " bytes for " + rows.length + " filtered bytes");
            BufferedImage back = ImageIO.read(new java.io.ByteArrayInputStream(png));
            assertArrayEquals(mask, ((java.awt.image.DataBufferByte) back.getRaster().getDataBuffer()).getData());
        }
    }

    @Test
    void adler32CombinesLikeOneChecksumOfTheWhole() {
        Random random = new Random(7);
        for (int round = 0; round < 200; round++) {
            byte[] data = new byte[random.nextInt(300_000)];
            random.nextBytes(data);
            if (round % 3 == 0) {
                Arrays.fill(data, (byte) 0xFF);             // the largest sums
            }
            int cut = data.length == 0 ? 0 : random.nextInt(data.length + 1);
            Adler32 a = new Adler32();
            a.update(data, 0, cut);
            Adler32 b = new Adler32();
            b.update(data, cut, data.length - cut);
            Adler32 whole = new Adler32();
            whole.update(data);
            assertEquals(whole.getValue(), PngWriter.combineAdler32(a.getValue(), b.getValue(), data.length - cut));
        }
    }

    /**
     * A picture of more than 2 GiB of filtered rows: the segments' checksums combine over a total past 2^31 bytes
     * (lengths are per segment, the running checksum carries no length). Reference: Adler-32 of data followed by
     * N zero bytes keeps s1 and adds N·s1 to s2, modulo 65521, by its definition.
     */
    @Test
    void adler32CombinesPastTwoGibibytes() {
        byte[] data = new byte[1000];
        new Random(11).nextBytes(data);
        Adler32 head = new Adler32();
        head.update(data);
        Adler32 zeros = new Adler32();
        zeros.update(new byte[PngWriter.SEGMENT_BYTES]);
        long combined = head.getValue();
        long n = 0;
        while (n <= Integer.MAX_VALUE + (long) PngWriter.SEGMENT_BYTES) {
            combined = PngWriter.combineAdler32(combined, zeros.getValue(), PngWriter.SEGMENT_BYTES);
            n += PngWriter.SEGMENT_BYTES;
        }
        long s1 = head.getValue() & 0xFFFF;
        long s2 = ((head.getValue() >>> 16) + n % 65521 * s1) % 65521;
        assertEquals(s2 << 16 | s1, combined, n + " bytes of zeros after the data");
    }

    @Test
    void zlibHeaderChecksAndNamesTheLevel() {
        int[] flevel = {0, 0, 1, 1, 1, 1, 2, 3, 3, 3};
        for (int level = 0; level <= 9; level++) {
            int flg = PngWriter.zlibFlags(level) & 0xFF;
            assertEquals(0, (0x78 * 256 + flg) % 31, "level " + level);
            assertEquals(flevel[level], flg >> 6, "level " + level);
            assertEquals(0, flg & 0x20, "no preset dictionary");
        }
    }

    private static byte[] inflate(byte[] zlib) throws DataFormatException {
        Inflater inflater = new Inflater();
        try {
            inflater.setInput(zlib);
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            byte[] buffer = new byte[1 << 16];
            while (!inflater.finished()) {
                int n = inflater.inflate(buffer);
                if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                    throw new AssertionError("the zlib stream ends early");
                }
                out.write(buffer, 0, n);
            }
            assertEquals(0, inflater.getRemaining(), "bytes after the zlib stream");
            return out.toByteArray();
        } finally {
            inflater.end();
        }
    }

    /** A PNG's chunks: the IDAT payloads joined, their lengths, and every other chunk as type + payload. */
    private record Chunks(byte[] idat, List<Integer> idatLengths, List<String> others) {
        static Chunks of(byte[] png) {
            ByteArrayOutputStream idat = new ByteArrayOutputStream();
            List<Integer> lengths = new ArrayList<>();
            List<String> others = new ArrayList<>();
            int p = 8;
            while (p < png.length) {
                int len = (png[p] & 0xFF) << 24 | (png[p + 1] & 0xFF) << 16 | (png[p + 2] & 0xFF) << 8
                        | png[p + 3] & 0xFF;
                String type = new String(png, p + 4, 4, StandardCharsets.US_ASCII);
                if (type.equals("IDAT")) {
                    idat.write(png, p + 8, len);
                    lengths.add(len);
                } else {
                    others.add(type + Arrays.toString(Arrays.copyOfRange(png, p + 8, p + 8 + len)));
                }
                p += 12 + len;
            }
            return new Chunks(idat.toByteArray(), lengths, others);
        }
    }
}
