package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import org.junit.jupiter.api.Test;

class DemResamplerTest {

    @Test
    void aSizeLargerThanAJavaArrayIsRefusedBeforeAllocating() {
        Dem dem = SyntheticDems.metric(2, 1, 10, new float[] {1, 2});
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DemResampler.resample(dem, 100_000, 53_718));
        assertTrue(e.getMessage().contains("100000×53718 = 5371800000 cells"), e.getMessage());
    }

    @Test
    void integerShrinkIsTheBlockMeanOfValidCells() {
        float n = Float.NaN;
        Dem dem = SyntheticDems.metric(4, 2, 10, new float[] {1, 3, n, n, 5, 7, n, 8});
        Dem out = DemResampler.resample(dem, 2, 1);
        assertEquals(4f, out.get(0, 0)); // (1+3+5+7)/4
        assertEquals(8f, out.get(1, 0)); // only the valid cell counts
        assertEquals(20.0, out.geometry().cellWidthMeters(0), 1e-12);
        assertEquals(20.0, out.geometry().cellHeightMeters(0), 1e-12);
    }

    @Test
    void allNoDataBlockIsNoData() {
        float n = Float.NaN;
        Dem dem = SyntheticDems.metric(2, 2, 1, new float[] {n, n, n, n});
        assertTrue(Float.isNaN(DemResampler.resample(dem, 1, 1).get(0, 0)));
    }

    @Test
    void fractionalShrinkPreservesTheMeanOfAPlaneAndTheExtent() {
        Dem real = TestDems.load(TestDems.BIG_TUJUNGA);
        Dem out = DemResampler.resample(real, 500, 300);
        assertEquals(500, out.width());
        assertEquals(300, out.height());
        assertEquals(real.geometry().eastX(), out.geometry().eastX(), 1e-6);
        assertEquals(real.geometry().southY(), out.geometry().southY(), 1e-6);
        // An area-weighted mean keeps the overall mean (all cells valid, each input cell counted once in total).
        double inMean = mean(real);
        double outMean = mean(out);
        assertEquals(inMean, outMean, 0.01);
        assertTrue(out.statistics().max() <= real.statistics().max());
        assertTrue(out.statistics().min() >= real.statistics().min());
    }

    @Test
    void enlargingAPlaneKeepsItAPlane() {
        float[] v = new float[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                v[r * 3 + c] = 2 * c + 5 * r;
            }
        }
        Dem out = DemResampler.resample(SyntheticDems.metric(3, 3, 1, v), 6, 6);
        // interior output cell (2, 3): centre at input coordinates x = (2.5)/2 − 0.5 = 0.75, y = 1.25
        assertEquals(2 * 0.75 + 5 * 1.25, out.get(2, 3), 1e-5);
    }

    @Test
    void sameSizeIsIdentity() {
        Dem dem = TestDems.load(TestDems.VOLCANO);
        assertSame(dem, DemResampler.resample(dem, dem.width(), dem.height()));
    }

    private static double mean(Dem d) {
        double s = 0;
        for (float f : d.backingArray()) {
            s += f;
        }
        return s / d.backingArray().length;
    }

    /**
     * A region of a resampled grid, computed from only the part of the full grid that {@code sourceSpan} says it
     * reads, is the same cells of the whole resample, bit for bit: shrinking, enlarging and mixed scales, with
     * no-data, regions at the edges and inside.
     */
    @Test
    void aRegionFromAPartEqualsTheSameCellsOfTheWholeResample() {
        Dem full = SyntheticDems.rough(97, 61, 30, 7, 400);
        float[] v = full.backingArray().clone();
        for (int i = 0; i < v.length; i += 13) {
            v[i] = Float.NaN;
        }
        full = new Dem(v, full.geometry());
        int[][] sizes = {{40, 25}, {31, 61}, {250, 150}, {60, 140}, {97, 30}};
        java.util.Random rnd = new java.util.Random(3);
        for (int[] size : sizes) {
            Dem whole = DemResampler.resample(full, size[0], size[1]);
            for (int t = 0; t < 12; t++) {
                int w = 1 + rnd.nextInt(size[0]);
                int h = 1 + rnd.nextInt(size[1]);
                int c = rnd.nextInt(size[0] - w + 1);
                int r = rnd.nextInt(size[1] - h + 1);
                int[] cols = DemResampler.sourceSpan(97, size[0], c, w);
                int[] rows = DemResampler.sourceSpan(61, size[1], r, h);
                Dem part = full.crop(cols[0], rows[0], cols[1] - cols[0], rows[1] - rows[0]);
                Dem region = DemResampler.resampleRegion(part, cols[0], rows[0], 97, 61, size[0], size[1],
                        c, r, w, h, whole.geometry().window(c, r, w, h), Upsampling.CATMULL_ROM);
                for (int y = 0; y < h; y++) {
                    for (int x = 0; x < w; x++) {
                        assertEquals(Float.floatToIntBits(whole.get(c + x, r + y)),
                                Float.floatToIntBits(region.get(x, y)), size[0] + "×" + size[1] + " at "
                                        + (c + x) + "," + (r + y));
                        assertEquals(whole.coverage(c + x, r + y), region.coverage(x, y));
                    }
                }
            }
        }
    }
}
