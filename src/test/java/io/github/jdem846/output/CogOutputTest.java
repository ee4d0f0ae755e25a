package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import io.github.jdem846.testing.TestDems;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Cloud-Optimized GeoTIFFs read back with TwelveMonkeys: tiled, one overview per halving until one tile holds the
 * picture, full resolution equal to the input, every overview equal to box means computed here directly from the
 * full-resolution pixels (no-data left out of gray means, colour weighted by alpha); the file laid out as GDAL's COG
 * driver lays it out; BigTIFF when forced.
 */
class CogOutputTest {

    @TempDir
    Path dir;

    static final int TILE = 32;
    /** 300 × 203 at tiles of 32: overviews 150×101, 75×50, 37×25, 18×12 (as gdal_translate -of COG makes them). */
    static final ShadedRelief RELIEF = SyntheticDems.shadedRelief(300, 203, 7);
    static final WriteOptions COG = WriteOptions.defaults().withTiffLayout(WriteOptions.TiffLayout.COG)
            .withCogTileSize(TILE);

    /** Big Tujunga's extent and CRS (EPSG:32611). */
    static final GeoReference GEO = GeoReference.of(TestDems.load(TestDems.BIG_TUJUNGA).geometry());

    /** The relief's colours with partial alphas, and transparent pixels whose colour bits are not 0. */
    static int[] rgba() {
        int[] argb = RELIEF.argb().clone();
        for (int i = 0; i < argb.length; i++) {
            int x = i % RELIEF.width();
            int y = i / RELIEF.width();
            if ((x + 2 * y) % 5 == 0) {
                argb[i] = ((x * 37 + y * 11) & 0xFF) << 24 | (argb[i] & 0xFFFFFF);
            } else if (argb[i] == 0 && (x + y) % 3 == 0) {
                argb[i] = 0x00FF00FF;                         // transparent magenta: must not tint the means
            }
        }
        return argb;
    }

    @Test
    void grayCogHasTilesOverviewsAndBoxMeansWithoutNoData() throws IOException {
        Path file = dir.resolve("shade.tif");
        ImageOutput.writeGray(file, RELIEF.gray(), RELIEF.width(), RELIEF.height(), GEO, COG.withNoData(0));
        List<Raster> levels = readLevels(file, 1);
        int[][] sizes = {{300, 203}, {150, 101}, {75, 50}, {37, 25}, {18, 12}};
        assertEquals(sizes.length, levels.size(), "full resolution and four overviews");
        for (int k = 0; k < sizes.length; k++) {
            Raster level = levels.get(k);
            assertEquals(sizes[k][0], level.getWidth(), "width of level " + k);
            assertEquals(sizes[k][1], level.getHeight(), "height of level " + k);
            int[] expected = grayMeans(RELIEF.gray(), RELIEF.width(), RELIEF.height(), k, 0);
            assertArrayEquals(expected, level.getSamples(0, 0, level.getWidth(), level.getHeight(), 0, (int[]) null),
                    "level " + k);
        }
        long valid = Arrays.stream(grayMeans(RELIEF.gray(), RELIEF.width(), RELIEF.height(), 2, 0)).filter(v -> v != 0)
                .count();
        assertTrue(valid > 0 && valid < 75 * 50, "the overview has valid and no-data pixels: " + valid);
    }

    @Test
    void rgbaCogStreamedInBandsAveragesColourByAlpha() throws IOException {
        int[] argb = rgba();
        int w = RELIEF.width();
        Path file = dir.resolve("relief.tif");
        try (ImageSink sink = ImageOutput.openRgba(file, w, RELIEF.height(), GEO, COG)) {
            for (int y = 0; y < RELIEF.height(); y += 10) {
                int n = Math.min(10, RELIEF.height() - y);
                sink.appendRgba(Arrays.copyOfRange(argb, y * w, (y + n) * w), n);
            }
            sink.commit();
        }
        List<Raster> levels = readLevels(file, 4);
        assertEquals(5, levels.size());
        for (int k = 0; k < levels.size(); k++) {
            Raster level = levels.get(k);
            int[] expected = argbMeans(argb, w, RELIEF.height(), k);
            for (int b = 0; b < 4; b++) {
                int shift = b == 3 ? 24 : 16 - 8 * b;
                int[] channel = Arrays.stream(expected).map(p -> p >>> shift & 0xFF).toArray();
                assertArrayEquals(channel, level.getSamples(0, 0, level.getWidth(), level.getHeight(), b,
                        (int[]) null), "level " + k + " band " + b);
            }
        }
    }

