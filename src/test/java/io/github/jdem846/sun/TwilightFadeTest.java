package io.github.jdem846.sun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The original's fade, worked by hand from jdem846-original.md §3: d −= 2·(z−90)/(108−90), clamp at −1. */
class TwilightFadeTest {

    private final TwilightFade fade = TwilightFade.ORIGINAL;

    @Test
    void daylightIsUntouched() {
        assertEquals(0.8, fade.apply(0.8, 30), 0);
        assertEquals(-0.3, fade.apply(-0.3, 90), 0);
        assertEquals(0, fade.darkening(0));
    }

    @Test
    void handWorkedValuesInTwilight() {
        assertEquals(0.8 - 2 * 5.0 / 18, fade.apply(0.8, 95), 1e-12); // 0.2444…
        assertEquals(0.0, fade.apply(1.0, 99), 1e-12); // halfway: minus 1
        assertEquals(1.0 - 2 * 0.01 / 18, fade.apply(1.0, 90.01), 1e-12);
        assertEquals(-1, fade.apply(1.0, 108), 0); // 1 − 2 = −1
        assertEquals(-1, fade.apply(0.5, 107), 0); // 0.5 − 1.889 clamps
    }

    @Test
    void nightIsFullyDarkWhateverTheSlope() {
        for (double d = -1; d <= 1; d += 0.125) {
            assertEquals(-1, fade.apply(d, 108.0001), 0);
            assertEquals(-1, fade.apply(d, 180), 0);
        }
        assertEquals(2, fade.darkening(120));
    }

    @Test
    void monotoneInZenithAndBoundedBelow() {
        for (double d = -1; d <= 1; d += 0.1) {
            double previous = Double.POSITIVE_INFINITY;
            for (double z = 0; z <= 180; z += 0.25) {
                double v = fade.apply(d, z);
                assertTrue(v <= previous + 1e-15, "not monotone at d=" + d + ", z=" + z);
                assertTrue(v >= -1 && v <= 1);
                previous = v;
            }
        }
    }

    @Test
    void noDataStaysNoData() {
        assertTrue(Double.isNaN(fade.apply(Double.NaN, 95)));
        assertTrue(Double.isNaN(fade.apply(0.5, Double.NaN)));
    }

    @Test
    void customZenithsAndValidation() {
        TwilightFade civil = new TwilightFade(90, 96);
        assertEquals(0.5 - 1, civil.apply(0.5, 93), 1e-12);
        SolarCalculatorTest.assertMessage(() -> new TwilightFade(108, 90), "light zenith < dark zenith");
        SolarCalculatorTest.assertMessage(() -> new TwilightFade(90, 200), "dark zenith");
        SolarCalculatorTest.assertMessage(() -> new TwilightFade(Double.NaN, 108), "zenith");
    }
}
