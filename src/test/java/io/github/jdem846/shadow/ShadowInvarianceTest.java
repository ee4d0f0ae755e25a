package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.testing.PoolExtension;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The mask depends on nothing but the DEM, the sun and the options: not on the thread count, not on the renderer's
 * tiles and threads, and a window computed alone equals the same cells of the whole grid (hard and soft shadows),
 * on a projected DEM (Big Tujunga, UTM) and on geographic ones (Luxembourg with its no-data border, Jacksboro).
 */
class ShadowInvarianceTest {

    private static final ShadowAlgorithm[] ALGORITHMS = {ShadowAlgorithm.MARCH, ShadowAlgorithm.SWEEP,
        ShadowAlgorithm.EXACT};
    @RegisterExtension
    static final PoolExtension POOLS = new PoolExtension(1, 2, 3);
    private static Dem bigTujunga;
    private static Dem luxembourg;
    private static Dem jacksboro;

    @BeforeAll
    static void start() throws IOException {
        bigTujunga = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"));
        luxembourg = DemReader.read(Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif"));
        jacksboro = DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
    }

    /**
     * The projected DEM an algorithm is run on here: the whole of Big Tujunga (1197×643) for the sweep, crops of it
     * (UTM geometry kept) for the march and for exact (eighth-cell steps) to keep the suite fast.
     */
    private static Dem projected(ShadowAlgorithm a) {
        return switch (a) {
            case SWEEP -> bigTujunga;
            case MARCH -> bigTujunga.crop(300, 100, 500, 400);
            default -> bigTujunga.crop(500, 200, 200, 150);
        };
    }

    @Test
    void theMaskIsTheSameForAnyPoolParallelism() {
        for (ShadowAlgorithm a : ALGORITHMS) {
            for (boolean soft : new boolean[] {false, true}) {
                ShadowOptions o = ShadowOptions.DEFAULTS.withSoftShadows(soft);
                for (Dem dem : new Dem[] {projected(a), luxembourg}) {
                    for (LightDirection l : soft ? new LightDirection[] {new LightDirection(250, 5)}
                            : new LightDirection[] {new LightDirection(250, 5), new LightDirection(160, 20)}) {
                        float[] one = null;
                        for (ForkJoinPool p : POOLS.all()) {
                            float[] m = a.compute(dem, l, o, p).backingArray();
                            if (one == null) {
                                one = m;
                            } else {
                                assertArrayEquals(one, m, a + " soft=" + soft + " " + l + " threads="
                                        + p.getParallelism());
                            }
                        }
                    }
                }
            }
        }
    }

    @Test
    void theRendererGivesTheSameShadowsAndPixelsForAnyTileSizeAndThreadCount() throws InterruptedException {
        Dem dem = bigTujunga.crop(420, 120, 300, 200);
        for (ShadowAlgorithm a : new ShadowAlgorithm[] {ShadowAlgorithm.MARCH, ShadowAlgorithm.SWEEP}) {
            Scene scene = Scene.defaults().withShadows(a).withLight(new LightDirection(250, 6));
            int[] reference = null;
            float[] referenceShadows = null;
            for (int[] setting : new int[][] {{1, 256}, {2, 16}, {3, 37}, {2, 100}}) {
                Renderer renderer = new Renderer(new RenderSettings(setting[0], setting[1]));
                int[] argb = renderer.render(dem, scene).argb();
                float[] shadows = renderer.shadows(dem, scene, RenderProgress.NONE);
                if (reference == null) {
                    reference = argb;
                    referenceShadows = shadows;
                    assertArrayEquals(a.compute(dem, new LightDirection(250, 6), ShadowOptions.DEFAULTS, POOLS.get(2))
                            .backingArray(), shadows, a + ": the renderer's shadows are the algorithm's mask");
                } else {
                    String what = a + " threads=" + setting[0] + " tile=" + setting[1];
                    assertArrayEquals(reference, argb, what + ": pixels");
                    assertArrayEquals(referenceShadows, shadows, what + ": shadows");
                }
            }
        }
    }

    /** Windows at the corners, along the edges, thin strips and single cells. */
    private static CellWindow[] windows(Dem dem) {
        int w = dem.width();
        int h = dem.height();
        return new CellWindow[] {
            new CellWindow(w / 3, h / 3, w / 4, h / 5),
            new CellWindow(0, 0, w / 5 + 1, h),
            new CellWindow(w - 13, h - 11, 13, 11),
            new CellWindow(0, h - 7, w, 7),
            new CellWindow(w - 1, 0, 1, h / 2),
            new CellWindow(w / 2, h / 2, 1, 1),
            new CellWindow(0, 0, 1, 1),
        };
    }

    @Test
    void aWindowEqualsTheSameCellsOfTheWholeGrid() {
        for (ShadowAlgorithm a : ALGORITHMS) {
            for (Dem dem : new Dem[] {projected(a), luxembourg, jacksboro}) {
                for (boolean soft : new boolean[] {false, true}) {
                    ShadowOptions o = ShadowOptions.DEFAULTS.withSoftShadows(soft);
                    for (LightDirection l : soft ? new LightDirection[] {new LightDirection(300, 5)}
                            : new LightDirection[] {new LightDirection(300, 5), new LightDirection(160, 20),
                                new LightDirection(45, 10)}) {
                        if (a == ShadowAlgorithm.EXACT && dem == jacksboro && (soft || l.elevationDegrees() != 20)) {
                            continue;
                        }
                        ShadowMask whole = a.compute(dem, l, o, POOLS.get(2));
                        for (CellWindow win : windows(dem)) {
                            ShadowMask part = a.computeWindow(dem, l, o, POOLS.get(2), win);
                            assertEquals(win.width(), part.width());
                            assertEquals(win.height(), part.height());
                            int differ = 0;
                            for (int r = 0; r < win.height(); r++) {
                                for (int c = 0; c < win.width(); c++) {
                                    if (part.get(c, r) != whole.get(win.col() + c, win.row() + r)) {
                                        differ++;
                                    }
                                }
                            }
                            assertEquals(0, differ, a + " soft=" + soft + " " + l + " " + win + " of " + dem.width()
                                    + "×" + dem.height() + ": cells that differ from the whole-grid mask");
                        }
                    }
                }
            }
        }
    }

    @Test
    void aWindowReadsOnlyItsHalo() {
        // Everything outside ShadowHalo.window(...) replaced by no-data: the window's mask must not change, so the
        // halo (upstream (zmax − tile min)/tan e plus a margin) really holds all the terrain that can shade it
        for (ShadowAlgorithm a : ALGORITHMS) {
            Dem dem = projected(a);
            for (LightDirection l : new LightDirection[] {new LightDirection(300, 5), new LightDirection(160, 20)}) {
                for (CellWindow win : windows(dem)) {
                    CellWindow halo = ShadowHalo.window(dem, l, ShadowOptions.DEFAULTS, win);
                    assertTrue(halo.col() <= win.col() && halo.colEnd() >= win.colEnd() && halo.row() <= win.row()
                            && halo.rowEnd() >= win.rowEnd(), "the halo contains the window");
                    float[] ref = a.computeWindow(dem, l, ShadowOptions.DEFAULTS, POOLS.get(2), win).backingArray();
                    float[] v = dem.backingArray().clone();
                    int removed = 0;
                    for (int r = 0; r < dem.height(); r++) {
                        for (int c = 0; c < dem.width(); c++) {
                            if (!halo.contains(c, r)) {
                                v[r * dem.width() + c] = Float.NaN;
                                removed++;
                            }
                        }
                    }
                    Dem masked = new Dem(v, dem.geometry());
                    float[] m = a.computeWindow(masked, l, ShadowOptions.DEFAULTS, POOLS.get(2), win).backingArray();
                    assertArrayEquals(ref, m, a + " " + l + " " + win + ": no-data outside the halo (" + removed
                            + " cells)");
                }
            }
        }
    }
}
