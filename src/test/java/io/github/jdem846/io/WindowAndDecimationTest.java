package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.BlockReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Properties of windowed and decimated reads: a window equals cropping the full read, a decimated read equals
 * block-averaging the full read (computed here independently), for raw rows, strips, tiles and text.
 */
class WindowAndDecimationTest {

    @TempDir
    Path tmp;

    /** Full reads are compared with the independent GridFloat loader first, so they can serve as reference. */
    private static Dem fullReference(Path file) throws IOException {
        Dem full = DemReader.read(file);
        String name = file.getFileName().toString();
        if (name.startsWith("bigtujunga_crop")) {
            assertSameValues(TestDems.load(TestDems.BIG_TUJUNGA).crop(420, 120, 600, 400), full, name);
        } else if (name.startsWith("luxembourg")) {
            assertSameValues(TestDems.load(TestDems.LUXEMBOURG), full, name);
        }
        return full;
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "testdata/dem/bigtujunga_srtm30m_utm11n.flt",
        "testdata/variants/bigtujunga_crop600x400_v01_int16_none_strip.tif",
        "testdata/variants/bigtujunga_crop600x400_v02_int16_lzw_pred2_strip16.tif",
        "testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif",
        "testdata/variants/bigtujunga_crop600x400_v11_float32_deflate_pred3_tile128_bigtiff_bigendian.tif",
        "testdata/variants/luxembourg_n01_float32_nan-nodata_deflate_pred3_tile32.tif",
        "testdata/formats/luxembourg.asc",
        "testdata/formats/luxembourg.bil"})
    void randomWindowsEqualCropsOfTheFullRead(String path) throws IOException {
        Path file = Path.of(path);
        Dem full = fullReference(file);
        Random random = new Random(path.hashCode());
        for (int i = 0; i < 12; i++) {
            int w = 1 + random.nextInt(full.width());
            int h = 1 + random.nextInt(full.height());
            int col = random.nextInt(full.width() - w + 1);
            int row = random.nextInt(full.height() - h + 1);
            Dem window = DemReader.read(file, ReadRequest.of(Window.cells(col, row, w, h)));
            String what = path + " window " + w + "×" + h + " at (" + col + ", " + row + ")";
            Dem expected = full.crop(col, row, w, h);
            assertSameValues(expected, window, what);
            assertEquals(expected.geometry(), window.geometry(), what);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "testdata/dem/bigtujunga_srtm30m_utm11n.flt",
        "testdata/variants/bigtujunga_crop600x400_v03_int16_packbits_strip.tif",
        "testdata/variants/bigtujunga_crop600x400_v05_float32_deflate_pred3_tile256.tif",
        "testdata/variants/bigtujunga_crop600x400_v11_float32_deflate_pred3_tile128_bigtiff_bigendian.tif",
        "testdata/variants/luxembourg_n01_float32_nan-nodata_deflate_pred3_tile32.tif",
        "testdata/variants/luxembourg_n03_int16_nodata-32768_packbits_bigendian.tif",
        "testdata/variants/luxembourg_g01_gridfloat_msbfirst.flt",
        "testdata/formats/luxembourg.asc"})
    void decimatedReadsEqualBlockAveragesOfTheFullRead(String path) throws IOException {
        Path file = Path.of(path);
        Dem full = fullReference(file);
        Random random = new Random(~path.hashCode());
        for (int d : new int[] {2, 3, 7, 16, 1000}) {
            assertDecimated(file, full, 0, 0, full.width(), full.height(), d, ReadRequest.decimated(d));
            int w = 1 + random.nextInt(full.width());
            int h = 1 + random.nextInt(full.height());
            int col = random.nextInt(full.width() - w + 1);
            int row = random.nextInt(full.height() - h + 1);
            assertDecimated(file, full, col, row, w, h, d, new ReadRequest(Window.cells(col, row, w, h), d));
        }
    }

    private static void assertDecimated(Path file, Dem full, int col, int row, int w, int h, int d,
                                        ReadRequest request) throws IOException {
        Dem actual = DemReader.read(file, request);
        Dem expected = blockAverage(full.crop(col, row, w, h), d);
        String what = file + " decimation " + d + " of " + w + "×" + h + " at (" + col + ", " + row + ")";
        assertEquals(expected.width(), actual.width(), what);
        assertEquals(expected.height(), actual.height(), what);
        float[] e = expected.backingArray();
        float[] a = actual.backingArray();
        for (int i = 0; i < e.length; i++) {
            if (Float.isNaN(e[i])) {
                assertTrue(Float.isNaN(a[i]), what + ": cell " + i + " should be no-data, is " + a[i]);
            } else {
                assertEquals(e[i], a[i], Math.abs(e[i]) * 1e-6, what + ": cell " + i);
            }
        }
        GridGeometry g = full.geometry().window(col, row, w, h).decimate(d, d);
        assertEquals(g, actual.geometry(), what + ": geometry");
    }

    /** Mean of the valid cells of each d×d block (partial at the edges), NaN when none is valid. */
    private static Dem blockAverage(Dem dem, int d) {
        int ow = (dem.width() + d - 1) / d;
        int oh = (dem.height() + d - 1) / d;
        float[] out = new float[ow * oh];
        for (int by = 0; by < oh; by++) {
            for (int bx = 0; bx < ow; bx++) {
                double sum = 0;
                int n = 0;
                for (int y = by * d; y < Math.min(dem.height(), (by + 1) * d); y++) {
                    for (int x = bx * d; x < Math.min(dem.width(), (bx + 1) * d); x++) {
                        float v = dem.get(x, y);
                        if (!Float.isNaN(v)) {
                            sum += v;
                            n++;
                        }
                    }
                }
                out[by * ow + bx] = n == 0 ? Float.NaN : (float) (sum / n);
            }
        }
        return new Dem(out, dem.geometry().decimate(d, d));
    }

    @Test
    void decimationIsABoxFilterNotPointSampling() throws IOException {
        // 4×2 GridFloat; 2×2 blocks: {1, 3, 5, 7} → 4 and {NaN, 10, 20, -9999} → 15.
        Path flt = gridFloat(4, 2, "-9999", new float[] {1, 3, Float.NaN, 10, 5, 7, 20, -9999});
        Dem dem = DemReader.read(flt, ReadRequest.decimated(2));
        assertEquals(2, dem.width());
        assertEquals(1, dem.height());
        assertEquals(4f, dem.get(0, 0));
        assertEquals(15f, dem.get(1, 0));
    }

    @Test
    void aBlockMeanEqualToTheNoDataValueStaysValid() throws IOException {
        // NODATA 5: the block {4, 6, 5, 5} has valid cells 4 and 6, whose mean is 5 — an elevation, not no-data.
        Path flt = gridFloat(2, 2, "5", new float[] {4, 6, 5, 5});
        Dem dem = DemReader.read(flt, ReadRequest.decimated(2));
        assertEquals(5f, dem.get(0, 0));
        assertEquals(0, dem.statistics().noDataCount());
        assertEquals(5.0, dem.declaredNoData());
    }

    @Test
    void allNoDataBlockIsNaN() throws IOException {
        Path flt = gridFloat(2, 2, "-9999", new float[] {-9999, -9999, Float.NaN, -9999});
        Dem dem = DemReader.read(flt, ReadRequest.decimated(2));
        assertTrue(Float.isNaN(dem.get(0, 0)));
    }

    @Test
    void worldWindowSelectsTheCellsItTouches() throws IOException {
        Path file = Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");
        Dem full = DemReader.read(file);
        GridGeometry g = full.geometry();
        // Exactly on cell edges: columns 10..29, rows 5..14.
        Window exact = Window.world(g.originX() + 10 * 30, g.originY() - 15 * 30, g.originX() + 30 * 30,
                g.originY() - 5 * 30);
        assertSameValues(full.crop(10, 5, 20, 10), DemReader.read(file, ReadRequest.of(exact)), "edge-aligned");
        // Inside cells: touches columns 10..30 and rows 5..15.
        Window inside = Window.world(g.originX() + 10.5 * 30, g.originY() - 15.5 * 30, g.originX() + 30.2 * 30,
                g.originY() - 5.9 * 30);
        assertSameValues(full.crop(10, 5, 21, 11), DemReader.read(file, ReadRequest.of(inside)), "partial cells");
        // Larger than the grid: clipped to it.
        Window larger = Window.world(g.originX() - 1e5, g.southY() - 1e5, g.eastX() + 1e5, g.originY() + 1e5);
        assertSameValues(full, DemReader.read(file, ReadRequest.of(larger)), "clipped");
        Window outside = Window.world(g.eastX() + 1, g.southY(), g.eastX() + 100, g.originY());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DemReader.read(file, ReadRequest.of(outside)));
        assertTrue(e.getMessage().contains("does not intersect"), e.getMessage());
    }

    @Test
    void cellWindowOutsideTheGridIsRefusedWithTheGridSize() {
        Path file = Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DemReader.read(file, ReadRequest.of(Window.cells(590, 0, 20, 10))));
        assertTrue(e.getMessage().contains("600×400"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Window.cells(-1, 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new ReadRequest(null, 0));
    }

    @Test
    void bandRowsAreMultiplesOfTheBlockAndCoverTheWindow() {
        for (int natural : new int[] {1, 6, 16, 128, 256, 400, 10_000}) {
            for (int d : new int[] {1, 2, 3, 7, 16, 1000}) {
                for (int h : new int[] {1, 5, 400, 3601}) {
                    int rows = BlockReader.bandRows(natural, d, 600, h, 1L << 20);
                    assertEquals(0, rows % d, "natural " + natural + ", d " + d + ", h " + h);
                    assertTrue(rows >= 1 && rows <= ((h + d - 1) / d) * d, "rows " + rows);
                }
            }
        }
    }

    private Path gridFloat(int cols, int rows, String noData, float[] values) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(values.length * 4).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : values) {
            b.putFloat(v);
        }
        Path flt = tmp.resolve("g.flt");
        Files.write(flt, b.array());
        Files.writeString(tmp.resolve("g.hdr"), "ncols " + cols + "\nnrows " + rows
                + "\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value " + noData + "\nbyteorder LSBFIRST\n");
        return flt;
    }
}
