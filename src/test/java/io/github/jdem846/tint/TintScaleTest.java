package io.github.jdem846.tint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.ElevationStatistics;
import org.junit.jupiter.api.Test;

/**
 * The original's elevation scalers applied to the tint, worked by hand from their formulas (jDem846
 * {@code scaling/*Scaler.java} with an elevation multiple of 1), and the tints ported from its gradient files.
 */
class TintScaleTest {

    private static ElevationStatistics range(double min, double max) {
        return new ElevationStatistics(min, max, 100, 100);
    }

    private static int argb(int r, int g, int b) {
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    @Test
    void formulasByHand() {
        // Logarithmic on a 1000 m range: r = 0.5 -> log(5000)/log(10000) = 3.69897/4 = 0.924743.
        assertEquals(0.924743, TintScale.LOGARITHMIC.apply(0.5, 1000), 1e-6);
        // r = 0.0001 -> 10·r·R = 1 -> log 1 = 0; below that the original went negative (black): clamped to 0.
        assertEquals(0, TintScale.LOGARITHMIC.apply(0.0001, 1000), 1e-12);
        assertEquals(0, TintScale.LOGARITHMIC.apply(0.00001, 1000), 0);
        // Exponential on 10 000 m: r = 0.5 -> (2^0.5 − 1)/(2 − 1) = 0.414214.
        assertEquals(Math.sqrt(2) - 1, TintScale.EXPONENTIAL.apply(0.5, 10000), 1e-12);
        // Cubic: r³.
        assertEquals(0.125, TintScale.CUBIC.apply(0.5, 1234), 0);
        assertEquals(0.3, TintScale.LINEAR.apply(0.3, 1234), 0);
    }

    @Test
    void everyScaleKeepsTheEndsAndIsMonotoneOnTinyAndHugeRanges() {
        for (TintScale scale : TintScale.values()) {
            for (double span : new double[] {0, 1e-6, 0.05, 0.1, 1, 1000, 8848 + 10994, 1e9, Float.MAX_VALUE}) {
                assertEquals(0, scale.apply(0, span), 1e-12, scale + " over " + span);
                assertEquals(1, scale.apply(1, span), 1e-12, scale + " over " + span);
                double previous = 0;
                for (int k = 0; k <= 1000; k++) {
                    double v = scale.apply(k / 1000.0, span);
                    assertTrue(v >= previous && v <= 1 && !Double.isNaN(v), scale + " over " + span + " at " + k);
                    previous = v;
                }
            }
            assertEquals(0, scale.apply(-3, 100), 0, "below the range clamps");
            assertEquals(1, scale.apply(7, 100), 0, "above the range clamps");
        }
    }

    @Test
    void exponentialTendsToLinearOnSmallRanges() {
        // 2^(x/10000) is almost linear over 100 m: within 0.2 % of r.
        for (int k = 0; k <= 10; k++) {
            assertEquals(k / 10.0, TintScale.EXPONENTIAL.apply(k / 10.0, 100), 0.002);
        }
    }

    @Test
    void aScaledPercentRampColoursTheScaledPosition() {
        // bumpmap is black at 0 % and white at 100 %: the grey level is the scaled position.
        TintFunction cubic = ColorRamp.named("bumpmap").withScale(TintScale.CUBIC).bind(range(100, 300));
        assertEquals(argb(32, 32, 32), cubic.argb(200));        // 0.5³·255 = 31.9
        assertEquals(argb(0, 0, 0), cubic.argb(100));
        assertEquals(argb(255, 255, 255), cubic.argb(300));
        assertEquals(argb(255, 255, 255), cubic.argb(1e6f), "beyond the range: the end colour");
        TintFunction log = ColorRamp.named("bumpmap").withScale(TintScale.LOGARITHMIC).bind(range(100, 1100));
        assertEquals(argb(236, 236, 236), log.argb(600));       // 0.924743·255 = 235.8
        assertEquals(0, log.argb(Float.NaN), "no-data stays transparent");
    }

    @Test
    void linearIsTheRampItself() {
        ColorRamp ramp = ColorRamp.named("hypsometric");
        assertSame(ramp, ramp.withScale(TintScale.LINEAR));
    }

    @Test
    void splitRampsScaleEachSideOfSeaLevelApart() {
        ElevationStatistics landAndSea = range(-1000, 3000);
        for (String name : new String[] {"hypsometric-bathymetric", "standard"}) {
            ColorRamp ramp = ColorRamp.named(name);
            TintFunction plain = ramp.bind(landAndSea);
            TintFunction cubic = ramp.withScale(TintScale.CUBIC).bind(landAndSea);
            // Land at r = 0.5 of [0, 3000] takes the plain colour of r = 0.125, i.e. of 375 m.
            assertEquals(plain.argb(375), cubic.argb(1500), name);
            // Sea at r = 0.5 of [−1000, 0] takes the plain colour of −875 m.
            assertEquals(plain.argb(-875), cubic.argb(-500), name);
            // Just above and below sea level the colours stay on their side.
            assertEquals(plain.argb(Float.MIN_VALUE), cubic.argb(0.001f), name);
            assertEquals(plain.argb(-1000), cubic.argb(-999.999f), name);
            assertEquals(plain.argb(0), cubic.argb(0), name);
            assertEquals(plain.argb(Math.nextDown(0f)), cubic.argb(-0.0001f), name);
        }
    }

    @Test
    void theLookupTableEqualsTheExactScaledTint() {
        ScaledRamp ramp = new ScaledRamp(ColorRamp.named("hypsometric-bathymetric"), TintScale.LOGARITHMIC);
        ElevationStatistics r = range(-1437, 2205);
        TintFunction fast = ramp.bind(r);
        TintFunction exact = ramp.bindExact(r);
        for (int e = -1440; e <= 2210; e++) {
            assertEquals(exact.argb(e), fast.argb(e), "at " + e);
        }
    }

    @Test
    void rampsInMetresAndDoubleScalesAreRefused() {
        for (String name : new String[] {"etopo1", "dark-bathymetric"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ColorRamp.named(name).withScale(TintScale.CUBIC));
            assertTrue(e.getMessage().contains(name) && e.getMessage().contains("percent"), e.getMessage());
        }
        ColorRamp once = ColorRamp.named("hypsometric").withScale(TintScale.CUBIC);
        assertThrows(IllegalArgumentException.class, () -> once.withScale(TintScale.LOGARITHMIC));
    }

    // --- the tints ported from the original -------------------------------------------------------------

    @Test
    void darkBathymetricIsTheOriginalsGradientFile() {
        TintFunction dark = ColorRamp.named("dark-bathy-tint").bind(range(-5000, 2000));
        assertEquals(argb(3, 8, 16), dark.argb(-11000));
        assertEquals(argb(26, 71, 128), dark.argb(-500));
        assertEquals(argb(26, 71, 128), dark.argb(-100));
        // −5750 m is halfway from −11000 to −500: (3 + 26)/2 = 14.5, (8 + 71)/2 = 39.5, (16 + 128)/2 = 72
        int mid = dark.argb(-5750);
        assertEquals(72, mid & 0xff);
        assertTrue(Math.abs(((mid >> 8) & 0xff) - 39.5) <= 0.5 && Math.abs(((mid >> 16) & 0xff) - 14.5) <= 0.5);
        assertEquals(argb(255, 255, 255), dark.argb(0), "land is white");
        assertEquals(argb(255, 255, 255), dark.argb(4000));
    }

    @Test
    void triGreenYellowRedAndTheOneColourTints() {
        TintFunction tri = ColorRamp.named("tri").bind(range(0, 200));
        assertEquals(argb(0, 255, 0), tri.argb(0));
        assertEquals(argb(255, 255, 0), tri.argb(100));
        assertEquals(argb(255, 0, 0), tri.argb(200));
        assertEquals(argb(64, 255, 0), tri.argb(25));           // 12.5 %: a quarter of the way to yellow, 63.75
        assertEquals(argb(146, 173, 144), ColorRamp.named("green-tint").bind(range(0, 9)).argb(5));
        assertEquals(argb(0, 0, 0), ColorRamp.named("black").bind(range(0, 9)).argb(5));
        assertEquals(0, ColorRamp.named("transparent").bind(range(0, 9)).argb(5));
    }
}
