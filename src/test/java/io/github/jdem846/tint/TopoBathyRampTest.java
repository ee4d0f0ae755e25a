package io.github.jdem846.tint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.testing.TestDems;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The default ramp, {@code hypsometric-bathymetric}: the article's table 2 on land-only DEMs, split at 0 m into
 * table 2 over [0, max] and the original's bathymetric ramp over [min, 0] when the DEM holds land and sea.
 */
class TopoBathyRampTest {

    private static final ColorRamp DEFAULT = ColorRamp.defaultRamp();
    private static final ColorRamp TABLE2 = ColorRamp.named("hypsometric");
    private static final ColorRamp BATHYMETRIC = ColorRamp.named("bathymetric");

    private static ElevationStatistics range(double min, double max) {
        return new ElevationStatistics(min, max, 1, 1);
    }

    private static int argb(int r, int g, int b) {
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    @Test
    void theDefaultIsTable2WithTheOriginalsBathymetricRamp() {
        assertEquals("hypsometric-bathymetric", ColorRamp.DEFAULT_NAME);
        TopoBathyRamp ramp = assertInstanceOf(DEFAULT);
        assertSame(TABLE2, ramp.land());
        assertSame(BATHYMETRIC, ramp.sea());
    }

    @Test
    void landAndSeaSplitExactlyAtZeroByHand() {
        TintFunction tint = DEFAULT.bind(range(-1437, 2205));
        // 0 m and −0 m are land: table 2's 0 % colour, 006246 (the land ramp spans [0, 2205]).
        assertEquals(0xFF006246, tint.argb(0));
        assertEquals(0xFF006246, tint.argb(-0f));
        // Just below 0 m is bathymetric's top: a = (−0.001 + 1437)/1437 ≈ 1 − 7e−7, so 100 % AFDAD1 after rounding.
        assertEquals(argb(175, 218, 209), tint.argb(-0.001f));
        // Land by hand: e = 1102.5 is a = 0.5 of [0, 2205], between 39 % 7C2123 and 52 % 797979, r = 0.11/0.13:
        // R = 124 − 3r = 121.46 → 121, G = 33 + 88r = 107.46 → 107, B = 35 + 86r = 107.77 → 108.
        assertEquals(argb(121, 107, 108), tint.argb(1102.5f));
        // e = 66.15 is a = 0.03 of [0, 2205]: table 2's 3 % stop 248234.
        assertEquals(0xFF248234, tint.argb(66.15f));
        assertEquals(0xFFE5E5E5, tint.argb(2205));
        // Sea by hand: −718.5 is a = 0.5 of [−1437, 0], bathymetric's 50 % stop 0BB0CB; −1437 is a = 0, below its
        // first stop (2.5 %), so its first colour 181736.
        assertEquals(argb(11, 176, 203), tint.argb(-718.5f));
        assertEquals(argb(24, 23, 54), tint.argb(-1437));
        // e = −359.25 is a = 0.75: the 75 % stop 5FC2D9.
        assertEquals(argb(95, 194, 217), tint.argb(-359.25f));
        assertEquals(0, tint.argb(Float.NaN));
    }

    @Test
    void eachSideIsItsOwnRampOverItsOwnPartOfTheRange() {
        Dem dem = TestDems.load(TestDems.VANCOUVER);
        ElevationStatistics all = dem.statistics();
        assertTrue(all.min() < 0 && all.max() > 0, "Vancouver holds land and sea");
        TintFunction split = DEFAULT.bind(dem);
        TintFunction land = TABLE2.bind(new ElevationStatistics(0, all.max(), 1, 1));
        TintFunction sea = BATHYMETRIC.bind(new ElevationStatistics(all.min(), 0, 1, 1));
        int landCells = 0;
        int seaCells = 0;
        for (float e : dem.backingArray()) {
            if (e < 0) {
                seaCells++;
                assertEquals(sea.argb(e), split.argb(e), "sea cell at " + e);
                int c = split.argb(e);
                assertTrue((c & 0xFF) > (c >> 16 & 0xFF), "blue above red at " + e);
            } else {
                landCells++;
                assertEquals(land.argb(e), split.argb(e), "land cell at " + e);
            }
        }
        assertEquals(4841, seaCells);
        assertEquals(10920 - 4841, landCells);
    }

    @Test
    void landOnlyDemsGetTable2Unchanged() {
        Random random = new Random(20);
        for (String name : List.of(TestDems.BIG_TUJUNGA, TestDems.LUXEMBOURG, TestDems.JACKSBORO,
                TestDems.VOLCANO)) {
            Dem dem = TestDems.load(name);
            assertTrue(dem.statistics().min() >= 0, name + " is land only");
            assertSameTint(TABLE2.bind(dem), DEFAULT.bind(dem), dem.backingArray(), name);
            float[] fractions = new float[2000];
            for (int i = 0; i < fractions.length; i++) {
                fractions[i] = (float) (dem.statistics().min() - 5
                        + random.nextDouble() * (dem.statistics().max() - dem.statistics().min() + 10));
            }
            assertSameTint(TABLE2.bind(dem), DEFAULT.bind(dem), fractions, name + " (fractions)");
        }
    }

    @Test
    void rangesThatDoNotStraddleSeaLevelAreNotSplit() {
        float[] probe = {-2000, -1000, -1, -0.5f, -0f, 0, 0.5f, 1, 100, 1000, Float.NaN};
        for (ElevationStatistics r : List.of(range(0, 2205), range(-1437, 0), range(-1437, -10), range(0, 0),
                range(-5, -5), range(7, 7), ElevationStatistics.ofRange(0, 0, 0, 4))) {
            assertFalse(TopoBathyRamp.holdsLandAndSea(r), r.toString());
            assertSameTint(TABLE2.bind(r), DEFAULT.bind(r), probe, r.toString());
        }
        // A land DEM starting at 0 m: 0 m is table 2's 0 % colour, as in the split.
        assertEquals(0xFF006246, DEFAULT.bind(range(0, 2205)).argb(0));
        assertTrue(TopoBathyRamp.holdsLandAndSea(range(-0.5, 0.5)));
    }

    @Test
    void anInfiniteRangeIsRejectedAsForTable2() {
        ElevationStatistics infinite = range(Double.NEGATIVE_INFINITY, 100);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DEFAULT.bind(infinite));
        assertTrue(e.getMessage().contains("not finite"), e.getMessage());
    }