    /** GDAL's COG layout, as its validator checks it: ghost block, IFDs in order, then tiles smallest first. */
    @Test
    void layoutIsGdalsIfdsFirstThenTilesSmallestLevelFirst() throws IOException {
        Path file = dir.resolve("shade.tif");
        ImageOutput.writeGray(file, RELIEF.gray(), RELIEF.width(), RELIEF.height(), null, COG);
        Tiff tiff = Tiff.read(file);
        assertEquals(42, tiff.version);
        String ghost = new String(tiff.bytes, 8, 43 + 140, StandardCharsets.US_ASCII);
        assertEquals("GDAL_STRUCTURAL_METADATA_SIZE=000140 bytes\nLAYOUT=IFDS_BEFORE_DATA\nBLOCK_ORDER=ROW_MAJOR\n"
                + "BLOCK_LEADER=SIZE_AS_UINT4\nBLOCK_TRAILER=LAST_4_BYTES_REPEATED\nKNOWN_INCOMPATIBLE_EDITION=NO\n ",
                ghost);
        assertEquals(192, tiff.ifds.get(0).offset, "the first IFD right after the ghost block, word-aligned");
        assertEquals(5, tiff.ifds.size());
        for (int k = 1; k < tiff.ifds.size(); k++) {
            assertTrue(tiff.ifds.get(k).offset > tiff.ifds.get(k - 1).offset, "IFDs in order of levels");
        }
        long previousLevelStart = Long.MAX_VALUE;
        for (int k = 0; k < tiff.ifds.size(); k++) {
            Tiff.Ifd ifd = tiff.ifds.get(k);
            assertEquals(k == 0 ? -1 : 1, ifd.value(254), "NewSubfileType");
            assertEquals(TILE, ifd.value(322));
            assertEquals(TILE, ifd.value(323));
            assertEquals(2, ifd.value(317), "predictor");
            long[] offsets = ifd.values(324);
            long[] counts = ifd.values(325);
            for (int t = 0; t < offsets.length; t++) {
                assertTrue(offsets[t] > tiff.ifds.get(tiff.ifds.size() - 1).offset, "tiles after the IFDs");
                ByteBuffer b = ByteBuffer.wrap(tiff.bytes).order(ByteOrder.LITTLE_ENDIAN);
                assertEquals(counts[t], b.getInt((int) offsets[t] - 4), "leader of tile " + t + " of level " + k);
                assertEquals(b.getInt((int) (offsets[t] + counts[t] - 4)), b.getInt((int) (offsets[t] + counts[t])),
                        "trailer of tile " + t + " of level " + k);
                if (t > 0) {
                    assertEquals(offsets[t - 1] + counts[t - 1] + 8, offsets[t], "row-major, back to back");
                }
            }
            assertTrue(offsets[offsets.length - 1] < previousLevelStart, "level " + k + " before level " + (k - 1));
            previousLevelStart = offsets[0];
        }
        assertEquals(tiff.bytes.length, tiff.ifds.get(0).values(324)[tiff.ifds.get(0).values(324).length - 1]
                + tiff.ifds.get(0).values(325)[tiff.ifds.get(0).values(325).length - 1] + 4, "full resolution last");
    }

    /** A tiny threshold forces BigTIFF: strips and COG alike, read back by TwelveMonkeys with every pixel. */
    @Test
    void bigTiffWhenForcedHoldsTheSamePixels() throws IOException {
        int w = RELIEF.width();
        int h = RELIEF.height();
        for (WriteOptions options : List.of(WriteOptions.defaults(), COG)) {
            boolean cog = options.tiffLayout() == WriteOptions.TiffLayout.COG;
            Path big = dir.resolve(cog ? "big-cog.tif" : "big-strips.tif");
            try (FileImageSink sink = FileImageSink.open(big, w, h, 4, 8, GEO, options, null, 1000)) {
                sink.appendRgba(RELIEF.argb(), h);
                sink.commit();
            }
            Tiff tiff = Tiff.read(big);
            assertEquals(43, tiff.version, "BigTIFF");
            assertEquals(cog ? 5 : 1, tiff.ifds.size());
            assertEquals(16, tiff.ifds.get(0).type(cog ? 324 : 273), "LONG8 offsets");
            if (cog) {
                assertEquals(200, tiff.ifds.get(0).offset, "16-byte header, ghost block, word-aligned");
            }
            Raster raster = TiffTags.raster(big);
            for (int b = 0; b < 4; b++) {
                int shift = b == 3 ? 24 : 16 - 8 * b;
                assertArrayEquals(Arrays.stream(RELIEF.argb()).map(p -> p >>> shift & 0xFF).toArray(),
                        raster.getSamples(0, 0, w, h, b, (int[]) null), big + " band " + b);
            }
            Path classic = dir.resolve(cog ? "classic-cog.tif" : "classic-strips.tif");
            ImageOutput.writeRgba(classic, RELIEF.argb(), w, h, GEO, options);
            assertEquals(42, Tiff.read(classic).version);
        }
    }

