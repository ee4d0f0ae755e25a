package io.github.jdem846.tint;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class ColorRampTest {

    private static final int DEEP_GREEN = 0xFF006246;    // table 2, 0 %
    private static final int LIGHT_GREY = 0xFFE5E5E5;    // table 2, 100 %

    private static ElevationStatistics range(double min, double max) {
        return new ElevationStatistics(min, max, 1, 1);
    }

    private static int argb(int r, int g, int b) {
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    // --- eq. 1–3 by hand, table 2 ----------------------------------------------------------------------

    @Test
    void table2WorkedByHand() {
        TintFunction tint = ColorRamp.named("hypsometric").bind(range(200, 1200));
        // e = 300: eq. 1 a = (300 − 200)/(1200 − 200) = 0.10, between 5 % E4CF7E (228,207,126) and 18 % 9A4600
        // (154,70,0). eq. 2 r = (0.10 − 0.05)/(0.18 − 0.05) = 0.384615. eq. 3: R = 228·(1−r) + 154·r = 199.54 → 200,
        // G = 207·(1−r) + 70·r = 154.31 → 154, B = 126·(1−r) + 0·r = 77.54 → 78.
        assertEquals(argb(200, 154, 78), tint.argb(300));
        // e = 650: a = 0.45, between 39 % 7C2123 (124,33,35) and 52 % 797979 (121,121,121); r = 0.06/0.13 = 0.461538:
        // R = 124 − 3r = 122.62 → 123, G = 33 + 88r = 73.62 → 74, B = 35 + 86r = 74.69 → 75.
        assertEquals(argb(123, 74, 75), tint.argb(650));
        // e = 1050: a = 0.85, between 68 % B2B2B2 (178) and 100 % E5E5E5 (229); r = 0.17/0.32 = 0.53125:
        // 178 + 51r = 205.09 → 205.
        assertEquals(argb(205, 205, 205), tint.argb(1050));
        // e = 230: a = 0.03, exactly on the 3 % stop 248234.
        assertEquals(0xFF248234, tint.argb(230));
        // The ends of the range are the end stops.
        assertEquals(DEEP_GREEN, tint.argb(200));
        assertEquals(LIGHT_GREY, tint.argb(1200));
    }

    @Test
    void table2LevelsAreTheOriginalGlobalGradientRounded() {
        List<ColorStop> table2 = ((StopRamp) ColorRamp.named("hypsometric")).stops();
        List<ColorStop> global = ((StopRamp) ColorRamp.named("hypsometric-global")).stops();
        assertEquals(global.size(), table2.size());
        for (int i = 0; i < table2.size(); i++) {
            assertEquals(Math.round(global.get(i).level()), table2.get(i).level(), "level of stop " + i);
            assertEquals(global.get(i).red(), table2.get(i).red(), 1, "red of stop " + i);
            assertEquals(global.get(i).green(), table2.get(i).green(), 1, "green of stop " + i);
            assertEquals(global.get(i).blue(), table2.get(i).blue(), 1, "blue of stop " + i);
        }
    }

    // --- ends, flat, NaN, extremes -----------------------------------------------------------------------

    @Test
    void valuesBeyondTheEndStopsTakeTheEndColoursNeverBlack() {
        for (String name : ColorRamp.names()) {
            ColorRamp ramp = ColorRamp.named(name);
            TintFunction tint = ramp.bind(range(-100, 900));
            // Percent ramps end at the DEM's min and max, absolute ones (etopo1) at their own end stops.
            boolean absolute = ramp instanceof StopRamp s && s.isAbsolute();
            float lowEnd = absolute ? -11000 : -100;
            float highEnd = absolute ? 8500 : 900;
            int low = tint.argb(lowEnd);
            int high = tint.argb(highEnd);
            for (float beyond : new float[] {lowEnd - 1, -1e7f, -Float.MAX_VALUE, Float.NEGATIVE_INFINITY}) {
                assertEquals(low, tint.argb(beyond), name + " at " + beyond);
            }
            for (float beyond : new float[] {highEnd + 1, 1e7f, Float.MAX_VALUE, Float.POSITIVE_INFINITY}) {
                assertEquals(high, tint.argb(beyond), name + " at " + beyond);
            }
            for (int c : new int[] {low, high}) {
                assertEquals(name.equals("transparent") ? 0 : 0xFF, c >>> 24, name + " end colours are opaque");
                assertTrue(name.equals("bumpmap") || name.equals("black") || name.equals("transparent")
                        || c != 0xFF000000, name + " end colours are not black");
            }
        }
    }

    @Test
    void bathymetricBelowItsFirstStopTakesTheFirstColour() {
        TintFunction tint = ColorRamp.named("bathymetric").bind(range(-1000, 0));
        assertEquals(argb(24, 23, 54), tint.argb(-1000));   // a = 0 < 2.5 %
        assertEquals(argb(24, 23, 54), tint.argb(-975));    // a = 2.5 %
    }

    @Test
    void flatDemIsColouredAsZeroPercent() {
        Dem flat = SyntheticDems.metric(4, 3, 30, new float[] {512, 512, 512, 512, 512, 512, 512, 512, 512, 512, 512,
            Float.NaN});
        TintFunction tint = ColorRamp.named("hypsometric").bind(flat);
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                assertEquals(flat.isValid(col, row) ? DEEP_GREEN : 0, tint.argb(flat.get(col, row)));
            }
        }
        assertEquals(DEEP_GREEN, tint.argb(511));
        assertEquals(LIGHT_GREY, tint.argb(513));
        // standard on a flat DEM at sea level: 0 m counts as sea, and the flat sea half is at 0 %, which lies below
        // bathymetric's first stop (2.5 %), so its first colour.
        assertEquals(argb(24, 23, 54), ColorRamp.named("standard").bind(range(0, 0)).argb(0));
    }

    @Test
    void noDataIsTransparentForEveryBuiltInRamp() {
        for (String name : ColorRamp.names()) {
            assertEquals(0, ColorRamp.named(name).bind(range(0, 100)).argb(Float.NaN), name);
        }
    }

    @Test
    void allNoDataDemBindsAndStaysTransparent() {
        Dem empty = SyntheticDems.metric(2, 1, 30, new float[] {Float.NaN, Float.NaN});
        for (String name : ColorRamp.names()) {
            TintFunction tint = ColorRamp.named(name).bind(empty);
            assertEquals(0, tint.argb(Float.NaN), name);
        }
    }

    @Test
    void infiniteRangeIsRejectedForPercentStopsOnly() {
        ElevationStatistics infinite = range(Double.NEGATIVE_INFINITY, 100);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ColorRamp.named("hypsometric").bind(infinite));
        assertTrue(e.getMessage().contains("not finite"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ColorRamp.named("standard").bind(infinite));
        assertEquals(argb(51, 204, 102), ColorRamp.named("etopo1").bind(infinite).argb(100));
    }

    @Test
    void float32ExtremesAsTheRange() {
        TintFunction tint = ColorRamp.named("hypsometric").bind(range(-Float.MAX_VALUE, Float.MAX_VALUE));
        assertEquals(DEEP_GREEN, tint.argb(-Float.MAX_VALUE));
        assertEquals(LIGHT_GREY, tint.argb(Float.MAX_VALUE));
        // 0 is the middle: a = 0.5, between 39 % (124,33,35) and 52 % (121,121,121): r = 0.11/0.13 = 0.846154,
        // R = 124 − 3r = 121.46 → 121, G = 33 + 88r = 107.46 → 107, B = 35 + 86r = 107.77 → 108.
        assertEquals(argb(121, 107, 108), tint.argb(0));
    }

    // --- standard and etopo1 -----------------------------------------------------------------------------

    @Test
    void standardUsesEachHalfRange() {
        TintFunction tint = ColorRamp.named("standard").bind(range(-1437, 2205));
        assertEquals(argb(24, 23, 54), tint.argb(-1437));      // bathymetric, below its 2.5 % stop
        assertEquals(argb(11, 176, 203), tint.argb(-718.5f));  // bathymetric 50 % of [−1437, 0]
        assertEquals(argb(175, 218, 209), tint.argb(0));       // bathymetric 100 %
        assertEquals(argb(0, 99, 70), tint.argb(1e-3f));       // global 0 % of [0, 2205] (rounded)
        assertEquals(argb(230, 230, 230), tint.argb(2205));    // global 100 %
        // A DEM entirely above sea level: the land ramp spans [min, max].
        TintFunction land = ColorRamp.named("standard").bind(range(315, 2295));
        assertEquals(argb(0, 99, 70), land.argb(315));
        assertEquals(argb(230, 230, 230), land.argb(2295));
    }

    @Test
    void etopo1HasTheHardStepAtMinusOneMillimetre() {
        StopRamp etopo1 = (StopRamp) ColorRamp.named("etopo1");
        assertEquals(43, etopo1.stops().size());
        TintFunction tint = etopo1.bind(range(-1437, 2205));
        assertEquals(argb(188, 230, 255), tint.argb(-0.0011f));   // sea side, rounded
        assertEquals(argb(51, 102, 0), tint.argb(-0.0009f));      // land side, rounded
        assertEquals(argb(10, 0, 121), tint.argb(-11000));
        assertEquals(argb(255, 255, 255), tint.argb(8500));
        // Absolute: the range does not matter.
        assertEquals(tint.argb(1234.5f), etopo1.bind(range(0, 1)).argb(1234.5f));
    }

    // --- properties ----------------------------------------------------------------------------------------

    @Test
    void monotoneOnEveryChannelBetweenAdjacentStops() {
        for (String name : ColorRamp.names()) {
            if (!(ColorRamp.named(name) instanceof StopRamp ramp)) {
                continue;
            }
            // Bound to [0, 100] the percent stops sit at elevation = percent.
            TintFunction tint = ramp.bind(range(0, 100));
            double[] levels = ramp.stops().stream().mapToDouble(ColorStop::level).sorted().distinct().toArray();
            for (int s = 0; s + 1 < levels.length; s++) {
                // First and last float strictly inside the segment (a stop level may not be a float).
                float inLow = (float) levels[s] > levels[s] ? (float) levels[s] : Math.nextUp((float) levels[s]);
                float inHigh = (float) levels[s + 1] < levels[s + 1] ? (float) levels[s + 1]
                        : Math.nextDown((float) levels[s + 1]);
                int previous = tint.argb(inLow);
                int first = previous;
                int last = tint.argb(inHigh);
                for (int k = 1; k <= 400; k++) {
                    float e = Math.min(inHigh, Math.max(inLow,
                            (float) (levels[s] + (levels[s + 1] - levels[s]) * k / 401.0)));
                    int c = tint.argb(e);
                    for (int shift = 0; shift < 32; shift += 8) {
                        int direction = Integer.signum((last >>> shift & 0xFF) - (first >>> shift & 0xFF));
                        int step = (c >>> shift & 0xFF) - (previous >>> shift & 0xFF);
                        assertTrue(step * direction >= 0 && (direction != 0 || step == 0),
                                name + " not monotone at " + e + " (channel shift " + shift + ")");
                    }
                    previous = c;
                }
            }
        }
    }

    @Test
    void addingAConstantLeavesAPercentRampImageUnchanged() {
        Dem lux = TestDems.load(TestDems.LUXEMBOURG);
        for (String name : List.of("hypsometric", "hypsometric-original", "hypsometric-natural", "bathymetric",
                "bumpmap")) {
            ColorRamp ramp = ColorRamp.named(name);
            int[] reference = tint(lux, ramp);
            for (float c : new float[] {1000, -5000, 0.25f}) {
                assertArrayEquals(reference, tint(shifted(lux, c), ramp), name + " shifted by " + c);
            }
        }
        // Absolute stops do move with the data (a check that the property is not vacuous).
        assertNotEquals(tint(lux, ColorRamp.named("etopo1"))[4000],
                tint(shifted(lux, 1000), ColorRamp.named("etopo1"))[4000]);
    }

    @Test
    void lookupTableEqualsTheExactInterpolation() {
        Random random = new Random(846);
        for (ElevationStatistics r : List.of(range(315, 2295), range(-1437, 2205), range(-0.5, 0.5),
                range(141, 547))) {
            for (String name : ColorRamp.names()) {
                ColorRamp ramp = ColorRamp.named(name);
                TintFunction fast = ramp.bind(r);
                TintFunction exact = ramp instanceof StopRamp s ? s.bindExact(r)
                        : ramp instanceof TopoBathyRamp t ? t.bindExact(r) : ((SeaLandRamp) ramp).bindExact(r);
                for (int e = (int) r.min() - 3; e <= r.max() + 3; e++) {
                    assertEquals(exact.argb(e), fast.argb(e), name + " at " + e);
                }
                for (int k = 0; k < 2000; k++) {
                    float e = (float) (r.min() + random.nextDouble() * (r.max() - r.min()));
                    assertEquals(exact.argb(e), fast.argb(e), name + " at " + e);
                }
                assertEquals(exact.argb(-0f), fast.argb(-0f));
            }
        }
        assertTrue(ColorRamp.named("hypsometric").bind(range(315, 2295)) instanceof IntegerLookupTint);
        assertTrue(ColorRamp.named("hypsometric").bind(range(0, 1e6)) instanceof RatioTint, "no table that large");
    }

    // --- names ---------------------------------------------------------------------------------------------

    @Test
    void namesAreCaseInsensitiveWithAliases() {
        assertEquals("hypsometric-bathymetric", ColorRamp.names().get(0));
        assertSame(ColorRamp.named("hypsometric-bathymetric"), ColorRamp.defaultRamp());
        assertSame(ColorRamp.defaultRamp(), ColorRamp.named(" Hypsometric_Bathymetric"));
        assertSame(ColorRamp.named("hypsometric-natural"), ColorRamp.named(" Hypsometric_NATURAL "));
        assertSame(ColorRamp.named("standard"), ColorRamp.named("standard-coloring"));
        assertSame(ColorRamp.named("hypsometric-original"), ColorRamp.named("hypsometric-tint"));
        assertTrue(ColorRamp.names().containsAll(List.of("hypsometric", "hypsometric-original",
                "hypsometric-natural", "bathymetric", "etopo1", "standard", "gray")));
    }

    @Test
    void unknownNameListsTheKnownOnes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ColorRamp.named("hypsometrik"));
        assertTrue(e.getMessage().contains("'hypsometrik'"), e.getMessage());
        for (String name : ColorRamp.names()) {
            assertTrue(e.getMessage().contains(name), e.getMessage());
        }
    }

    @Test
    void grayIsOneColour() {
        TintFunction gray = ColorRamp.named("gray").bind(range(0, 100));
        assertEquals(0xFF808080, gray.argb(0));
        assertEquals(0xFF808080, gray.argb(57.3f));
        assertEquals(0xFF808080, gray.argb(1e9f));
    }

    // -------------------------------------------------------------------------------------------------------

    private static int[] tint(Dem dem, ColorRamp ramp) {
        TintFunction f = ramp.bind(dem);
        float[] v = dem.backingArray();
        int[] out = new int[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = f.argb(v[i]);
        }
        return out;
    }

    private static Dem shifted(Dem dem, float c) {
        float[] v = dem.backingArray().clone();
        for (int i = 0; i < v.length; i++) {
            v[i] += c;                      // exact in float32 for these integer elevations
        }
        return new Dem(v, dem.geometry());
    }
}
