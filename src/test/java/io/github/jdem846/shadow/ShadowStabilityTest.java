package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.PoolExtension;
import io.github.jdem846.testing.SyntheticDems;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Extreme suns and degenerate DEMs: no NaN, no value outside [0, 1], no-data cells 0, no hang, and the answers the
 * physics demands where it demands one.
 */
class ShadowStabilityTest {

    static final double[] ELEVATIONS = {-5, 0, 1e-6, 0.01, 2, 45, 89.99, 90};
    static final double[] AZIMUTHS = {-720, -0.0, 0, 1e-12, 45, 90, 179.9, 180, 250, 270, 359.999, 360, 1e6};

    @RegisterExtension
    static final PoolExtension POOL = new PoolExtension(2);

    static Map<String, Dem> dems() {
        Map<String, Dem> m = new LinkedHashMap<>();
        m.put("flat", SyntheticDems.flat(9, 7, 30, 100f));
        m.put("spike", SyntheticDems.spike(15, 15, 30, 7, 7, 500f));
        float[] cliff = new float[12 * 12];
        for (int i = 0; i < cliff.length; i++) {
            cliff[i] = (i % 12) >= 6 ? 10_000f : 0f;
        }
        m.put("10 km cliff, 0.5 m cells", SyntheticDems.metric(12, 12, 0.5, cliff));
        float[] nd = new float[6 * 5];
        java.util.Arrays.fill(nd, Float.NaN);
        m.put("all no-data", SyntheticDems.metric(6, 5, 30, nd));
        m.put("1x1", SyntheticDems.metric(1, 1, 30, new float[] {5f}));
        m.put("1xN", SyntheticDems.rough(1, 17, 30, 1, 300));
        m.put("Nx1", SyntheticDems.rough(17, 1, 30, 2, 300));
        Dem striped = SyntheticDems.rough(16, 16, 30, 3, 400);
        float[] sv = striped.backingArray().clone();
        for (int r = 0; r < 16; r++) {
            for (int c = 0; c < 16; c++) {
                if (c % 5 == 2 || r % 6 == 3) {
                    sv[r * 16 + c] = Float.NaN;
                }
            }
        }
        m.put("no-data stripes", SyntheticDems.metric(16, 16, 30, sv));
        m.put("rows at 89.9-90", SyntheticDems.geographic(10, 8, 0, 90, 0.1 / 8,
                SyntheticDems.rough(10, 8, 1, 4, 300).backingArray().clone()));
        m.put("1 degree cells", SyntheticDems.geographic(10, 10, 5, 50, 1.0,
                SyntheticDems.rough(10, 10, 1, 5, 3000).backingArray().clone()));
        m.put("0.5 m cells", SyntheticDems.rough(12, 12, 0.5, 6, 5));
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
                            ShadowMask m = algorithm.compute(dem, new LightDirection(az, e), opt, POOL.get());
                            check(dem, m, e, what);
                        }
                    }
                }
            }
        });
    }

    @org.junit.jupiter.api.Test
    void theSweepsThinFeatureOptionSurvivesEveryExtremeCase() {
        // the option's own-ray samples and hulls on the same extreme DEMs and suns: finite, bounded, no hang, the
        // short cuts kept; and never less shadow than the plain sweep (it only adds own-ray samples)
        Map<String, Dem> dems = dems();
        ShadowOptions thin = ShadowOptions.DEFAULTS.withThinFeatures(true);
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (boolean soft : new boolean[] {false, true}) {
                for (var entry : dems.entrySet()) {
                    Dem dem = entry.getValue();
                    for (double e : ELEVATIONS) {
                        for (double az : AZIMUTHS) {
                            String what = "thin features " + entry.getKey() + " e=" + e + " az=" + az + " soft="
                                    + soft;
                            LightDirection l = new LightDirection(az, e);
                            ShadowMask m = ShadowAlgorithm.SWEEP.compute(dem, l, thin.withSoftShadows(soft),
                                    POOL.get());
                            check(dem, m, e, what);
                            ShadowMask plain = ShadowAlgorithm.SWEEP.compute(dem, l,
                                    ShadowOptions.DEFAULTS.withSoftShadows(soft), POOL.get());
                            for (int i = 0; i < m.backingArray().length; i++) {
                                if (m.backingArray()[i] < plain.backingArray()[i]) {
                                    fail(what + ": cell " + i + " has less shadow than the plain sweep");
                                }
                            }
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
                assertEquals(0, algorithm.compute(SyntheticDems.flat(9, 7, 30, 100f), l, ShadowOptions.DEFAULTS,
                        POOL.get()).shadowedCount(), algorithm + " flat e=" + e + " az=" + az);
                assertEquals(0, algorithm.compute(SyntheticDems.metric(1, 1, 30, new float[] {5f}), l,
                        ShadowOptions.DEFAULTS, POOL.get()).shadowedCount(), algorithm + " 1x1");
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void aTenKilometreCliffShadesTheGroundBelowItOnItsShadySide(ShadowAlgorithm algorithm) {
        // west half at 0, east half at 10 000 m, 0.5 m cells; sun in the east at 45°: the whole low half is in
        // shadow (the cliff is 20 000 times higher than the 3 m of low ground); sun in the west: all lit
        Dem cliff = dems().get("10 km cliff, 0.5 m cells");
        ShadowMask east = algorithm.compute(cliff, new LightDirection(90, 45), ShadowOptions.DEFAULTS, POOL.get());
        ShadowMask west = algorithm.compute(cliff, new LightDirection(270, 45), ShadowOptions.DEFAULTS, POOL.get());
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
        Dem dem = SyntheticDems.geographic(w, h, 10, 78.03, 0.01, v);
        double cellM = dem.geometry().cellWidthMeters(3);
        double expected = 500 / Math.tan(Math.toRadians(5)) / cellM;
        ShadowMask m = algorithm.compute(dem, new LightDirection(270, 5), ShadowOptions.DEFAULTS, POOL.get());
        int last = 5;
        for (int c = 6; c < w; c++) {
            if (m.get(c, 3) >= 0.5f) {
                last = c;
            }
        }
        assertEquals(expected, last - 5, 1.5, algorithm + ": shadow length in cells at 78° N");
        assertTrue(expected > 20, "the case must be one where flat degrees would fail");
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void aSpikeShadesOnlyItsLeeAtEveryExtremeSun(ShadowAlgorithm algorithm) {
        // 500 m spike on flat ground, 30 m cells. At every azimuth of the list and every sun above the horizon, a
        // shadowed cell lies away from the sun, within two cells sideways of the spike's axis (block or bilinear
        // skirt, plus the sweep's line spacing) and no farther than h/tan e + 2 cells; at 89.99° nothing is shaded
        // (the shadow would be 0.09 m long), at 45° something is. With soft shadows flat ground ahead already hides
        // the part of the sun's disk below 0° (half of it as e → 0): only more than that counts as the spike's.
        Dem spike = SyntheticDems.spike(15, 15, 30, 7, 7, 500f);
        for (boolean soft : new boolean[] {false, true}) {
            ShadowOptions opt = ShadowOptions.DEFAULTS.withSoftShadows(soft);
            for (double e : new double[] {1e-6, 0.01, 2, 45, 89.99}) {
                for (double az : AZIMUTHS) {
                    ShadowMask m = algorithm.compute(spike, new LightDirection(az, e), opt, POOL.get());
                    double a = Math.toRadians(LightDirection.normalizeAzimuth(az));
                    double lowerLimb = e - (soft ? 0.265 : 0);
                    double reach = lowerLimb > 0 ? 500 / Math.tan(Math.toRadians(lowerLimb)) + 60
                            : Double.POSITIVE_INFINITY;
                    double ground = soft ? SunDisk.hiddenFraction(e, 0, 0.265) + 1e-6 : 0;
                    String what = algorithm + " soft=" + soft + " e=" + e + " az=" + az;
                    for (int r = 0; r < 15; r++) {
                        for (int c = 0; c < 15; c++) {
                            if (m.get(c, r) <= ground || (c == 7 && r == 7)) {
                                continue;
                            }
                            double east = (c - 7) * 30.0;
                            double north = (7 - r) * 30.0;
                            double along = -(east * Math.sin(a) + north * Math.cos(a));
                            double across = Math.abs(east * Math.cos(a) - north * Math.sin(a));
                            String at = what + " cell (" + c + ", " + r + ") = " + m.get(c, r);
                            assertTrue(along > -30 && along <= reach && across <= 60 + 1e-9, at);
                        }
                    }
                    if (e == 89.99) {
                        assertEquals(0, m.shadowedCount(), what);
                    } else if (e == 45) {
                        assertTrue(m.shadowedCount() > 0, what + ": a 500 m spike casts a 500 m shadow");
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void aNoDataStripeAcrossTheRaysDoesNotStopTheShadow(ShadowAlgorithm algorithm) {
        // a 615 m wall one cell wide at column 30, no-data in columns 20–22, flat ground at 0, 30 m cells; sun in
        // the east (and, mirrored, in the west) at 45°: the article's test 3 keeps marching through no-data, so
        // the ground beyond the stripe is still shaded where 615 > distance·tan 45° (columns 10–19 and 23–29)
        int w = 41;
        int h = 5;
        for (boolean mirrored : new boolean[] {false, true}) {
            float[] v = new float[w * h];
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    int x = mirrored ? w - 1 - c : c;
                    v[r * w + c] = x == 30 ? 615f : (x >= 20 && x <= 22 ? Float.NaN : 0f);
                }
            }
            Dem dem = SyntheticDems.metric(w, h, 30, v);
            ShadowMask m = algorithm.compute(dem, new LightDirection(mirrored ? 270 : 90, 45),
                    ShadowOptions.DEFAULTS, POOL.get());
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    int x = mirrored ? w - 1 - c : c;
                    boolean shaded = x >= 10 && x < 30 && !(x >= 20 && x <= 22);
                    assertEquals(shaded ? 1f : 0f, m.get(c, r), algorithm + " mirrored=" + mirrored + " cell (" + c
                            + ", " + r + ")");
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = ShadowAlgorithm.class, names = {"MARCH", "SWEEP", "EXACT"})
    void flatGroundAtThePoleAndOnOneDegreeCellsIsLit(ShadowAlgorithm algorithm) {
        Dem pole = SyntheticDems.geographic(10, 8, 0, 90, 0.1 / 8, new float[80]);
        Dem degrees = SyntheticDems.geographic(10, 10, 5, 50, 1.0, new float[100]);
        for (Dem dem : new Dem[] {pole, degrees}) {
            for (double e : new double[] {1e-6, 0.01, 2, 45, 89.99}) {
                for (double az : AZIMUTHS) {
                    for (boolean soft : new boolean[] {false, true}) {
                        ShadowMask m = algorithm.compute(dem, new LightDirection(az, e),
                                ShadowOptions.DEFAULTS.withSoftShadows(soft), POOL.get());
                        float max = 0;
                        for (float x : m.backingArray()) {
                            max = Math.max(max, x);
                        }
                        // soft: with the sun's centre at e the flat horizon (0°) hides the part of the disk below
                        // it, at most half of it when e → 0. The article's step (eq. 9, march) is the hypotenuse
                        // of the two cell sizes: on the polar rows (≈ 1390 m × 0–3 m cells) it leaves the grid in
                        // one step and sees no ground ahead, so it may hide less, never more.
                        double expected = soft ? SunDisk.hiddenFraction(e, 0, 0.265) : 0;
                        String what = algorithm + " soft=" + soft + " e=" + e + " az=" + az + " on "
                                + dem.geometry();
                        if (algorithm == ShadowAlgorithm.MARCH && dem == pole) {
                            assertTrue(max <= expected + 1e-6, what + ": " + max);
                        } else {
                            assertEquals(expected, max, 1e-6, what);
                        }
                    }
                }
            }
        }
    }
}
