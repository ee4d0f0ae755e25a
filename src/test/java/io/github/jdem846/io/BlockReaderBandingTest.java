package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.BlockReader;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The band-by-band machinery of {@link BlockReader} with bands far smaller than the windows (the real band sizes
 * make the test files fit in one band): windows and decimations straddling many band, strip and tile boundaries
 * equal the crop and block average of the full read.
 */
class BlockReaderBandingTest {

    /** A source whose reads are split into bands of about {@code cells} cells. */
    private record SmallBands(RasterSource source, long cells) implements RasterSource {
        @Override
        public DemInfo info() {
            return source.info();
        }

        @Override
        public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
            source.readRows(col, row, width, rows, dst);
        }

        @Override
        public int naturalRowBlock() {
            return source.naturalRowBlock();
        }

        @Override
        public long bandCells() {
            return cells;
        }

        @Override
        public void close() throws IOException {
            source.close();
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "testdata/dem/bigtujunga_srtm30m_utm11n.flt",
        "testdata/variants/bigtujunga_crop600x400_v02_int16_lzw_pred2_strip16.tif",
        "testdata/variants/bigtujunga_crop600x400_v06_float32_none_strip.tif",
        "testdata/variants/bigtujunga_crop600x400_v11_float32_deflate_pred3_tile128_bigtiff_bigendian.tif",
        "testdata/variants/luxembourg_n01_float32_nan-nodata_deflate_pred3_tile32.tif",
        "testdata/variants/luxembourg_n03_int16_nodata-32768_packbits_bigendian.tif",
        "testdata/formats/luxembourg.asc",
        "testdata/formats/luxembourg.bil"})
    void smallBandsGiveTheSameResult(String path) throws IOException {
        Path file = Path.of(path);
        Dem full = DemReader.read(file);
        Random random = new Random(path.hashCode() * 31L);
        for (int i = 0; i < 6; i++) {
            int d = new int[] {1, 2, 3, 7}[i % 4];
            int w = 1 + random.nextInt(full.width());
            int h = 1 + random.nextInt(full.height());
            int col = random.nextInt(full.width() - w + 1);
            int row = random.nextInt(full.height() - h + 1);
            long cells = (long) w * (1 + random.nextInt(40));
            Dem expected = blockAverage(full.crop(col, row, w, h), d);
            int outW = BlockReader.outputSize(w, d);
            float[] got = new float[outW * BlockReader.outputSize(h, d)];
            int[] rows = {0};
            try (RasterSource s = new SmallBands(DemReader.open(file), cells)) {
                BlockReader.read(s, Window.cells(col, row, w, h), d, s.info().noDataOrNaN(), (r, v) -> {
                    assertEquals(rows[0]++, r, "rows arrive in order");
                    System.arraycopy(v, 0, got, r * outW, outW);
                });
            }
            String what = path + ": d " + d + ", window " + w + "×" + h + " at (" + col + ", " + row + "), bands of "
                    + cells + " cells";
            float[] e = expected.backingArray();
            for (int k = 0; k < e.length; k++) {
                if (Float.isNaN(e[k])) {
                    assertTrue(Float.isNaN(got[k]), what + ": cell " + k);
                } else {
                    assertEquals(e[k], got[k], Math.abs(e[k]) * 1e-6, what + ": cell " + k);
                }
            }
        }
    }

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
}
