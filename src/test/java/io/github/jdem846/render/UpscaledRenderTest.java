package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.Upsampling;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.ArrayDeque;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;

/**
 * A picture eight times larger than its DEM is computed on a smooth surface: no step the size of a cell in the
 * hillshade of a plane or a cone, one smooth shadow for a spike, anti-aliased no-data edges.
 */
class UpscaledRenderTest {

    private static final int F = 8;
    private static final LightDirection SUN = new LightDirection(315, 45);
    private static final Renderer RENDERER = new Renderer(new RenderSettings(2, 64));

    private static float[] hillshade(Dem dem) throws InterruptedException {
        return RENDERER.illumination(dem, HillshadeMethod.HORN.stage(HillshadeOptions.DEFAULTS),
                LightField.uniform(SUN), RenderProgress.NONE);
    }

    private static Dem enlarged(Dem dem, Upsampling method) {
        return DemResampler.resample(dem, dem.width() * F, dem.height() * F, method);
    }

    @Test
    void theHillshadeOfAnEnlargedPlaneIsOneValueUpToTheEdges() throws InterruptedException {
        Dem plane = SyntheticDems.surface(20, 15, 10, (x, y) -> 0.3 * x + 0.1 * y + 50);
        Dem big = enlarged(plane, DemResampler.DEFAULT_UPSAMPLING);
        float[] light = hillshade(big);
        float first = light[big.width() + 1];
        for (int r = 1; r < big.height() - 1; r++) {
            for (int c = 1; c < big.width() - 1; c++) {
                assertEquals(first, light[r * big.width() + c], 1e-5, "pixel " + c + ", " + r);
            }
        }
    }

    /**
     * The largest change of 8-bit hillshade between neighbouring pixels, further than {@code clearance} pixels
     * from the apex (a kink of the cone itself) and two from the edges.
     */
    private static double largestStep(Dem big, float[] light, int clearance) {
        double largest = 0;
        int w = big.width();
        for (int r = 2; r < big.height() - 3; r++) {
            for (int c = 2; c < w - 3; c++) {
                if (Math.hypot(c + 0.5 - w / 2.0, r + 0.5 - big.height() / 2.0) < clearance) {
                    continue;
                }
                largest = Math.max(largest, 255 * Math.max(Math.abs(light[r * w + c + 1] - light[r * w + c]),
                        Math.abs(light[(r + 1) * w + c] - light[r * w + c])));
            }
        }
        return largest;
    }

    /**
     * The cone's own hillshade changes by up to 3.6 gray levels from pixel to pixel at the distance looked at (the
     * cone sampled at the picture's resolution); bilinear cells make steps of 60 and more at their edges.
     */
    @Test
    void theHillshadeOfAnEnlargedConeHasNoCellSizedSteps() throws InterruptedException {
        int n = 21;
        DoubleBinaryOperator cone = (x, y) -> 200 - 0.8 * Math.hypot(x - 105, y - 105);
        Dem coarse = SyntheticDems.surface(n, n, 10, cone);
        Dem exact = SyntheticDems.surface(n * F, n * F, 10.0 / F, cone);
        double own = largestStep(exact, hillshade(exact), 4 * F);
        Dem smooth = enlarged(coarse, DemResampler.DEFAULT_UPSAMPLING);
        Dem bilinear = enlarged(coarse, Upsampling.BILINEAR);
        double smoothStep = largestStep(smooth, hillshade(smooth), 4 * F);
        double bilinearStep = largestStep(bilinear, hillshade(bilinear), 4 * F);
        assertTrue(bilinearStep > 10 * own, "bilinear: " + bilinearStep + ", the cone's own: " + own);
        assertTrue(smoothStep < 1.5 * own, "smooth: " + smoothStep + ", the cone's own: " + own);
    }

    /** Pieces of the mask where it is more than half shadow, 4-connected. */
    private static int shadowPieces(float[] mask, int w, int h) {
        boolean[] seen = new boolean[mask.length];
        int pieces = 0;
        for (int start = 0; start < mask.length; start++) {
            if (seen[start] || mask[start] <= 0.5f) {
                continue;
            }
            pieces++;
            ArrayDeque<Integer> todo = new ArrayDeque<>();
            todo.add(start);
            seen[start] = true;
            while (!todo.isEmpty()) {
                int i = todo.poll();
                int c = i % w;
                int r = i / w;
                int[] next = {c > 0 ? i - 1 : -1, c < w - 1 ? i + 1 : -1, r > 0 ? i - w : -1, r < h - 1 ? i + w : -1};
                for (int j : next) {
                    if (j >= 0 && !seen[j] && mask[j] > 0.5f) {
                        seen[j] = true;
                        todo.add(j);
                    }
                }
            }
        }
        return pieces;
    }