    @Test
    void theLookupTableEqualsTheExactSplit() {
        TopoBathyRamp ramp = assertInstanceOf(DEFAULT);
        Random random = new Random(846);
        for (ElevationStatistics r : List.of(range(-1437, 2205), range(-0.5, 0.5), range(-3, 40000))) {
            TintFunction fast = ramp.bind(r);
            TintFunction exact = ramp.bindExact(r);
            for (int e = (int) r.min() - 3; e <= r.max() + 3; e++) {
                assertEquals(exact.argb(e), fast.argb(e), "at " + e);
            }
            for (int k = 0; k < 2000; k++) {
                float e = (float) (r.min() + random.nextDouble() * (r.max() - r.min()));
                assertEquals(exact.argb(e), fast.argb(e), "at " + e);
            }
            assertEquals(exact.argb(-0f), fast.argb(-0f));
        }
        assertTrue(ramp.bind(range(-1437, 2205)) instanceof IntegerLookupTint);
    }

    private static TopoBathyRamp assertInstanceOf(ColorRamp ramp) {
        assertTrue(ramp instanceof TopoBathyRamp, ramp.getClass().getName());
        return (TopoBathyRamp) ramp;
    }

    private static void assertSameTint(TintFunction expected, TintFunction actual, float[] values, String what) {
        for (float e : values) {
            assertEquals(expected.argb(e), actual.argb(e), what + " at " + e);
        }
    }
}
