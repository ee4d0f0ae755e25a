package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Extreme suns and degenerate DEMs: no NaN, no value outside [0, 1], no-data cells 0, no hang, and the answers the
 * physics demands where it demands one.
 */
class ShadowStabilityTest {

    static final double[] ELEVATIONS = {-5, 0, 1e-6, 0.01, 2, 45, 89.99, 90};
    static final double[] AZIMUTHS = {-720, -0.0, 0, 1e-12, 45, 90, 179.9, 180, 250, 270, 359.999, 360, 1e6};

    private static ForkJoinPool pool;

    @BeforeAll
    static void start() {
        pool = new ForkJoinPool(2);
    }

    @AfterAll
    static void stop() {
        pool.shutdownNow();
    }

    static Map<String, Dem> dems() {
        Map<String, Dem> m = new LinkedHashMap<>();
        m.put("flat", ShadowTestDems.flat(9, 7, 30, 100f));
        m.put("spike", ShadowTestDems.spike(15, 15, 30, 7, 7, 500f));
        float[] cliff = new float[12 * 12];
        for (int i = 0; i < cliff.length; i++) {
            cliff[i] = (i % 12) >= 6 ? 10_000f : 0f;
        }
        m.put("10 km cliff, 0.5 m cells", ShadowTestDems.metric(12, 12, 0.5, cliff));
        float[] nd = new float[6 * 5];
        java.util.Arrays.fill(nd, Float.NaN);
        m.put("all no-data", ShadowTestDems.metric(6, 5, 30, nd));
        m.put("1x1", ShadowTestDems.metric(1, 1, 30, new float[] {5f}));
        m.put("1xN", ShadowTestDems.rough(1, 17, 30, 1, 300));
        m.put("Nx1", ShadowTestDems.rough(17, 1, 30, 2, 300));
        Dem striped = ShadowTestDems.rough(16, 16, 30, 3, 400);
        float[] sv = striped.backingArray().clone();
        for (int r = 0; r < 16; r++) {
            for (int c = 0; c < 16; c++) {
                if (c % 5 == 2 || r % 6 == 3) {
                    sv[r * 16 + c] = Float.NaN;
                }
            }
        }
        m.put("no-data stripes", ShadowTestDems.metric(16, 16, 30, sv));
        m.put("rows at 89.9-90", ShadowTestDems.geographic(10, 8, 0, 90, 0.1 / 8,
                ShadowTestDems.rough(10, 8, 1, 4, 300).backingArray().clone()));
        m.put("1 degree cells", ShadowTestDems.geographic(10, 10, 5, 50, 1.0,
                ShadowTestDems.rough(10, 10, 1, 5, 3000).backingArray().clone()));
        m.put("0.5 m cells", ShadowTestDems.rough(12, 12, 0.5, 6, 5));
        return m;
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void everyExtremeCaseGivesAFiniteMaskWithoutHanging(ShadowAlgorithm algorithm) {
        Map<String, Dem> dems = dems();
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (boolean soft : new boolean[] {false, true}) {
                ShadowOptions opt = ShadowOptions.DEFAULTS.withSoftShadows(soft);
                for (var entry : dems.entrySet()) {
                    Dem dem = entry.getValue();
                    for (double e : ELEVATIONS) {
                        for (double az : AZIMUTHS) {
                            String what = algorithm + " " + entry.getKey() + " e=" + e + " az=" + az + " soft="
                                    + soft;
                            ShadowMask m = algorithm.compute(dem, new LightDirection(az, e), opt, pool);
                            check(dem, m, e, what);
                        }
                    }
                }
            }
        });
    }

    private static void check(Dem dem, ShadowMask m, double e, String what) {
        assertEquals(dem.width(), m.width(), what);
        assertEquals(dem.height(), m.height(), what);
        for (int r = 0; r < dem.height(); r++) {
            for (int c = 0; c < dem.width(); c++) {
                float s = m.get(c, r);
                if (!(s >= 0 && s <= 1)) {
                    fail(what + ": cell (" + c + ", " + r + ") = " + s);
                }
                if (!dem.isValid(c, r)) {
                    assertEquals(0f, s, what + ": no-data cell must be 0");
                } else if (e <= 0) {
                    assertEquals(1f, s, what + ": sun at or below the horizon shades every cell");
                } else if (e >= 90) {
                    assertEquals(0f, s, what + ": sun at the zenith casts no shadow");
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void flatGroundAndSingleCellsAreLitWheneverTheSunIsUp(ShadowAlgorithm algorithm) {
        for (double e : new double[] {1e-6, 0.01, 2, 45, 89.99}) {
            for (double az : AZIMUTHS) {
                LightDirection l = new LightDirection(az, e);
                assertEquals(0, algorithm.compute(ShadowTestDems.flat(9, 7, 30, 100f), l, ShadowOptions.DEFAULTS,
                        pool).shadowedCount(), algorithm + " flat e=" + e + " az=" + az);
                assertEquals(0, algorithm.compute(ShadowTestDems.metric(1, 1, 30, new float[] {5f}), l,
                        ShadowOptions.DEFAULTS, pool).shadowedCount(), algorithm + " 1x1");
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void aTenKilometreCliffShadesTheGroundBelowItOnItsShadySide(ShadowAlgorithm algorithm) {
        // west half at 0, east half at 10 000 m, 0.5 m cells; sun in the east at 45°: the whole low half is in
        // shadow (the cliff is 20 000 times higher than the 3 m of low ground); sun in the west: all lit
        Dem cliff = dems().get("10 km cliff, 0.5 m cells");
        ShadowMask east = algorithm.compute(cliff, new LightDirection(90, 45), ShadowOptions.DEFAULTS, pool);
        ShadowMask west = algorithm.compute(cliff, new LightDirection(270, 45), ShadowOptions.DEFAULTS, pool);
        for (int r = 0; r < 12; r++) {
            for (int c = 0; c < 12; c++) {
                assertEquals(c < 6 ? 1f : 0f, east.get(c, r), algorithm + " east sun (" + c + ", " + r + ")");
                assertEquals(0f, west.get(c, r), algorithm + " west sun (" + c + ", " + r + ")");
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void polarAndOneDegreeGridsGiveShadowsOfTheRightLength(ShadowAlgorithm algorithm) {
        // a north-south wall on a lat/lon grid at 78° N: one 0.01° column (≈ 232 m wide there) at 500 m; sun in
        // the west at 5°: the shadow reaches 500/tan 5° = 5715 m ≈ 24.6 cells east (the original, stepping in
        // flat degrees, would give about 5 cells)
        int w = 40;
        int h = 6;
        float[] v = new float[w * h];
        for (int r = 0; r < h; r++) {
            v[r * w + 5] = 500f;
        }
        Dem dem = ShadowTestDems.geographic(w, h, 10, 78.03, 0.01, v);
        double cellM = dem.geometry().cellWidthMeters(3);
        double expected = 500 / Math.tan(Math.toRadians(5)) / cellM;
        ShadowMask m = algorithm.compute(dem, new LightDirection(270, 5), ShadowOptions.DEFAULTS, pool);
        int last = 5;
        for (int c = 6; c < w; c++) {
            if (m.get(c, 3) >= 0.5f) {
                last = c;
            }
        }
        assertEquals(expected, last - 5, 1.5, algorithm + ": shadow length in cells at 78° N");
        assertTrue(expected > 20, "the case must be one where flat degrees would fail");
    }
}