    @Test
    void anEnlargedSpikeCastsOneShadowWhoseEdgeIsNotACellStaircase() throws InterruptedException {
        Dem spike = SyntheticDems.spike(15, 15, 10, 7, 7, 40);
        Dem big = enlarged(spike, DemResampler.DEFAULT_UPSAMPLING);
        Scene scene = Scene.defaults().withTint(null).withShadows(ShadowAlgorithm.SWEEP)
                .withLight(new LightDirection(90, 35));
        float[] mask = RENDERER.shadows(big, scene, RenderProgress.NONE);
        int w = big.width();
        assertEquals(1, shadowPieces(mask, w, big.height()));
        // the shadow's north edge, column by column west of the spike: it moves by at most a pixel or two between
        // neighbouring columns (a smooth curve), never by a cell's eight
        int previous = -1;
        int columns = 0;
        for (int c = 7 * F - 1; c >= 0; c--) {
            int top = -1;
            for (int r = 0; r < big.height() && top < 0; r++) {
                if (mask[r * w + c] > 0.5f) {
                    top = r;
                }
            }
            if (top < 0) {
                break;
            }
            if (previous >= 0) {
                assertTrue(Math.abs(top - previous) <= 2, "column " + c + ": " + top + " after " + previous);
            }
            previous = top;
            columns++;
        }
        assertTrue(columns > 2 * F, "a shadow longer than two cells: " + columns + " columns");
    }

    /**
     * The share of the shadow's edges (lit next to shadow, across or down) that lie on a line through cell centres,
     * where a bilinear surface's slope jumps (between pixels 8i + 3 and 8i + 4 of cell i).
     */
    private static double edgesOnCellEdges(float[] mask, int w, int h) {
        long edges = 0;
        long onCells = 0;
        for (int r = 0; r < h - 1; r++) {
            for (int c = 0; c < w - 1; c++) {
                boolean here = mask[r * w + c] > 0.5f;
                if (here != mask[r * w + c + 1] > 0.5f) {
                    edges++;
                    onCells += (c + 1) % F == F / 2 ? 1 : 0;
                }
                if (here != mask[(r + 1) * w + c] > 0.5f) {
                    edges++;
                    onCells += (r + 1) % F == F / 2 ? 1 : 0;
                }
            }
        }
        return (double) onCells / edges;
    }

    /**
     * On the real volcano eight times enlarged, the edges of cast and self shadows cross the lines through cell
     * centres as any curve does (an eighth of them lie there by chance); on the bilinear surface, whose slope jumps
     * there, one in five does.
     */
    @Test
    void shadowEdgesOfARealDemDoNotFollowItsCells() throws InterruptedException {
        Dem volcano = TestDems.load(TestDems.VOLCANO);
        Scene scene = Scene.defaults().withTint(null).withShadows(ShadowAlgorithm.SWEEP)
                .withLight(new LightDirection(135, 20));
        double[] share = new double[2];
        Upsampling[] methods = {DemResampler.DEFAULT_UPSAMPLING, Upsampling.BILINEAR};
        for (int i = 0; i < 2; i++) {
            Dem big = enlarged(volcano, methods[i]);
            share[i] = edgesOnCellEdges(RENDERER.shadows(big, scene, RenderProgress.NONE), big.width(),
                    big.height());
        }
        // measured: 0.133 and 0.211
        assertTrue(share[1] > 0.18, "bilinear: " + share[1]);
        assertTrue(share[0] < 0.15, "smooth: " + share[0]);
    }

    @Test
    void theEdgeOfNoDataIsAntiAliasedAndMonotone() throws InterruptedException {
        int n = 16;
        float[] v = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                v[r * n + c] = Math.hypot(c - 7.5, r - 7.5) < 6 ? 100 + c + r : Float.NaN;
            }
        }
        Dem disc = new Dem(v, GridGeometry.metric(n, n, 30));
        Dem big = enlarged(disc, DemResampler.DEFAULT_UPSAMPLING);
        int[] argb = RENDERER.render(big, Scene.defaults()).argb();
        int w = big.width();
        int partial = 0;
        // every row, from the centre column out to either side: alpha never rises, and reaches 0
        for (int r = 0; r < big.height(); r++) {
            for (int dir : new int[] {-1, 1}) {
                int last = 256;
                for (int c = w / 2; c >= 0 && c < w; c += dir) {
                    int alpha = argb[r * w + c] >>> 24;
                    assertTrue(alpha <= last, "row " + r + " column " + c + ": " + alpha + " after " + last);
                    if (alpha > 0 && alpha < 255) {
                        partial++;
                    }
                    last = alpha;
                }
                assertEquals(0, last, "row " + r);
            }
        }
        assertTrue(partial > 2 * big.height() / 2, "partial alpha on the edge: " + partial);
        assertEquals(255, argb[(w / 2) * w + w / 2] >>> 24);
    }
}
