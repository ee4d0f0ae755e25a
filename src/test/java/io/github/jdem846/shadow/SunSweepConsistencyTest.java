package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.PoolExtension;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The sweep's fast path (a block of lines walked in lockstep, hard shadows on uniform projected grids) against its
 * straightforward line-by-line path, cell for cell and bit for bit; and the mask's independence of the pool size
 * and of the window (computeWindow = the same cells of compute), on real DEMs (projected and geographic) and on
 * seeded synthetic ones with no-data stripes, Earth curvature and geographic cells.
 */
class SunSweepConsistencyTest {

    private static final ShadowOptions THIN = ShadowOptions.DEFAULTS.withThinFeatures(true);

    private static final String[] REAL_DEMS = {"bigtujunga_srtm30m_utm11n", "jacksboro_srtm3s_wgs84",
        "luxembourg_srtm30s_wgs84", "maungawhau-volcano_10m_nztm-approx",
        "vancouver-island_topobathy_2min_mercator"};
    private static final double[] ELEVATIONS = {2, 5, 20, 45};
    private static final double[] AZIMUTHS = {0, 45, 90, 160, 250, 300, 359.999};

    @RegisterExtension
    static final PoolExtension POOLS = new PoolExtension(1, 2, 3);

    private static Dem real(String name) throws IOException {
        return DemReader.read(Path.of("testdata/dem/" + name + ".flt"));
    }

    /** The sweep with the lockstep fast path allowed or not. */
    private static float[] sweep(Dem dem, LightDirection light, ShadowOptions options, boolean lockstep,
                                 ForkJoinPool pool) {
        float[] out = new float[dem.width() * dem.height()];
        RayFrame frame = new RayFrame(dem, light, options);
        new SunSweep(dem, frame, options.sampling() != Sampling.NEAREST, options.firstCellTest(), lockstep,
                options.terrainMinimum(), options.thinFeatures())
                .run(CellWindow.whole(dem.width(), dem.height()), Integer.MAX_VALUE, out, pool);
        return out;
    }

    private static int differences(float[] a, float[] b) {
        int n = 0;
        for (int i = 0; i < a.length; i++) {
            if (Float.floatToRawIntBits(a[i]) != Float.floatToRawIntBits(b[i])) {
                n++;
            }
        }
        return n;
    }

    @Test
    void lockstepEqualsLineByLineOnRealDems() throws IOException {
        int masks = 0;
        long shadowed = 0;
        for (String name : REAL_DEMS) {
            Dem dem = name.startsWith("bigtujunga") ? real(name).crop(300, 150, 400, 300) : real(name);
            for (double e : ELEVATIONS) {
                for (double a : AZIMUTHS) {
                    LightDirection light = new LightDirection(a, e);
                    for (ShadowOptions o : new ShadowOptions[] {ShadowOptions.DEFAULTS, THIN}) {
                        float[] fast = sweep(dem, light, o, true, POOLS.get(2));
                        float[] reference = sweep(dem, light, o, false, POOLS.get(1));
                        assertEquals(0, differences(fast, reference), name + " az " + a + " el " + e + " thin "
                                + o.thinFeatures());
                    }
                    float[] fast = sweep(dem, light, ShadowOptions.DEFAULTS, true, POOLS.get(2));
                    for (float s : fast) {
                        shadowed += s >= 0.5f ? 1 : 0;
                    }
                    masks++;
                }
            }
        }
        assertEquals(REAL_DEMS.length * ELEVATIONS.length * AZIMUTHS.length, masks);
        assertTrue(shadowed > 10_000, "the comparison must include shadowed cells, got " + shadowed);
    }

    @Test
    void lockstepEqualsLineByLineWithNoDataAndEveryAzimuth() {
        Random rnd = new Random(846);
        for (int t = 0; t < 60; t++) {
            Dem dem = synthetic(rnd, false);
            assertLockstepEqualsLineByLine(dem, t, rnd);
        }
    }

