package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Random;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The soft sweep's one walk over all the disk's elevations ({@code SunSweep.runLevels}) against its definition, hard
 * sweeps one elevation after another: the highest shaded elevation of every cell must be the same, for whole grids
 * and windows, projected and lat/lon grids (up to the pole), suns straddling the horizon or near the zenith, and
 * grids with no-data.
 */
class SoftSweepOneWalkTest {

    private static final double[] ELEVATIONS = {0.1, 0.3, 2, 5, 20, 45, 89.8};
    private static final double[] AZIMUTHS = {0, 45, 100, 250, 300};
    private static final ShadowOptions HARD = ShadowOptions.DEFAULTS;

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(3);

    private static int[] assertSameLevels(Dem dem, LightDirection light, CellWindow window) {
        double r = ShadowOptions.DEFAULTS.sunDiameterDegrees() / 2;
        double[] levels = ShadowAlgorithm.softLevels(light.elevationDegrees(), r);
        ForkJoinPool pool = POOL.get();
        int[] oneWalk = ShadowAlgorithm.highestBlockedInOneWalk(dem, light, HARD, pool, window, levels);
        assertNotNull(oneWalk, "a grid with the default options takes the one walk");
        int[] reference = ShadowAlgorithm.highestBlockedLevelByLevel(dem, light, HARD, pool, window, levels);
        assertArrayEquals(reference, oneWalk, light + " " + window);
        return oneWalk;
    }

    @Test
    void realDemsWholeGrids() throws IOException {
        Dem bigTujunga = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.flt")).crop(400, 100, 300, 220);
        Dem volcano = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.flt"));
        Dem lux = DemReader.read(Path.of("testdata/dem/luxembourg_srtm30s_wgs84.flt"));
        // Luxembourg's border of no-data on a projected grid of 900 m cells
        Dem luxMetric = new Dem(lux.backingArray().clone(), GridGeometry.metric(lux.width(), lux.height(), 900));
        Dem jacksboro = DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.flt")).crop(100, 80, 200, 150);
        long between = 0;
        // projected grids, and lat/lon grids (a step length per row: the other lockstep walk)
        for (Dem dem : new Dem[] {bigTujunga, volcano, luxMetric, lux, jacksboro}) {
            for (double e : ELEVATIONS) {
                for (double a : AZIMUTHS) {
                    LightDirection light = new LightDirection(a, e);
                    int[] levels = assertSameLevels(dem, light, CellWindow.whole(dem.width(), dem.height()));
                    int top = ShadowAlgorithm.softLevels(e, ShadowOptions.DEFAULTS.sunDiameterDegrees() / 2).length - 1;
                    for (int k : levels) {
                        between += k >= 0 && k < top ? 1 : 0;
                    }
                }
            }
        }
        assertTrue(between > 1000, "the comparison must include penumbra cells, got " + between);
    }

    @Test
    void windowsAndNoDataStripes() {
        Random rnd = new Random(530);
        for (int t = 0; t < 40; t++) {
            int w = 30 + rnd.nextInt(90);
            int h = 30 + rnd.nextInt(90);
            Dem dem = SyntheticDems.rough(w, h, 10 + rnd.nextDouble() * 40, rnd.nextLong(),
                    50 + rnd.nextDouble() * 400);
            float[] v = dem.backingArray();
            int from = rnd.nextInt(w);
            for (int y = 0; y < h; y++) {
                for (int x = from; x < Math.min(w, from + 1 + rnd.nextInt(3)); x++) {
                    v[y * w + x] = Float.NaN;
                }
            }
            GridGeometry g = t % 2 == 0 ? dem.geometry()
                    : new GridGeometry(w, h, 20, t % 4 == 1 ? 89.9 : -30 + rnd.nextDouble() * 60, 0.0003, 0.0004,
                            CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
            Dem withNoData = new Dem(v, g);
            LightDirection light = new LightDirection(rnd.nextDouble() * 360, 0.05 + rnd.nextDouble() * 30);
            int cw = 1 + rnd.nextInt(w);
            int ch = 1 + rnd.nextInt(h);
            CellWindow window = new CellWindow(rnd.nextInt(w - cw + 1), rnd.nextInt(h - ch + 1), cw, ch);
            assertSameLevels(withNoData, light, window);
            assertSameLevels(withNoData, light, CellWindow.whole(w, h));
        }
    }

    @Test
    void otherCasesKeepTheLevelByLevelPath() {
        Dem metric = SyntheticDems.rough(60, 50, 30, 7L, 300);
        LightDirection light = new LightDirection(250, 5);
        double[] levels = ShadowAlgorithm.softLevels(5, ShadowOptions.DEFAULTS.sunDiameterDegrees() / 2);
        CellWindow whole = CellWindow.whole(60, 50);
        ForkJoinPool pool = POOL.get();
        assertNull(ShadowAlgorithm.highestBlockedInOneWalk(metric, light, HARD.withEarthCurvature(true), pool, whole,
                levels), "curvature");
        assertNull(ShadowAlgorithm.highestBlockedInOneWalk(metric, light, HARD.withThinFeatures(true), pool, whole,
                levels), "thin features");
    }
}
