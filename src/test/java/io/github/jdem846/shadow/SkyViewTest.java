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
        assertThrows(IllegalArgumentException.class, () -> SkyViewOptions.DEFAULTS.withRadius(0));
        assertThrows(IllegalArgumentException.class, () -> SkyViewOptions.DEFAULTS.withRadius(Double.NaN));
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
    void theBruteForceStopsEarlyWithoutChangingAHorizon() throws IOException {
        // the reference stops a ray once even the highest terrain could not be steeper than its horizon so far
        Dem volcano = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"));
        Dem luxembourg = DemReader.read(Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif")); // no-data around
        for (Dem dem : new Dem[] {volcano, luxembourg}) {
            for (double scale : new double[] {1, 3}) {
                HorizonReference early = new HorizonReference(dem, 0.25, scale);
                HorizonReference full = HorizonReference.exhaustive(dem, 0.25, scale);
                int compared = 0;
                for (int r = 0; r < dem.height(); r += 3) {
                    for (int c = 0; c < dem.width(); c += 3) {
                        for (double az = 0; az < 360; az += 22.5) {
                            double a = early.horizonTangent(c, r, az);
                            assertEquals(full.horizonTangent(c, r, az), a, 0.0,
                                    "cell " + c + ", " + r + " azimuth " + az + " scale " + scale);
                            compared += Double.isNaN(a) ? 0 : 1;
                        }
                    }
                }
                assertTrue(compared > 1000, "valid cells compared: " + compared);
            }
        }
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

    /** {mean |error|, max |error|} of the sweep with a search radius against the brute force with the same one. */
    private static double[] errors(Dem dem, int directions, double radius) {
        float[] s = SkyView.compute(dem, SkyViewOptions.DEFAULTS.withDirections(directions).withRadius(radius),
                POOL.get(2));
        HorizonReference ref = new HorizonReference(dem, 0.125, 1, radius);
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
    void aSearchRadiusAgreesWithTheBruteForceSearchWithinTheSameRadius() throws IOException {
        Dem volcano = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"));
        Dem tujunga = standalone(DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"))
                .crop(500, 150, 90, 70));
        Dem jacksboro = standalone(DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"))
                .crop(150, 120, 80, 60));
        // radii of a few cells to half the grid: the radius cuts most horizons short
        double[][] radii = {{45, 150}, {100, 600}, {250, 900}};
        Dem[] dems = {volcano, tujunga, jacksboro};
        for (int k = 0; k < dems.length; k++) {
            for (double radius : radii[k]) {
                for (int d : new int[] {8, 16}) {
                    double[] e = errors(dems[k], d, radius);
                    String what = String.format(Locale.ROOT, "%s R=%.0f D=%d: mean %.5f max %.4f",
                            dems[k].geometry().crs(), radius, d, e[0], e[1]);
                    assertTrue(e[0] < 0.003, what);
                    assertTrue(e[1] < 0.04, what);
                }
            }
        }
    }

    @Test
    void aLargerRadiusNeverSeesMoreSkyAndOneBeyondTheGridIsTheUnboundedFactor() {
        Dem dem = SyntheticDems.rough(90, 70, 30, 5, 700);
        SkyViewOptions o = SkyViewOptions.DEFAULTS.withDirections(16);
        float[] previous = null;
        for (double radius : new double[] {30, 95, 200, 600, 1500}) {
            float[] s = SkyView.compute(dem, o.withRadius(radius), POOL.get(2));
            if (previous != null) {
                for (int i = 0; i < s.length; i++) {
                    assertTrue(s[i] <= previous[i] + 1e-6f, "R = " + radius + ", cell " + i);
                }
            }
            previous = s;
        }
        // the grid's diagonal is 3400 m: a radius beyond it sees every sample the unbounded sweep sees
        assertArrayEquals(SkyView.compute(dem, o, POOL.get(2)), SkyView.compute(dem, o.withRadius(3500),
                POOL.get(2)), 1e-6f);
    }

    @Test
    void aPieceReadWithTheHaloOfTheRadiusEqualsTheWholeGrid() throws IOException {
        Dem tujunga = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif")).crop(300, 100, 400, 300);
        Dem jacksboro = DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
        // 1200 m: 40 cells of 30 m, and 16.1 of Jacksboro's 3" (74.4 m east-west at its northern edge, 36.7° N)
        int[] halos = {42, 18};
        Dem[] dems = {tujunga, jacksboro};
        for (int k = 0; k < dems.length; k++) {
            Dem dem = dems[k];
            SkyViewOptions o = SkyViewOptions.DEFAULTS.withDirections(24).withRadius(1200);
            int halo = SkyView.haloCells(dem.geometry(), o);
            assertEquals(halos[k], halo, "halo");
            float[] whole = SkyView.compute(dem, o, POOL.get(2));
            // pieces inside the grid and at its corners, cut with the halo (clipped by the grid)
            for (CellWindow area : new CellWindow[] {new CellWindow(150, 120, 60, 50), new CellWindow(0, 0, 70, 40),
                new CellWindow(dem.width() - 50, dem.height() - 45, 50, 45)}) {
                int c0 = Math.max(0, area.col() - halo);
                int r0 = Math.max(0, area.row() - halo);
                int c1 = Math.min(dem.width(), area.colEnd() + halo);
                int r1 = Math.min(dem.height(), area.rowEnd() + halo);
                Dem piece = dem.crop(c0, r0, c1 - c0, r1 - r0);
                CellWindow inside = new CellWindow(area.col() - c0, area.row() - r0, area.width(), area.height());
                float[] part = SkyView.compute(piece, o, POOL.get(1), inside);
                for (int r = 0; r < area.height(); r++) {
                    for (int c = 0; c < area.width(); c++) {
                        assertEquals(whole[(area.row() + r) * dem.width() + area.col() + c],
                                part[r * area.width() + c], 0f, dem.geometry().crs() + " " + area + " " + c + "," + r);
                    }
                }
            }
        }
    }
}