    /** A mean that rounds to the no-data value moves off it, to the side of the exact mean. */
    @Test
    void grayMeansThatRoundToNoDataStayValid() throws IOException {
        byte[] gray = {127, (byte) 129, (byte) 128, 126, (byte) 128, (byte) 128, (byte) 129, (byte) 128};
        List<Integer> overview = new ArrayList<>();
        OverviewPyramid pyramid = new OverviewPyramid(4, 2, 1, 1, 128, (level, row) -> {
            byte[] samples = new byte[row.width()];
            row.row(0, samples, 0);
            for (byte v : samples) {
                overview.add(v & 0xFF);
            }
        });
        pyramid.add(Arrays.copyOfRange(gray, 0, 4), 4);
        pyramid.add(Arrays.copyOfRange(gray, 4, 8), 4);
        // box 1: 127, 129 valid (exact 128) → 129; box 2: 128 no-data, 126, 129 → 127.5 rounds to 128 → 127
        assertEquals(List.of(129, 127), overview);
        assertEquals(List.of(129, 127), Arrays.stream(grayMeans(gray, 4, 2, 1, 128)).boxed().toList());
    }

    @Test
    void overviewCountIsGdals() {
        assertEquals(0, CogWriter.overviewCount(512, 512, 512));
        assertEquals(1, CogWriter.overviewCount(513, 1, 512));
        assertEquals(2, CogWriter.overviewCount(1197, 643, 512));   // GDAL: 598x321, 299x160
        assertEquals(4, CogWriter.overviewCount(300, 203, 32));
        assertEquals(7, CogWriter.overviewCount(60000, 60000, 512));
    }

    /** Pixels across (or down) level {@code k} of a picture {@code size} pixels across: halved k times, rounded down. */
    static int levelSize(int size, int k) {
        int s = size;
        for (int i = 0; i < k; i++) {
            s = Math.max(1, s / 2);
        }
        return s;
    }

    /** Where box {@code x} of level {@code k} starts and ends in full-resolution pixels: the last one at the edge. */
    private static int[] box(int x, int k, int levelSize, int size) {
        return new int[]{x << k, x == levelSize - 1 ? size : (x + 1) << k};
    }

    /** The full-resolution pixels (level 0) or the box means of level {@code k}, per the rules of the overviews. */
    static int[] grayMeans(byte[] gray, int w, int h, int k, int noData) {
        int lw = levelSize(w, k);
        int lh = levelSize(h, k);
        int[] out = new int[lw * lh];
        for (int y = 0; y < lh; y++) {
            int[] rows = box(y, k, lh, h);
            for (int x = 0; x < lw; x++) {
                int[] columns = box(x, k, lw, w);
                long sum = 0;
                long n = 0;
                for (int yy = rows[0]; yy < rows[1]; yy++) {
                    for (int xx = columns[0]; xx < columns[1]; xx++) {
                        int v = gray[yy * w + xx] & 0xFF;
                        if (v != noData) {
                            sum += v;
                            n++;
                        }
                    }
                }
                int mean = n == 0 ? noData : (int) Math.floor((double) sum / n + 0.5);
                if (n > 0 && mean == noData) {
                    mean = (double) sum / n >= noData && noData < 255 ? noData + 1 : noData - 1;
                }
                out[y * lw + x] = mean;
            }
        }
        return out;
    }

