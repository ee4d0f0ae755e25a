package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.testing.ExternalTools;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Full-resolution reads decode straight into the grid (raw rows and uncompressed TIFF blocks through a direct
 * buffer, no band buffer): the values, no-data cells and statistics are those written, for odd sizes, both byte
 * orders, rows longer than one read, windows and row bands read at once; and a source's rows read into the middle
 * of an array equal the same rows read on their own.
 */
class DirectReadTest {

    private static final float NO_DATA = -9999f;

    /** Integer elevations (exact in every sample type), one cell in 13 no-data. */
    private static float[] grid(int w, int h, long seed) {
        Random random = new Random(seed);
        float[] v = new float[w * h];
        for (int i = 0; i < v.length; i++) {
            v[i] = random.nextInt(13) == 0 ? NO_DATA : (float) (random.nextInt(6000) - 500);
        }
        return v;
    }

    private static Path gridFloat(Path dir, String name, float[] v, int w, int h, ByteOrder order)
            throws IOException {
        Path flt = dir.resolve(name + ".flt");
        ByteBuffer b = ByteBuffer.allocate(v.length * 4).order(order);
        b.asFloatBuffer().put(v);
        Files.write(flt, b.array());
        Files.writeString(dir.resolve(name + ".hdr"), "ncols " + w + "\nnrows " + h + "\nxllcorner 440000\n"
                + "yllcorner 3940000\ncellsize 30\nNODATA_value " + (int) NO_DATA + "\nbyteorder "
                + (order == ByteOrder.BIG_ENDIAN ? "MSBFIRST" : "LSBFIRST") + "\n");
        return flt;
    }

    /** The values as read: no-data as NaN. */
    private static float[] expected(float[] v) {
        float[] e = v.clone();
        for (int i = 0; i < e.length; i++) {
            if (e[i] == NO_DATA) {
                e[i] = Float.NaN;
            }
        }
        return e;
    }

    private static float[] crop(float[] v, int w, int col, int row, int cw, int ch) {
        float[] c = new float[cw * ch];
        for (int r = 0; r < ch; r++) {
            System.arraycopy(v, (row + r) * w + col, c, r * cw, cw);
        }
        return c;
    }

    /** Whole reads in 1, 2 and 3 bands at once and random windows equal the values written. */
    private static void assertReadsEqual(Path file, float[] values, int w, int h, long seed) throws IOException {
        float[] all = expected(values);
        for (int parallelism : new int[] {1, 2, 3}) {
            LoadedDem loaded = DemReader.load(file, ReadRequest.FULL, parallelism, 1);
            assertArrayEquals(all, loaded.dem().backingArray(), file.getFileName() + " in " + parallelism);
            assertEquals(ElevationStatistics.of(all), loaded.sourceStatistics(), file.getFileName() + " stats");
            assertEquals(ElevationStatistics.of(all), loaded.dem().statistics(), file.getFileName() + " dem stats");
        }
        Random random = new Random(seed);
        for (int k = 0; k < 12; k++) {
            int cw = 1 + random.nextInt(w);
            int ch = 1 + random.nextInt(h);
            int col = random.nextInt(w - cw + 1);
            int row = random.nextInt(h - ch + 1);
            float[] crop = crop(all, w, col, row, cw, ch);
            LoadedDem window = DemReader.load(file, new ReadRequest(Window.cells(col, row, cw, ch), 1),
                    1 + k % 3, 1);
            String what = file.getFileName() + " window " + col + "," + row + " " + cw + "×" + ch;
            assertArrayEquals(crop, window.dem().backingArray(), what);
            assertEquals(ElevationStatistics.of(crop), window.sourceStatistics(), what);
        }
    }

