package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.internal.Brightness;
import io.github.jdem846.shade.HillshadeOptions;
import org.junit.jupiter.api.Test;

class CompositorTest {

    private final Compositor original = new Compositor(HillshadeOptions.DEFAULTS, 0.4);

    @Test
    void eq8DarkensTowardBlackAndLightensTowardWhite() {
        // Worked by hand: c = 0.6; d = −0.5 → 0.6·0.5 = 0.3; d = +0.5 → 0.6 + 0.4·0.5 = 0.8.
        assertEquals(0.3, Brightness.adjustBrightness(0.6, -0.5), 1e-15);
        assertEquals(0.8, Brightness.adjustBrightness(0.6, 0.5), 1e-15);
        assertEquals(0.0, Brightness.adjustBrightness(0.6, -1), 1e-15);
        assertEquals(1.0, Brightness.adjustBrightness(0.6, 1), 1e-15);
        assertEquals(0.6, Brightness.adjustBrightness(0.6, 0), 1e-15);
    }

    @Test
    void brightnessFollowsTheOriginalOrder() {
        // dot 0.8, lit: 0.8·0.75 = 0.6. In shadow: 0.8 − 0.8 = 0 → 0. dot 0.2 in shadow: 0.2 − 0.8 = −0.6 (dark 1.0).
        assertEquals(0.6, original.brightness(0.8, 0, 0), 1e-12);
        assertEquals(0.0, original.brightness(0.8, 1, 0), 1e-12);
        assertEquals(-0.6, original.brightness(0.2, 1, 0), 1e-12);
        // clamped at −1 before the intensities
        assertEquals(-1.0, original.brightness(-0.9, 1, 0), 1e-12);
    }

    @Test
    void evenSpotExponentKeepsShadeDark() {
        Compositor spot2 = new Compositor(HillshadeOptions.DEFAULTS.withIntensities(1, 1).withSpotExponent(2), 0.4);
        assertEquals(-0.64, spot2.brightness(-0.8, 0, 0), 1e-12);
        assertEquals(0.64, spot2.brightness(0.8, 0, 0), 1e-12);
    }

    @Test
    void composeRoundsEachChannelAndKeepsAlpha() {
        int tint = 0xFF_99_33_00; // r = 153, g = 51, b = 0
        // d = 0.4 · 0.75 = 0.3: r = 153 + 102·0.3 = 183.6 → 184; g = 51 + 204·0.3 = 112.2 → 112; b = 76.5 → 77
        // (76.5 rounds half up to 77)
        int px = original.compose(tint, 0.4, 0, 0);
        assertEquals(0xFF, px >>> 24);
        assertEquals(184, (px >> 16) & 0xff);
        assertEquals(112, (px >> 8) & 0xff);
        assertEquals(77, px & 0xff);
    }

    @Test
    void noDataStaysTransparent() {
        assertEquals(0, original.compose(0x00000000, 0.5, 0, 0));
        assertEquals(0, original.compose(0xFFFFFFFF, Double.NaN, 0, 0));
    }
}
