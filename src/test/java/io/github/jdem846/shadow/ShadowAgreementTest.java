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
import java.util.Locale;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The algorithms against each other on real DEMs: the sweep against the march it stands for, and the sweep and the
 * article's march against {@code exact}. Every assertion message carries the measured disagreement (fraction of
 * cells on which two hard masks differ).
 */
class ShadowAgreementTest {

    private static final double[] OFF_AXIS = {160, 250, 300};
    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(2);
    private static Dem bigTujunga;
    private static Dem jacksboro;

    @BeforeAll
    static void start() throws IOException {
        // 300×200 cells of the steepest part of Big Tujunga (UTM 11N, 30 m), 614–2095 m
        bigTujunga = standalone(DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"))
                .crop(420, 120, 300, 200));
        // 200×150 cells of Jacksboro (SRTM 3″, lat/lon: ≈ 74 × 93 m cells at 36.6° N)
        jacksboro = standalone(DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"))
                .crop(100, 100, 200, 150));
    }

    /**
     * The crop as a grid of its own (same cells, CRS and georeferencing): its sides are then the grid's outer edges
     * for every algorithm. {@code Dem.crop} keeps the file around it ({@code GridGeometry.placement()}), which the
     * sweep treats as terrain continuing beyond the sides while the marches stop there.
     */
    private static Dem standalone(Dem crop) {
        GridGeometry g = crop.geometry();
        return new Dem(crop.backingArray(), new GridGeometry(g.width(), g.height(), g.originX(), g.originY(),
                g.cellWidth(), g.cellHeight(), g.crs(), g.declaredAnchor()));
    }

    private static String pct(double fraction) {
        return String.format(Locale.ROOT, "%.3f %%", 100 * fraction);
    }

    @Test
    void nearestSweepIsTheOneCellNearestMarch() {
        // With nearest sampling and the first-cell test off, the sweep performs the march's test with one-cell
        // steps. Where the sun lies along a grid axis, or a diagonal of square cells, every cell sits on a
        // sun-parallel line and the two compute the same maximum: identical masks. (Jacksboro's cells are ≈ 74 ×
        // 93 m, so 45° is off-diagonal there: 0.93 % at 5°.) Off-axis a cell lies between two lines and the sweep
        // interpolates their shadow heights, so it is approximate (measured 0.30–1.51 % on Big Tujunga, 0.62–1.82 %
        // on Jacksboro at 160/250/300°).
        ShadowOptions sweep = ShadowOptions.DEFAULTS.withSampling(Sampling.NEAREST);   // first-cell test: bilinear only
        ShadowOptions march = ShadowOptions.DEFAULTS.withSampling(Sampling.NEAREST).withStep(StepSize.ONE_CELL);
        for (Dem dem : new Dem[] {bigTujunga, jacksboro}) {
            for (double e : new double[] {5, 20}) {
                double[] onLines = dem == bigTujunga ? new double[] {0, 45, 90, 135, 180, 225, 270, 315}
                        : new double[] {0, 90, 180, 270};
                for (double az : onLines) {
                    LightDirection l = new LightDirection(az, e);
                    double d = ShadowAlgorithm.SWEEP.compute(dem, l, sweep, POOL.get())
                            .disagreement(ShadowAlgorithm.MARCH.compute(dem, l, march, POOL.get()));
                    assertEquals(0, d, "az=" + az + " e=" + e + " on " + dem + ": " + pct(d));
                }
                for (double az : OFF_AXIS) {
                    LightDirection l = new LightDirection(az, e);
                    double d = ShadowAlgorithm.SWEEP.compute(dem, l, sweep, POOL.get())
                            .disagreement(ShadowAlgorithm.MARCH.compute(dem, l, march, POOL.get()));
                    assertTrue(d < 0.02, "az=" + az + " e=" + e + " on " + dem + ": " + pct(d));
                }
            }
        }
    }

    @Test
    void sweepAndArticleMarchAgainstExact() {
        // The aim for the sweep on a 20 m-class DEM: ≤ 0.5 % at 5°, ≤ 0.25 % at 20°. Measured on this
        // Big Tujunga crop (a grid of its own): 0.08–0.21 % at 5°, 0.10–0.24 % at 20°; on the Jacksboro crop
        // (≈ 74 × 93 m cells) 0.30–0.35 % and 0.09–0.26 %. The article's march (eq. 9 step, nearest cell) misses by
        // 1.6–5.5 % on Big Tujunga and 3.6–7.3 % on Jacksboro: always worse. Asserted: sweep < 1 %, article < 10 %,
        // sweep better.
        for (Dem dem : new Dem[] {bigTujunga, jacksboro}) {
            for (double e : new double[] {5, 20}) {
                for (double az : OFF_AXIS) {
                    LightDirection l = new LightDirection(az, e);
                    ShadowMask exact = ShadowAlgorithm.EXACT.compute(dem, l, ShadowOptions.DEFAULTS, POOL.get());
                    double sweep = ShadowAlgorithm.SWEEP.compute(dem, l, ShadowOptions.DEFAULTS, POOL.get())
                            .disagreement(exact);
                    double article = ShadowAlgorithm.MARCH.compute(dem, l, ShadowOptions.DEFAULTS, POOL.get())
                            .disagreement(exact);
                    String what = (dem == bigTujunga ? "Big Tujunga" : "Jacksboro") + " az=" + az + " e=" + e
                            + ": sweep " + pct(sweep) + ", article march " + pct(article) + ", shadowed "
                            + pct((double) exact.shadowedCount() / (dem.width() * dem.height()));
                    assertTrue(sweep < 0.01, what);
                    assertTrue(article < 0.10, what);
                    assertTrue(sweep < article, what);
                    assertTrue(exact.shadowedCount() > 0.05 * dem.width() * dem.height(),
                            what + ": a case with shadows to disagree about");
                }
            }
        }
    }

    @Test
    void marchAndExactAgreeWithAHandWorkedWallShadow() {
        // A 615 m north–south wall one cell wide on flat ground (30 m cells), sun in the east at 45°: cell c west
        // of the wall is shaded exactly when 615 > (30 − c)·30, i.e. for 10 ≤ c < 30 (no ties: 600 and 630 are the
        // nearest distances). Holds for nearest sampling (the wall is a block) and for the bilinear surface (its
        // ramp from the neighbouring cell rises at 615 m per cell, far steeper than the 45° ray).
        int w = 40;
        int h = 5;
        float[] v = new float[w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                v[r * w + c] = c == 30 ? 615f : 0f;
            }
        }
        Dem wall = SyntheticDems.metric(w, h, 30, v);
        LightDirection east45 = new LightDirection(90, 45);
        for (ShadowAlgorithm a : new ShadowAlgorithm[] {ShadowAlgorithm.MARCH, ShadowAlgorithm.SWEEP,
            ShadowAlgorithm.EXACT}) {
            ShadowMask m = a.compute(wall, east45, ShadowOptions.DEFAULTS, POOL.get());
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    boolean expected = c < 30 && 615 > (30 - c) * 30;
                    assertEquals(expected ? 1f : 0f, m.get(c, r), a + " cell (" + c + ", " + r + ")");
                }
            }
        }
    }
}
