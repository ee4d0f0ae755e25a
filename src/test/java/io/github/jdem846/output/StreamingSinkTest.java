package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * A picture appended band of rows by band of rows makes the file {@link ImageOutput#writeRgba} or
 * {@link ImageOutput#writeGray} makes of the whole picture, byte for byte, however the rows are cut: one row at a
 * time, odd bands, bands larger than a PNG segment, TIFF strip or COG tile row and not aligned with them, random
 * bands with empty appends between them; through one reused band array, as a renderer hands them over.
 */
class StreamingSinkTest {

    @TempDir
    Path dir;

    private static final ShadedRelief WIDE = SyntheticDems.shadedRelief(600, 1000, 3);
    private static final ShadedRelief SQUARE = SyntheticDems.shadedRelief(1500, 1500, 4);
    private static final ShadedRelief SMALL = SyntheticDems.shadedRelief(300, 203, 5);

    /** How to cut a picture of {@code height} rows into bands. */
    private record Cut(String name, int[] bands) {
        @Override
        public String toString() {
            return name;
        }
    }

    private static List<Cut> cuts(int height, int chunkRows) {
        List<Cut> cuts = new ArrayList<>();
        cuts.add(new Cut("1 row", fill(height, 1)));
        cuts.add(new Cut("7 rows", fill(height, 7)));
        cuts.add(new Cut("chunk + 3 rows (" + (chunkRows + 3) + ")", fill(height, chunkRows + 3)));
        Random random = new Random(height);
        List<Integer> bands = new ArrayList<>();
        for (int left = height; left > 0; ) {
            int n = random.nextInt(4) == 0 ? 0 : Math.min(left, 1 + random.nextInt(2 * chunkRows));
            bands.add(n);
            left -= n;
        }
        cuts.add(new Cut("random", bands.stream().mapToInt(Integer::intValue).toArray()));
        return cuts;
    }

    private static int[] fill(int height, int band) {
        int[] bands = new int[(height + band - 1) / band];
        Arrays.fill(bands, band);
        bands[bands.length - 1] = height - band * (bands.length - 1);
        return bands;
    }

    /** Rows of one PNG segment, one TIFF strip, one COG tile row: the chunks the encoders cut. */
    static Stream<Arguments> pictures() {
        WriteOptions cog = WriteOptions.defaults().withTiffLayout(WriteOptions.TiffLayout.COG).withCogTileSize(32);
        return Stream.of(
                Arguments.of("png", WIDE, true, WriteOptions.defaults(), PngWriter.SEGMENT_BYTES / (1 + 4 * 600)),
                Arguments.of("png", SQUARE, false, WriteOptions.defaults().withPngCompressionLevel(6),
                        PngWriter.SEGMENT_BYTES / 1501),
                Arguments.of("tif", WIDE, true, WriteOptions.defaults(), 65536 / (4 * 600)),
                Arguments.of("tif", SQUARE, false, WriteOptions.defaults().withNoData(0), 65536 / 1500),
                Arguments.of("tif", SMALL, true, cog, 32),
                Arguments.of("tif", SMALL, false, cog.withNoData(0), 32));
    }

    @ParameterizedTest(name = "{0} {1}×… rgba={2}")
    @MethodSource("pictures")
    void anyCutIntoBandsWritesTheWholePicturesBytes(String ext, ShadedRelief relief, boolean rgba,
                                                     WriteOptions options, int chunkRows) throws IOException {
        GeoReference geo = GeoReference.of(TestDems.load(TestDems.BIG_TUJUNGA).geometry());
        int w = relief.width();
        int h = relief.height();
        Path whole = dir.resolve("whole." + ext);
        if (rgba) {
            ImageOutput.writeRgba(whole, relief.argb(), w, h, geo, options);
        } else {
            ImageOutput.writeGray(whole, relief.gray(), w, h, geo, options);
        }
        byte[] expected = Files.readAllBytes(whole);
        assertTrue(chunkRows > 1 && chunkRows < h / 2, "more than two chunks of several rows: " + chunkRows);
        for (Cut cut : cuts(h, chunkRows)) {
            Path streamed = dir.resolve("streamed." + ext);
            int[] band = new int[w * (Arrays.stream(cut.bands()).max().orElse(1) + 1)];   // longer than needed
            byte[] grayBand = new byte[band.length];
            try (ImageSink sink = rgba ? ImageOutput.openRgba(streamed, w, h, geo, options)
                    : ImageOutput.openGray(streamed, w, h, geo, options)) {
                int y = 0;
                for (int n : cut.bands()) {
                    Arrays.fill(band, 0x5A5A5A5A);                         // what is left of the last band is garbage
                    Arrays.fill(grayBand, (byte) 0x5A);
                    if (rgba) {
                        System.arraycopy(relief.argb(), y * w, band, 0, n * w);
                        sink.appendRgba(band, n);
                    } else {
                        System.arraycopy(relief.gray(), y * w, grayBand, 0, n * w);
                        sink.appendGray(grayBand, n);
                    }
                    y += n;
                    assertEquals(y, sink.rowsWritten());
                }
                sink.commit();
            }
            assertArrayEquals(expected, Files.readAllBytes(streamed), ext + " cut into " + cut);
        }
    }

    /** Float32 GeoTIFFs (no public sink, but the same strips) and the same bands. */
    @Test
    void float32StripsStreamToTheSameBytes() throws IOException {
        int w = 700;
        int h = 90;
        float[] values = new float[w * h];
        Random random = new Random(9);
        for (int i = 0; i < values.length; i++) {
            values[i] = i % 11 == 0 ? Float.NaN : (float) random.nextGaussian() * 1000;
        }
        Path whole = dir.resolve("whole.tif");
        WriteOptions options = WriteOptions.defaults().withNoData(Double.NaN);
        ImageOutput.writeFloat(whole, values, w, h, null, options);
        Path streamed = dir.resolve("streamed.tif");
        try (FileImageSink sink = FileImageSink.open(streamed, w, h, 1, 32, null, options, Double.NaN,
                TiffDirectory.CLASSIC_LIMIT)) {
            for (int y = 0; y < h; y += 13) {
                int n = Math.min(13, h - y);
                sink.append(new Pixels.Float32(Arrays.copyOfRange(values, y * w, (y + n) * w), w, n));
            }
            sink.commit();
        }
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(streamed));
    }
}
