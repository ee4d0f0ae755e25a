package io.github.jdem846.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.shade.HillshadeOptions;
import org.junit.jupiter.api.Test;

class BrightnessTest {

    @Test
    void eq8WorkedByHand() {
        // Color·(1 + dot) for dot < 0: 0.4·(1 − 0.5) = 0.2; Color + (1 − Color)·dot: 0.4 + 0.6·0.5 = 0.7.
        assertEquals(0.2, Brightness.adjustBrightness(0.4, -0.5), 1e-15);
        assertEquals(0.7, Brightness.adjustBrightness(0.4, 0.5), 1e-15);
        assertEquals(0.4, Brightness.adjustBrightness(0.4, 0.0), 0.0);
        assertEquals(0.0, Brightness.adjustBrightness(0.4, -1.0), 0.0);
        assertEquals(1.0, Brightness.adjustBrightness(0.4, 1.0), 0.0);
    }

    @Test
    void eq8StaysInRangeAndIsMonotoneInD() {
        for (double c = 0; c <= 1.0; c += 0.125) {
            double previous = -1;
            for (double d = -1.5; d <= 1.5; d += 0.01) {
                double b = Brightness.adjustBrightness(c, d);
                assertTrue(b >= 0 && b <= 1, "channel " + c + ", d " + d + " gave " + b);
                assertTrue(b >= previous, "not monotone at channel " + c + ", d " + d);
                previous = b;
            }
        }
        assertTrue(Double.isNaN(Brightness.adjustBrightness(0.5, Double.NaN)));
    }

    @Test
    void eq8OnArgbKeepsAlphaAndRoundsLikeTheOriginal() {
        // 128/255 · 0.5 · 255 = 64; 0x20/255 + (1 − 0x20/255)·0.25 → 32 + 223·0.25 = 87.75 → 88.
        assertEquals(0x7F404040, Brightness.adjustBrightness(0x7F808080, -0.5));
        assertEquals(0xFF585858, Brightness.adjustBrightness(0xFF202020, 0.25));
    }

    @Test
    void eq8OnArgbEqualsEq8OnEachChannel() {
        // The packed-pixel version is the per-channel formula on c/255, rounded with Math.round, for every 8-bit
        // channel value and d across and beyond [−1, 1] (including the clamps and d = ±0).
        java.util.Random rnd = new java.util.Random(846);
        for (int c = 0; c < 256; c++) {
            for (int k = -60; k <= 60; k++) {
                double d = k == 0 ? -0.0 : k / 50.0 + (rnd.nextDouble() - 0.5) * 1e-3;
                int argb = 0x80000000 | (c << 16) | ((255 - c) << 8) | (c * 7 & 0xFF);
                int expected = 0x80000000
                        | (int) Math.round(Brightness.adjustBrightness(c / 255.0, d) * 255.0) << 16
                        | (int) Math.round(Brightness.adjustBrightness((255 - c) / 255.0, d) * 255.0) << 8
                        | (int) Math.round(Brightness.adjustBrightness((c * 7 & 0xFF) / 255.0, d) * 255.0);
                assertEquals(expected, Brightness.adjustBrightness(argb, d), "c " + c + ", d " + d);
            }
        }
    }

    @Test
    void intensityStepScalesLightAndDarkSeparately() {
        assertEquals(0.6, Brightness.intensity(0.8, 0.75, 1.0), 1e-15);
        assertEquals(-0.8, Brightness.intensity(-0.8, 0.75, 1.0), 1e-15);
        assertEquals(-0.4, Brightness.intensity(-0.8, 0.75, 0.5), 1e-15);
        assertEquals(0.0, Brightness.intensity(0.0, 0.75, 0.5), 0.0);
    }

    @Test
    void spotExponentPreservesTheSign() {
        // The original's pow(−0.8, 2) = +0.64 turned shade into light; here it stays shade.
        assertEquals(-0.64, Brightness.spot(-0.8, 2), 1e-15);
        assertEquals(0.25, Brightness.spot(0.5, 2), 1e-15);
        assertEquals(-0.125, Brightness.spot(-0.5, 3), 1e-15);
        assertEquals(-0.3, Brightness.spot(-0.3, 1), 0.0);
        for (double d = -1; d <= 1; d += 0.05) {
            for (double spot : new double[] {0.5, 1, 2, 4, 5}) {
                double s = Brightness.spot(d, spot);
                assertTrue(Math.signum(s) == Math.signum(d) || d == 0 || Math.abs(s) < 1e-300,
                        "sign changed: spot(" + d + ", " + spot + ") = " + s);
                assertTrue(Math.abs(s) <= 1, "spot left [−1, 1]");
            }
        }
    }

    @Test
    void toneAppliesIntensityThenSpot() {
        HillshadeOptions o = HillshadeOptions.DEFAULTS.withSpotExponent(2);
        // 0.8 · 0.75 = 0.6, squared 0.36; −0.5 · 1.0 = −0.5, signed square −0.25.
        assertEquals(0.36, o.tone(0.8), 1e-15);
        assertEquals(-0.25, o.tone(-0.5), 1e-15);
        assertEquals(0.6, HillshadeOptions.DEFAULTS.tone(0.8), 1e-15);
    }
}
