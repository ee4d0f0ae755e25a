package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.HorizonReference;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The sky-view factor: analytic cases (plane, V-shaped valley, conical pit), the properties that must hold (quarter
 * turns, a constant added, no-data, windows, thread counts) and the sweep against the brute-force horizon search
 * ({@link HorizonReference}) on real DEMs.
 */
class SkyViewTest {

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(1, 2);

    private static float[] svf(Dem dem, int directions) {
        return SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(directions), POOL.get(2));
    }

    @Test
    void aFlatPlaneSeesTheWholeSky() {
        for (int d : new int[] {4, 8, 16, 32, 64, 36}) {
            float[] s = svf(SyntheticDems.flat(40, 30, 10, 123.5f), d);
            for (float f : s) {
                assertEquals(1f, f, 0f, "D = " + d);
            }
        }
    }

    /** A valley along the north-south axis, walls rising at {@code beta} degrees from column {@code bottom}. */
    private static Dem valley(int width, int height, int bottom, double beta, double cell) {
        double t = Math.tan(Math.toRadians(beta));
        float[] v = new float[width * height];
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                v[r * width + c] = (float) (500 + t * Math.abs(c - bottom) * cell);
            }
        }
        return SyntheticDems.metric(width, height, cell, v);
    }

    /** 1 − mean over the D azimuths of sin(atan(|sin a|·tan β)): the floor of a V-shaped valley along north. */
    private static double valleyFloor(double beta, int directions) {
        double t = Math.tan(Math.toRadians(beta));
        double sum = 0;
        for (int d = 0; d < directions; d++) {
            double h = Math.abs(Math.sin(Math.toRadians(360.0 * d / directions))) * t;
            sum += h / Math.sqrt(1 + h * h);
        }
        return 1 - sum / directions;
    }

    @Test
    void theFloorOfAVShapedValleyHasTheAnalyticFactor() {
        for (double beta : new double[] {10, 30, 60}) {
            Dem dem = valley(81, 61, 40, beta, 30);
            // on the axes and diagonals the lines run through cell centres: the sweep is exact
            for (int d : new int[] {4, 8}) {
                float[] s = svf(dem, d);
                assertEquals(valleyFloor(beta, d), s[30 * 81 + 40], 1e-6, "β = " + beta + ", D = " + d);
            }
            // off the axes the horizon is interpolated between two lines, which here lie on opposite walls: the kink
            // right at the cell is the sweep's worst case (the brute-force search, on this surface, is exact)
            float[] s = svf(dem, 32);
            double ref = new HorizonReference(dem, 0.125, 1).skyView(40, 30, 32);
            assertEquals(valleyFloor(beta, 32), ref, 1e-6, "β = " + beta + ", reference");
            assertEquals(valleyFloor(beta, 32), s[30 * 81 + 40], 0.04, "β = " + beta + ", D = 32");
        }
    }

    @Test
    void theBottomOfAConicalPitSeesOneMinusSinBeta() {
        int n = 81;
        double cell = 10;
        for (double beta : new double[] {15, 45}) {
            double t = Math.tan(Math.toRadians(beta));
            Dem pit = SyntheticDems.surface(n, n, cell, (x, y) -> t * Math.hypot(x - 405, y - 405));
            // along the axes the bilinear surface is the cone; along other azimuths it is not, at the apex (the
            // patches around it are saddles, steeper than the cone on the diagonals): there the reference is the
            // brute-force search on the same surface
            assertEquals(1 - Math.sin(Math.toRadians(beta)), svf(pit, 4)[40 * n + 40], 1e-6, "β = " + beta);
            HorizonReference ref = new HorizonReference(pit, 0.125, 1);
            for (int d : new int[] {8, 32}) {
                double e = svf(pit, d)[40 * n + 40] - ref.skyView(40, 40, d);
                assertEquals(0, e, 0.01, "β = " + beta + ", D = " + d);
            }
        }
    }

    @Test
    void aQuarterTurnOfTheGridTurnsTheFactor() {
        Dem dem = SyntheticDems.rough(70, 50, 20, 846, 400);
        Dem turned = SyntheticDems.rotateClockwise(dem);
        for (int d : new int[] {8, 16, 32}) {
            float[] expected = SyntheticDems.rotateClockwise(svf(dem, d), 70, 50);
            assertArrayEquals(expected, svf(turned, d), 2e-6f, "D = " + d);
        }
    }

    @Test
    void addingAConstantHeightChangesNothing() {
        Dem dem = SyntheticDems.rough(60, 45, 25, 7, 300);
        Dem raised = SyntheticDems.map(dem, z -> z + 1024);
        assertArrayEquals(svf(dem, 32), svf(raised, 32), 2e-6f);
    }

    @Test
    void doublingTheHeightScaleIsDoublingTheHeights() {
        Dem dem = SyntheticDems.rough(60, 45, 25, 7, 300);
        Dem doubled = SyntheticDems.map(dem, z -> 2 * z);
        float[] a = SkyView.compute(dem, SkyViewOptions.DEFAULTS.withHeightScale(2), POOL.get(2));
        assertArrayEquals(svf(doubled, 16 * 2), a, 2e-6f);
    }

    @Test
    void noDataCellsAreNaNAndTheTerrainBeyondThemStillCounts() {
        // a hole in a plane: every valid cell still sees the whole sky
        Dem flat = SyntheticDems.flat(30, 30, 10, 50f);
        float[] v = flat.backingArray().clone();
        for (int r = 10; r < 15; r++) {
            for (int c = 12; c < 20; c++) {
                v[r * 30 + c] = Float.NaN;
            }
        }
        float[] s = svf(SyntheticDems.metric(30, 30, 10, v), 32);
        for (int i = 0; i < v.length; i++) {
            if (Float.isNaN(v[i])) {
                assertTrue(Float.isNaN(s[i]), "no-data cell " + i);
            } else {
                assertEquals(1f, s[i], 0f, "cell " + i);
            }
        }
        // a strip of no-data across both walls of a valley, away from the floor: the walls beyond it still count
        Dem dem = valley(81, 61, 40, 30, 30);
        float[] w = dem.backingArray().clone();
        for (int r = 0; r < 61; r++) {
            for (int c = 50; c < 53; c++) {
                w[r * 81 + c] = Float.NaN;
                w[r * 81 + 80 - c] = Float.NaN;
            }
        }
        float[] sv = svf(SyntheticDems.metric(81, 61, 30, w), 8);
        assertEquals(valleyFloor(30, 8), sv[30 * 81 + 40], 1e-6);
        // an all-no-data grid
        float[] none = new float[12];
        java.util.Arrays.fill(none, Float.NaN);
        for (float f : svf(SyntheticDems.metric(4, 3, 10, none), 16)) {
            assertTrue(Float.isNaN(f));
        }
    }

    @Test
    void aWindowEqualsTheSameCellsOfTheWholeGridOnAnyThreadCount() {
        Dem dem = SyntheticDems.rough(90, 70, 30, 11, 600);
        SkyViewOptions o = SkyViewOptions.DEFAULTS.withDirections(24);
        float[] whole = SkyView.compute(dem, o, POOL.get(1));
        assertArrayEquals(whole, SkyView.compute(dem, o, POOL.get(2)));
        CellWindow win = new CellWindow(17, 9, 40, 33);
        float[] part = SkyView.compute(dem, o, POOL.get(2), win);
        for (int r = 0; r < win.height(); r++) {
            for (int c = 0; c < win.width(); c++) {
                assertEquals(whole[(win.row() + r) * 90 + win.col() + c], part[r * win.width() + c], 0f);
            }
        }
    }

    @Test
    void anInterruptStopsTheSweeps() throws InterruptedException {
        // 64 sweeps of 800 × 600 cells take seconds; the interrupt comes after 100 ms
        Dem dem = SyntheticDems.rough(800, 600, 30, 3, 900);
        io.github.jdem846.testing.InterruptedRun run = io.github.jdem846.testing.InterruptedRun.of(
                () -> SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(64), POOL.get(2)), 100);
        assertTrue(run.thrown() instanceof java.util.concurrent.CancellationException, "ended by " + run.thrown());
        assertTrue(run.interruptStatusAtEnd(), "the interrupt status stays set");
    }

    @Test
    void optionsOutsideTheirRangeAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> SkyViewOptions.DEFAULTS.withDirections(3));
        assertThrows(IllegalArgumentException.class, () -> SkyViewOptions.DEFAULTS.withDirections(361));
        assertThrows(IllegalArgumentException.class, () -> SkyViewOptions.DEFAULTS.withHeightScale(0));
    }

    private static Dem standalone(Dem crop) {
        GridGeometry g = crop.geometry();
        return new Dem(crop.backingArray(), new GridGeometry(g.width(), g.height(), g.originX(), g.originY(),
                g.cellWidth(), g.cellHeight(), g.crs(), g.declaredAnchor()));
    }

    /** {mean |error|, max |error|} of the sweep against the brute force over every valid cell. */
    private static double[] errors(Dem dem, int directions) {
        float[] s = svf(dem, directions);
        HorizonReference ref = new HorizonReference(dem, 0.125, 1);
        double sum = 0;
        double max = 0;
        int n = 0;
        for (int r = 0; r < dem.height(); r++) {
            for (int c = 0; c < dem.width(); c++) {
                double e = ref.skyView(c, r, directions);
                if (Double.isNaN(e)) {
                    continue;
                }
                double err = Math.abs(s[r * dem.width() + c] - e);
                sum += err;
                max = Math.max(max, err);
                n++;
            }
        }
        return new double[] {sum / n, max};
    }

    @Test
    void theSweepAgreesWithTheBruteForceSearchOnRealDems() throws IOException {
        Dem volcano = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"));
        Dem tujunga = standalone(DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"))
                .crop(500, 150, 90, 70));
        Dem jacksboro = standalone(DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"))
                .crop(150, 120, 80, 60));
        for (Dem dem : new Dem[] {volcano, tujunga, jacksboro}) {
            for (int d : new int[] {8, 16}) {
                double[] e = errors(dem, d);
                String what = String.format(Locale.ROOT, "%s D=%d: mean %.5f max %.4f", dem.geometry().crs(), d,
                        e[0], e[1]);
                assertTrue(e[0] < 0.003, what);
                assertTrue(e[1] < 0.04, what);
            }
        }
    }
}