    /**
     * Lat/lon grids have a step length per row, which the lockstep path walks with the line-by-line path's own
     * arithmetic: the masks must be the same bit for bit, from mid latitudes to rows next to the pole.
     */
    @Test
    void lockstepEqualsLineByLineOnGeographicGrids() {
        Random rnd = new Random(4326);
        for (int t = 0; t < 60; t++) {
            Dem dem = t % 3 == 2 ? nearPole(rnd) : synthetic(rnd, true);
            assertLockstepEqualsLineByLine(dem, t, rnd);
        }
        // suns on the grid axes and diagonals (lines through cell centres, m = 0 or 1), south of the equator too
        double[] axes = {0, 45, 90, 135, 180, 225, 270, 315};
        for (int t = 0; t < axes.length; t++) {
            Dem north = synthetic(rnd, true);
            Dem south = new Dem(north.backingArray(), new GridGeometry(north.width(), north.height(), 150,
                    -rnd.nextDouble() * 50, 0.001, 0.002, CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84),
                    PixelAnchor.CORNER));
            for (Dem dem : new Dem[] {north, south}) {
                assertLockstepEqualsLineByLine(dem, new LightDirection(axes[t], 1 + rnd.nextDouble() * 30), t);
            }
        }
    }

    private static void assertLockstepEqualsLineByLine(Dem dem, int t, Random rnd) {
        assertLockstepEqualsLineByLine(dem, new LightDirection(t * 6 + rnd.nextDouble() * 6,
                0.5 + rnd.nextDouble() * 60), t);
    }

    private static void assertLockstepEqualsLineByLine(Dem dem, LightDirection light, int t) {
        for (ShadowOptions o : new ShadowOptions[] {ShadowOptions.DEFAULTS, THIN}) {
            float[] fast = sweep(dem, light, o, true, POOLS.get(3));
            float[] reference = sweep(dem, light, o, false, POOLS.get(1));
            assertEquals(0, differences(fast, reference), "trial " + t + " " + light + " thin "
                    + o.thinFeatures() + " on " + dem.geometry());
        }
    }

    /**
     * With nearest sampling, on the axes and the diagonal of square cells (lines through cell centres) the sweep is
     * the one-cell nearest march: the first-cell test must then look only at the next cell, not at eighths of it.
     */
    @Test
    void nearestSweepEqualsOneCellNearestMarchOnAxes() throws IOException {
        Dem dem = real("bigtujunga_srtm30m_utm11n").crop(420, 120, 300, 200);
        ShadowOptions nearest = ShadowOptions.DEFAULTS.withSampling(Sampling.NEAREST);
        long shadowed = 0;
        for (double a : new double[] {0, 45, 90, 180, 270}) {
            for (double e : new double[] {5, 20}) {
                LightDirection light = new LightDirection(a, e);
                ShadowMask sweep = ShadowAlgorithm.SWEEP.compute(dem, light, nearest, POOLS.get(2));
                ShadowMask march = ShadowAlgorithm.MARCH.compute(dem, light, nearest.withStep(StepSize.ONE_CELL),
                        POOLS.get(2));
                assertEquals(0, differences(sweep.backingArray(), march.backingArray()), "az " + a + " el " + e);
                shadowed += march.shadowedCount();
            }
        }
        assertTrue(shadowed > 1000, "the comparison must include shadowed cells, got " + shadowed);
    }

    @Test
    void sameMaskForAnyPoolSize() throws IOException {
        Dem dem = real("jacksboro_srtm3s_wgs84");
        for (ShadowOptions options : List.of(ShadowOptions.DEFAULTS, ShadowOptions.DEFAULTS.withSoftShadows(true),
                ShadowOptions.DEFAULTS.withEarthCurvature(true))) {
            for (double a : new double[] {160, 300}) {
                LightDirection light = new LightDirection(a, 5);
                float[] m1 = ShadowAlgorithm.SWEEP.compute(dem, light, options, POOLS.get(1)).backingArray();
                float[] m2 = ShadowAlgorithm.SWEEP.compute(dem, light, options, POOLS.get(2)).backingArray();
                float[] m3 = ShadowAlgorithm.SWEEP.compute(dem, light, options, POOLS.get(3)).backingArray();
                assertEquals(0, differences(m1, m2), options + " az " + a);
                assertEquals(0, differences(m1, m3), options + " az " + a);
            }
        }
    }

    @Test
    void windowEqualsWholeOnRealDems() throws IOException {
        Random rnd = new Random(4);
        for (String name : List.of("jacksboro_srtm3s_wgs84", "luxembourg_srtm30s_wgs84",
                "maungawhau-volcano_10m_nztm-approx")) {
            Dem dem = real(name);
            for (double e : ELEVATIONS) {
                for (double a : AZIMUTHS) {
                    LightDirection light = new LightDirection(a, e);
                    assertWindowsMatch(dem, light, ShadowOptions.DEFAULTS, rnd, 3, name);
                    assertWindowsMatch(dem, light, THIN, rnd, 1, name + " thin features");
                }
            }
        }
    }

    /**
     * Windows of seeded rough DEMs with no-data stripes, on metric and geographic grids, some with curvature: the
     * configurations where an earlier sweep let terrain beyond the halo tip the interpolation between two lines.
     */
    @Test
    void windowEqualsWholeOnSyntheticDems() {
        Random rnd = new Random(1);
        for (int t = 0; t < 400; t++) {
            Dem dem = synthetic(rnd, rnd.nextBoolean());
            LightDirection light = new LightDirection(rnd.nextDouble() * 360, 1 + rnd.nextDouble() * 60);
            ShadowOptions options = rnd.nextInt(4) == 0
                    ? ShadowOptions.DEFAULTS.withEarthCurvature(true, 0.13, 1e5) : ShadowOptions.DEFAULTS;
            assertWindowsMatch(dem, light, options, rnd, 10, "trial " + t);
            if (t % 2 == 0) {
                assertWindowsMatch(dem, light, options.withThinFeatures(true), rnd, 5, "thin features, trial " + t);
            }
        }
    }

    /**
     * A window read from a file is a grid of its own: its elevation range is not the file's. Told the file's
     * minimum, the sweep of the window and its halo gives the whole file's mask there, always; with the loaded
     * grid's own range (as before this option) some cases differ, so the test can fail.
     */
    @Test
    void aFileWindowToldTheFileMinimumEqualsTheWholeFile() {
        Random rnd = new Random(7);
        int sensitive = 0;
        for (int t = 0; t < 300; t++) {
            for (FileWindowCase c : FileWindowCase.random(rnd, 8)) {
                ShadowOptions told = ShadowOptions.DEFAULTS.withTerrainMinimum(c.dem().statistics().min());
                ForkJoinPool pool = t % 2 == 0 ? POOLS.get(1) : POOLS.get(2);
                assertEquals(0, c.differences(told, pool), "trial " + t + " " + c.light() + " " + c.window());
                if (t % 4 == 0) {
                    assertEquals(0, c.differences(told.withThinFeatures(true), POOLS.get(2)), "thin features, trial "
                            + t + " " + c.light() + " " + c.window());
                }
                sensitive += c.differences(ShadowOptions.DEFAULTS, POOLS.get(1)) > 0 ? 1 : 0;
            }
        }
        assertTrue(sensitive > 0, "some trials must depend on the file's minimum");
    }

    private static void assertWindowsMatch(Dem dem, LightDirection light, ShadowOptions options, Random rnd,
                                           int windows, String what) {
        ShadowMask whole = ShadowAlgorithm.SWEEP.compute(dem, light, options, POOLS.get(2));
        int width = dem.width();
        int height = dem.height();
        for (int q = 0; q < windows; q++) {
            int w = 1 + rnd.nextInt(width);
            int h = 1 + rnd.nextInt(height);
            CellWindow window = new CellWindow(rnd.nextInt(width - w + 1), rnd.nextInt(height - h + 1), w, h);
            ForkJoinPool pool = q % 2 == 0 ? POOLS.get(1) : POOLS.get(2);
            ShadowMask part = ShadowAlgorithm.SWEEP.computeWindow(dem, light, options, pool, window);
            List<String> bad = new ArrayList<>();
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    float expected = whole.get(window.col() + c, window.row() + r);
                    if (Float.compare(part.get(c, r), expected) != 0 && bad.size() < 5) {
                        bad.add("(" + (window.col() + c) + ", " + (window.row() + r) + ")");
                    }
                }
            }
            assertTrue(bad.isEmpty(), what + " " + light + " " + window + " differs at " + bad);
        }
    }

    /** Rough terrain as {@link #synthetic} on a lat/lon grid whose northern rows reach 89.9–90° N. */
    private static Dem nearPole(Random rnd) {
        Dem d = synthetic(rnd, false);
        int w = d.width();
        int h = d.height();
        double cell = 0.01 + rnd.nextDouble() * 0.05;
        GridGeometry g = new GridGeometry(w, h, -30, 90 - rnd.nextDouble() * 0.1, cell, cell,
                CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
        return new Dem(d.backingArray(), g);
    }

    /** Rough terrain 20–170 cells a side with up to three no-data stripes, metric or geographic (20–60° N). */
    private static Dem synthetic(Random rnd, boolean geographic) {
        int w = 20 + rnd.nextInt(150);
        int h = 20 + rnd.nextInt(150);
        float[] v = new float[w * h];
        double fx = rnd.nextDouble() * 0.3;
        double fy = rnd.nextDouble() * 0.3;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                v[y * w + x] = (float) (100 * Math.sin(x * fx) * Math.cos(y * fy) + 50 * rnd.nextDouble());
            }
        }
        int stripes = rnd.nextInt(4);
        for (int s = 0; s < stripes; s++) {
            int from = rnd.nextInt(Math.max(w, h));
            int span = 1 + rnd.nextInt(20);
            boolean vertical = rnd.nextBoolean();
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int at = vertical ? x : y;
                    if (at >= from && at < from + span) {
                        v[y * w + x] = Float.NaN;
                    }
                }
            }
        }
        GridGeometry g = geographic
                ? new GridGeometry(w, h, 10, 60 - rnd.nextDouble() * 40, 0.001, 0.001,
                        CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER)
                : GridGeometry.metric(w, h, 30);
        return new Dem(v, g);
    }
}