    /** The same for RGBA: alpha the plain mean, colour weighted by alpha, (0, 0, 0, 0) where all are transparent. */
    static int[] argbMeans(int[] argb, int w, int h, int k) {
        int lw = levelSize(w, k);
        int lh = levelSize(h, k);
        int[] out = new int[lw * lh];
        for (int y = 0; y < lh; y++) {
            int[] rows = box(y, k, lh, h);
            for (int x = 0; x < lw; x++) {
                int[] columns = box(x, k, lw, w);
                long[] weighted = new long[3];
                long alphas = 0;
                long n = 0;
                for (int yy = rows[0]; yy < rows[1]; yy++) {
                    for (int xx = columns[0]; xx < columns[1]; xx++) {
                        int p = argb[yy * w + xx];
                        int a = p >>> 24;
                        for (int c = 0; c < 3; c++) {
                            weighted[c] += (long) (p >>> (16 - 8 * c) & 0xFF) * a;
                        }
                        alphas += a;
                        n++;
                    }
                }
                if (k == 0) {
                    out[y * lw + x] = argb[y * w + x];
                } else if (alphas > 0) {
                    int a = (int) Math.floor((double) alphas / n + 0.5);
                    int r = (int) Math.floor((double) weighted[0] / alphas + 0.5);
                    int g = (int) Math.floor((double) weighted[1] / alphas + 0.5);
                    int b = (int) Math.floor((double) weighted[2] / alphas + 0.5);
                    out[y * lw + x] = a << 24 | r << 16 | g << 8 | b;
                }
            }
        }
        return out;
    }

    /** Every image of the file (full resolution, then the overviews), checked tiled by {@link #TILE}. */
    static List<Raster> readLevels(Path file, int bands) throws IOException {
        ImageReader reader = new TIFFImageReaderSpi().createReaderInstance(null);
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in);
            List<Raster> levels = new ArrayList<>();
            for (int i = 0; i < reader.getNumImages(true); i++) {
                assertTrue(reader.isImageTiled(i), "level " + i + " tiled");
                assertEquals(TILE, reader.getTileWidth(i));
                assertEquals(TILE, reader.getTileHeight(i));
                Raster raster = reader.readRaster(i, null);
                assertEquals(bands, raster.getNumBands());
                levels.add(raster);
            }
            return levels;
        } finally {
            reader.dispose();
        }
    }

    /** A minimal little-endian TIFF/BigTIFF structure reader: the IFD chain and integer tag values. */
    static final class Tiff {
        final byte[] bytes;
        final int version;
        final List<Ifd> ifds = new ArrayList<>();

        record Ifd(long offset, java.util.Map<Integer, long[]> values, java.util.Map<Integer, Integer> types) {
            long value(int tag) {
                long[] v = values.get(tag);
                return v == null ? -1 : v[0];
            }

            long[] values(int tag) {
                return values.get(tag);
            }

            int type(int tag) {
                return types.get(tag);
            }
        }

        private Tiff(byte[] bytes) {
            this.bytes = bytes;
            ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
            assertEquals('I', b.get(0));
            this.version = b.getShort(2);
            boolean big = version == 43;
            long next = big ? b.getLong(8) : b.getInt(4) & 0xFFFFFFFFL;
            while (next != 0) {
                int at = (int) next;
                long n = big ? b.getLong(at) : b.getShort(at) & 0xFFFF;
                int entry = at + (big ? 8 : 2);
                java.util.Map<Integer, long[]> values = new java.util.TreeMap<>();
                java.util.Map<Integer, Integer> types = new java.util.TreeMap<>();
                for (int i = 0; i < n; i++, entry += big ? 20 : 12) {
                    int tag = b.getShort(entry) & 0xFFFF;
                    int type = b.getShort(entry + 2);
                    long count = big ? b.getLong(entry + 4) : b.getInt(entry + 4) & 0xFFFFFFFFL;
                    int size = switch (type) {
                        case 3 -> 2;
                        case 4 -> 4;
                        case 16 -> 8;
                        default -> 0;
                    };
                    types.put(tag, type);
                    if (size == 0) {
                        continue;
                    }
                    int valueAt = entry + (big ? 12 : 8);
                    if (size * count > (big ? 8 : 4)) {
                        valueAt = (int) (big ? b.getLong(valueAt) : b.getInt(valueAt) & 0xFFFFFFFFL);
                    }
                    long[] v = new long[(int) count];
                    for (int j = 0; j < count; j++) {
                        int p = valueAt + j * size;
                        v[j] = size == 2 ? b.getShort(p) & 0xFFFF : size == 4 ? b.getInt(p) & 0xFFFFFFFFL : b.getLong(p);
                    }
                    values.put(tag, v);
                }
                ifds.add(new Ifd(at, values, types));
                next = big ? b.getLong(entry) : b.getInt(entry) & 0xFFFFFFFFL;
            }
        }

        static Tiff read(Path file) throws IOException {
            return new Tiff(Files.readAllBytes(file));
        }
    }
}