    @Test
    void gridFloatOfOddSizeInBothByteOrders(@TempDir Path dir) throws IOException {
        int w = 1237;
        int h = 53;
        float[] v = grid(w, h, 1);
        for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
            Path flt = gridFloat(dir, "odd_" + order, v, w, h, order);
            assertReadsEqual(flt, v, w, h, 2);
        }
    }

    @Test
    void gridFloatRowsLongerThanOneReadAndOneRow(@TempDir Path dir) throws IOException {
        // 270 001 float32 cells = 1.03 MiB per row: each row read in column pieces
        int w = 270_001;
        float[] v = grid(w, 3, 3);
        assertReadsEqual(gridFloat(dir, "wide", v, w, 3, ByteOrder.BIG_ENDIAN), v, w, 3, 4);
        float[] one = grid(5, 1, 5);
        assertReadsEqual(gridFloat(dir, "one", one, 5, 1, ByteOrder.LITTLE_ENDIAN), one, 5, 1, 6);
    }

    @Test
    void rowsReadIntoTheMiddleOfAnArrayEqualRowsReadAlone(@TempDir Path dir) throws IOException {
        int w = 301;
        int h = 40;
        Path flt = gridFloat(dir, "middle", grid(w, h, 7), w, h, ByteOrder.BIG_ENDIAN);
        List<Path> files = new ArrayList<>(List.of(flt,
                Path.of("testdata/variants/bigtujunga_crop600x400_v01_int16_none_strip.tif"),
                Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif"),
                Path.of("testdata/variants/bigtujunga_crop600x400_v09_int16_none_strip_bigendian.tif"),
                Path.of("testdata/formats/volcano_sparse_tile16_nodata.tif"),
                Path.of("testdata/formats/volcano_uint8_jpeg_q95.tif")));
        for (Path file : files) {
            try (RasterSource source = DemReader.open(file)) {
                int cw = Math.min(37, source.info().width() - 5);
                int ch = Math.min(9, source.info().height() - 3);
                float[] alone = new float[cw * ch];
                source.readRows(5, 3, cw, ch, alone);
                float[] inside = new float[cw * ch + 20];
                Arrays.fill(inside, -1f);
                source.readRows(5, 3, cw, ch, inside, 11);
                assertArrayEquals(alone, Arrays.copyOfRange(inside, 11, 11 + cw * ch), file.toString());
                for (int i : new int[] {0, 10, 11 + cw * ch, inside.length - 1}) {
                    assertEquals(-1f, inside[i], file + ": cell " + i + " outside the rows");
                }
            }
        }
    }

    /**
     * Uncompressed GeoTIFFs as GDAL writes them from one GridFloat: tiles whose last column and row stick out,
     * strips of 7 rows (the last one short), big-endian, and other sample types; each equals the values written.
     */
    @Test
    void uncompressedTilesAndStripsEqualTheGridFloatTheyWereMadeFrom(@TempDir Path dir) throws IOException {
        assumeTrue(ExternalTools.onPath("gdal_translate"), "gdal-bin absent");
        int w = 419;
        int h = 283;
        float[] v = grid(w, h, 11);
        Path flt = gridFloat(dir, "source", v, w, h, ByteOrder.LITTLE_ENDIAN);
        String[][] variants = {
            {"tiles.tif", "-co", "TILED=YES", "-co", "BLOCKXSIZE=128", "-co", "BLOCKYSIZE=64"},
            {"tiles_be.tif", "-co", "TILED=YES", "-co", "ENDIANNESS=BIG"},
            {"strips7.tif", "-co", "BLOCKYSIZE=7"},
            {"strips_be_int16.tif", "-ot", "Int16", "-co", "ENDIANNESS=BIG", "-co", "BLOCKYSIZE=5"},
            {"tiles_int32.tif", "-ot", "Int32", "-co", "TILED=YES", "-co", "BLOCKXSIZE=32", "-co", "BLOCKYSIZE=48"},
            {"strips_float64.tif", "-ot", "Float64"},
        };
        for (String[] variant : variants) {
            Path tif = dir.resolve(variant[0]);
            List<String> command = new ArrayList<>(List.of("gdal_translate", "-q"));
            command.addAll(Arrays.asList(variant).subList(1, variant.length));
            command.addAll(List.of(flt.toString(), tif.toString()));
            ExternalTools.Result r = ExternalTools.run(command);
            assertEquals(0, r.exitCode(), command + ": " + r.err());
            assertReadsEqual(tif, v, w, h, 12);
        }
    }

    @Test
    void decimatedReadsStillAverageTheValuesRead(@TempDir Path dir) throws IOException {
        int w = 97;
        int h = 61;
        float[] v = grid(w, h, 13);
        Path flt = gridFloat(dir, "decimated", v, w, h, ByteOrder.BIG_ENDIAN);
        float[] all = expected(v);
        Dem d3 = DemReader.read(flt, new ReadRequest(null, 3));
        // the block at output (1, 2): rows 6-8, columns 3-5
        double sum = 0;
        int n = 0;
        for (int r = 6; r < 9; r++) {
            for (int c = 3; c < 6; c++) {
                float x = all[r * w + c];
                if (x == x) {
                    sum += x;
                    n++;
                }
            }
        }
        assertEquals(n == 0 ? Float.NaN : (float) (sum / n), d3.backingArray()[2 * d3.width() + 1]);
    }
}
