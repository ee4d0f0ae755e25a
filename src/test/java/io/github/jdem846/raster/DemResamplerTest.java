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
                        c, r, w, h, whole.geometry().window(c, r, w, h), DemResampler.DEFAULT_UPSAMPLING);
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

    /** Cells at −1 m between cells at −50 m, row after row (a shoal one cell wide, across the grid). */
    private static Dem shoal() {
        float[] v = new float[6 * 4];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 6; c++) {
                v[r * 6 + c] = c == 2 || c == 3 ? -1 : -50;
            }
        }
        return SyntheticDems.metric(6, 4, 100, v);
    }

    @Test
    void catmullRomOvershootsAShoalIntoAnIslandAndTheClampedOneDoesNot() {
        // between x = 2 and 3, neighbours at −50: up to 2·(−50·−1/16) + 2·(−1·9/16) = +5.125 m
        Dem plain = DemResampler.resample(shoal(), 48, 32, Upsampling.CATMULL_ROM);
        Dem clamped = DemResampler.resample(shoal(), 48, 32, Upsampling.CLAMPED_CATMULL_ROM);
        Dem monotone = DemResampler.resample(shoal(), 48, 32, Upsampling.MONOTONE_CUBIC);
        // output column 24: centre at x = 24.5/8 − 0.5 = 2.5625
        assertTrue(plain.get(24, 16) > 4, "Catmull-Rom: " + plain.get(24, 16));
        assertEquals(-1f, clamped.get(24, 16));
        assertEquals(-1f, monotone.get(24, 16));
    }

    @Test
    void theSmoothSurfacesStayWithinTheCellsTheyRead() {
        Dem rough = SyntheticDems.rough(24, 18, 30, 11, 500);
        Dem clamped = DemResampler.resample(rough, 24 * 5, 18 * 5, Upsampling.CLAMPED_CATMULL_ROM);
        Dem monotone = DemResampler.resample(rough, 24 * 5, 18 * 5, Upsampling.MONOTONE_CUBIC);
        for (int r = 0; r < clamped.height(); r++) {
            for (int c = 0; c < clamped.width(); c++) {
                double x = (c + 0.5) / 5 - 0.5;
                double y = (r + 0.5) / 5 - 0.5;
                if (x < 0 || y < 0 || x > 23 || y > 17) {
                    continue; // the outer half cells go on linearly
                }
                int c0 = Math.min(22, (int) x);
                int r0 = Math.min(16, (int) y);
                float[] inner = {rough.get(c0, r0), rough.get(c0 + 1, r0), rough.get(c0, r0 + 1),
                    rough.get(c0 + 1, r0 + 1)};
                float lo = Math.min(Math.min(inner[0], inner[1]), Math.min(inner[2], inner[3]));
                float hi = Math.max(Math.max(inner[0], inner[1]), Math.max(inner[2], inner[3]));
                float m = monotone.get(c, r);
                assertTrue(m >= lo - 1e-3 && m <= hi + 1e-3, "monotone " + m + " outside " + lo + ".." + hi);
                float lo4 = Float.MAX_VALUE;
                float hi4 = -Float.MAX_VALUE;
                for (int j = Math.max(0, r0 - 1); j <= Math.min(17, r0 + 2); j++) {
                    for (int i = Math.max(0, c0 - 1); i <= Math.min(23, c0 + 2); i++) {
                        lo4 = Math.min(lo4, rough.get(i, j));
                        hi4 = Math.max(hi4, rough.get(i, j));
                    }
                }
                float k = clamped.get(c, r);
                assertTrue(k >= lo4 && k <= hi4, "clamped " + k + " outside " + lo4 + ".." + hi4);
            }
        }
    }

    /**
     * A straight edge of no-data along a cell edge: at a whole factor it falls on a pixel edge (coverage 1 on one
     * side, 0 on the other, nothing to blend); at 7.625 it crosses the middle of pixel 30, which is half covered.
     */
    @Test
    void theEdgeOfNoDataIsCoveredAsAPixelWideBoxWouldSeeIt() {
        float n = Float.NaN;
        float[] v = new float[8 * 2];
        for (int r = 0; r < 2; r++) {
            for (int c = 0; c < 8; c++) {
                v[r * 8 + c] = c < 4 ? 10 + c : n;
            }
        }
        Dem whole = DemResampler.resample(SyntheticDems.metric(8, 2, 10, v), 64, 16);
        assertEquals(1f, whole.coverage(31, 8));
        assertEquals(0f, whole.coverage(32, 8));
        assertTrue(Float.isNaN(whole.get(32, 8)));
        Dem out = DemResampler.resample(SyntheticDems.metric(8, 2, 10, v), 61, 16);
        assertTrue(out.hasCoverage());
        float last = 1;
        for (int c = 0; c < 61; c++) {
            float a = out.coverage(c, 8);
            assertTrue(a <= last, "column " + c);
            assertEquals(a == 0, Float.isNaN(out.get(c, 8)), "no-data exactly where nothing is covered, column " + c);
            assertEquals(c < 30 ? 1f : c == 30 ? 0.5f : 0f, a, 1e-6f, "column " + c);
            last = a;
        }
        assertEquals(13f, out.get(30, 8), 1e-4, "a half-covered pixel has the value of the data it covers");
    }
}
