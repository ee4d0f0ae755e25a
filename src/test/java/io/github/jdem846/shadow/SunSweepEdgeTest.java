package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The sweep at the grid's outer edges, against rays worked out by hand and against the marches: a ray that has left
 * the grid (past the outer cell edges, the article's test 2) is lit, so the sweep must not shade a cell from terrain
 * its ray only meets beyond the edge, where the lines parallel to it read the edge cells (clamped) before.
 */
class SunSweepEdgeTest {

    private static final double[] AZIMUTHS = {20, 45, 135, 160, 250, 300};
    private static final double[] ELEVATIONS = {5, 20};

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(2);

    /**
     * Flat ground at 0 with 600 m spikes on the four edge rows/columns. Off the open squares of side 2 around the
     * spikes the bilinear surface is exactly 0, so a cell at 0 whose ray stays more than a cell (Chebyshev) from
     * every spike until it leaves the grid meets no terrain above it: lit, worked out from the geometry alone. Checked
     * for the cells whose ray leaves through a side edge (one the lines run along, not across) within four steps:
     * their neighbouring lines run on beyond where their ray has left and, before the fix, read the spikes there
     * from the clamped edge cells.
     */
    @Test
    void raysThatLeaveTheGridBesideASpikeAreLit() {
        int n = 40;
        float[] v = new float[n * n];
        int[][] spikes = {{n - 1, 10}, {n - 1, 30}, {0, 10}, {0, 30}, {10, 0}, {30, 0}, {10, n - 1}, {30, n - 1}};
        for (int[] s : spikes) {
            v[s[1] * n + s[0]] = 600f;
        }
        Dem dem = SyntheticDems.metric(n, n, 30, v);
        int constrained = 0;
        long shaded = 0;
        List<String> wrong = new ArrayList<>();
        for (double e : ELEVATIONS) {
            for (double a : AZIMUTHS) {
                LightDirection light = new LightDirection(a, e);
                float[] sweep = ShadowAlgorithm.SWEEP.compute(dem, light, ShadowOptions.DEFAULTS, POOL.get())
                        .backingArray();
                float[] exact = ShadowAlgorithm.EXACT.compute(dem, light, ShadowOptions.DEFAULTS, POOL.get())
                        .backingArray();
                double ux = Math.sin(Math.toRadians(a));
                double uy = -Math.cos(Math.toRadians(a));
                for (int r = 0; r < n; r++) {
                    for (int c = 0; c < n; c++) {
                        shaded += sweep[r * n + c] > 0.5f ? 1 : 0;
                        if (v[r * n + c] != 0 || !leavesBesideClear(c, r, ux, uy, n, spikes)) {
                            continue;
                        }
                        constrained++;
                        assertEquals(0f, exact[r * n + c], "exact at (" + c + ", " + r + ") az " + a + " el " + e);
                        if (sweep[r * n + c] != 0f) {
                            wrong.add("(" + c + ", " + r + ") az " + a + " el " + e);
                        }
                    }
                }
            }
        }
        assertTrue(wrong.isEmpty(), wrong.size() + " cells shaded by terrain their ray meets only beyond the edge: "
                + wrong.subList(0, Math.min(12, wrong.size())));
        assertTrue(constrained > 300, "the check must include cells at the side edges, got " + constrained);
        assertTrue(shaded > 500, "the spikes must cast shadows inside the grid, got " + shaded);
    }

    /**
     * True when the ray from cell (c, r) leaves the grid through a side edge (the x edges when the sun's larger grid
     * component is y, else the y edges) within 4 major steps, staying more than 1.05 cells (Chebyshev) from every
     * spike until then.
     */
    private static boolean leavesBesideClear(int c, int r, double ux, double uy, int n, int[][] spikes) {
        boolean yMajor = Math.abs(uy) > Math.abs(ux);
        double scale = 1 / Math.max(Math.abs(ux), Math.abs(uy));
        double dx = ux * scale / 64;
        double dy = uy * scale / 64;
        double x = c;
        double y = r;
        for (int q = 0; q <= 64 * 4; q++) {
            boolean outX = x < -0.5 || x > n - 0.5;
            boolean outY = y < -0.5 || y > n - 0.5;
            if (outX || outY) {
                return yMajor ? outX && !outY : outY && !outX;
            }
            for (int[] s : spikes) {
                if (Math.max(Math.abs(x - s[0]), Math.abs(y - s[1])) <= 1.05) {
                    return false;
                }
            }
            x += dx;
            y += dy;
        }
        return false;
    }

    /**
     * Real terrain (crops of Big Tujunga, each traced as a grid of its own): in the band of cells within two cells
     * of the grid's edge, the sweep shades no more cells that both {@code exact} and the bilinear quarter-cell march
     * leave lit than it does in the interior, relative to the number of cells (before the edge fix: about ten
     * times as many, 0.3–0.4 % of the band at 5°).
     */
    @Test
    void noExtraFalseShadowsAlongTheEdgesOfRealTerrain() throws IOException {
        Dem file = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"));
        int[][] crops = {{420, 120, 200, 150}, {800, 50, 200, 150}};
        ShadowOptions quarter = ShadowOptions.DEFAULTS.withStep(StepSize.QUARTER_CELL)
                .withSampling(Sampling.BILINEAR);
        long edgeCells = 0;
        long edgeFalse = 0;
        long innerCells = 0;
        long innerFalse = 0;
        long shaded = 0;
        for (int[] cr : crops) {
            Dem crop = file.crop(cr[0], cr[1], cr[2], cr[3]);
            // a grid of its own: its edges are the outer edges (Dem.crop would keep the file around it)
            Dem dem = new Dem(crop.backingArray(), GridGeometry.metric(cr[2], cr[3], 30));
            int w = dem.width();
            int h = dem.height();
            for (double e : ELEVATIONS) {
                for (double a : AZIMUTHS) {
                    LightDirection light = new LightDirection(a, e);
                    float[] sweep = ShadowAlgorithm.SWEEP.compute(dem, light, ShadowOptions.DEFAULTS, POOL.get())
                            .backingArray();
                    float[] exact = ShadowAlgorithm.EXACT.compute(dem, light, ShadowOptions.DEFAULTS, POOL.get())
                            .backingArray();
                    float[] march = ShadowAlgorithm.MARCH.compute(dem, light, quarter, POOL.get()).backingArray();
                    for (int r = 0; r < h; r++) {
                        for (int c = 0; c < w; c++) {
                            int i = r * w + c;
                            int d = Math.min(Math.min(c, w - 1 - c), Math.min(r, h - 1 - r));
                            boolean falseShadow = sweep[i] > 0.5f && exact[i] < 0.5f && march[i] < 0.5f;
                            shaded += sweep[i] > 0.5f ? 1 : 0;
                            if (d < 2) {
                                edgeCells++;
                                edgeFalse += falseShadow ? 1 : 0;
                            } else if (d >= 3) {
                                innerCells++;
                                innerFalse += falseShadow ? 1 : 0;
                            }
                        }
                    }
                }
            }
        }
        double edgeRate = (double) edgeFalse / edgeCells;
        double innerRate = (double) innerFalse / innerCells;
        assertTrue(innerFalse > 20, "the interior must have some (grazing) disagreements to compare with, got "
                + innerFalse);
        assertTrue(edgeRate <= innerRate, String.format("false shadows within 2 cells of the edge: %d of %d (%.3f %%);"
                + " interior: %d of %d (%.3f %%)", edgeFalse, edgeCells, 100 * edgeRate, innerFalse, innerCells,
                100 * innerRate));
        assertTrue(shaded > 50_000, "got " + shaded);
    }
}
