package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.tint.ColorRamp;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The blend modes ({@link BlendMode}, {@link Blend}) against hand-worked values and the properties they must have. */
class BlendTest {

    private static final HillshadeOptions TONE = HillshadeOptions.DEFAULTS;

    private static Compositor compositor(BlendMode mode, double opacity, HillshadeOptions tone) {
        return new Compositor(tone, 0.4, LightModel.JDEM846, 0, new Blend(mode, opacity));
    }

    private static int red(int argb) {
        return (argb >> 16) & 0xFF;
    }

    @Test
    void w3cFormulasByHand() {
        // multiply c·g; screen c + g − c·g
        assertEquals(0.3, BlendMode.MULTIPLY.blend(0.6, 0.5), 1e-15);
        assertEquals(0.8, BlendMode.SCREEN.blend(0.6, 0.5), 1e-15);
        // overlay, backdrop c = 0.2 ≤ ½: 2·0.2·0.3 = 0.12; c = 0.6: screen(0.3, 0.2) = 0.3 + 0.2 − 0.06 = 0.44
        assertEquals(0.12, BlendMode.OVERLAY.blend(0.2, 0.3), 1e-15);
        assertEquals(0.44, BlendMode.OVERLAY.blend(0.6, 0.3), 1e-15);
        // soft light, g = 0.3 ≤ ½: 0.2 − 0.4·0.2·0.8 = 0.136
        assertEquals(0.136, BlendMode.SOFT_LIGHT.blend(0.2, 0.3), 1e-15);
        // g = 0.8, c = 0.16 ≤ ¼: D = ((2.56 − 12)·0.16 + 4)·0.16 = 0.398336; 0.16 + 0.6·0.238336 = 0.3030016
        assertEquals(0.3030016, BlendMode.SOFT_LIGHT.blend(0.16, 0.8), 1e-15);
        // g = 0.8, c = 0.64 > ¼: D = √0.64 = 0.8; 0.64 + 0.6·0.16 = 0.736
        assertEquals(0.736, BlendMode.SOFT_LIGHT.blend(0.64, 0.8), 1e-15);
    }

    @Test
    void neutralLayersLeaveEveryChannelAsItWas() {
        for (int v = 0; v <= 255; v++) {
            double c = v / 255.0;
            assertEquals(c, BlendMode.MULTIPLY.blend(c, 1), 1e-15, "multiply by white");
            assertEquals(c, BlendMode.SCREEN.blend(c, 0), 1e-15, "screen with black");
            assertEquals(c, BlendMode.OVERLAY.blend(c, 0.5), 1e-15, "overlay with gray ½");
            assertEquals(c, BlendMode.SOFT_LIGHT.blend(c, 0.5), 1e-15, "soft light with gray ½");
        }
    }

    @Test
    void originalLightenAndDarkenByHandWithTheSignFixed() {
        // d = 0.5 (a lit slope), c = 0.4.
        // LIGHTEN: e = (1 + 0.5)/2 = 0.75 → 0.4 + 0.6·0.75 = 0.85 (the original's e = 1 − 0.75 = 0.25 lit it least)
        double e = BlendMode.JDEM846_LIGHTEN.layer(0.5, TONE);
        assertEquals(0.75, e, 1e-15);
        assertEquals(0.85, BlendMode.JDEM846_LIGHTEN.blend(0.4, e), 1e-15);
        // DARKEN: e = (0.5 − 1)/2 = −0.25 → 0.4·0.75 = 0.3 (the original's e = −0.75 darkened it most)
        e = BlendMode.JDEM846_DARKEN.layer(0.5, TONE);
        assertEquals(-0.25, e, 1e-15);
        assertEquals(0.3, BlendMode.JDEM846_DARKEN.blend(0.4, e), 1e-15);
        // spot exponent 2 keeps the sign: d = −0.5 → d′ = −0.25; LIGHTEN e = 0.375 → 0.4 + 0.6·0.375 = 0.625;
        // DARKEN e = −0.625 → 0.4·0.375 = 0.15. The light/dark intensities are not used (the original's era A).
        HillshadeOptions spot2 = TONE.withSpotExponent(2).withIntensities(0.1, 0.1);
        assertEquals(0.625, BlendMode.JDEM846_LIGHTEN.blend(0.4, BlendMode.JDEM846_LIGHTEN.layer(-0.5, spot2)), 1e-15);
        assertEquals(0.15, BlendMode.JDEM846_DARKEN.blend(0.4, BlendMode.JDEM846_DARKEN.layer(-0.5, spot2)), 1e-15);
        // the ends: facing the light fully, LIGHTEN is white and DARKEN the tint; facing away, the reverse
        assertEquals(1.0, BlendMode.JDEM846_LIGHTEN.blend(0.4, BlendMode.JDEM846_LIGHTEN.layer(1, TONE)), 1e-15);
        assertEquals(0.4, BlendMode.JDEM846_LIGHTEN.blend(0.4, BlendMode.JDEM846_LIGHTEN.layer(-1, TONE)), 1e-15);
        assertEquals(0.4, BlendMode.JDEM846_DARKEN.blend(0.4, BlendMode.JDEM846_DARKEN.layer(1, TONE)), 1e-15);
        assertEquals(0.0, BlendMode.JDEM846_DARKEN.blend(0.4, BlendMode.JDEM846_DARKEN.layer(-1, TONE)), 1e-15);
    }

    @Test
    void theFixedModesAreTheOriginalFormulasWithTheLightReversed() {
        for (double d = -1; d <= 1; d += 1.0 / 64) {
            double originalLighten = 1 - (-d + 1) / 2;           // the original's LIGHTEN of −d
            double originalDarken = -Math.abs((-d + 1) / 2);     // the original's DARKEN of −d
            assertEquals(originalLighten, BlendMode.JDEM846_LIGHTEN.layer(d, TONE), 1e-15);
            assertEquals(originalDarken, BlendMode.JDEM846_DARKEN.layer(d, TONE), 1e-15);
        }
    }

    @Test
    void lightenNeverDarkensAndDarkenNeverLightensAnyChannel() {
        for (double d = -1; d <= 1; d += 1.0 / 32) {
            for (int v = 0; v <= 255; v += 5) {
                int tint = 0xFF000000 | v << 16 | (255 - v) << 8 | (v * 7 % 256);
                for (double spot : new double[] {0.5, 1, 3}) {
                    HillshadeOptions tone = TONE.withSpotExponent(spot);
                    int light = compositor(BlendMode.JDEM846_LIGHTEN, 1, tone).compose(tint, d, 0, 0);
                    int dark = compositor(BlendMode.JDEM846_DARKEN, 1, tone).compose(tint, d, 0, 0);
                    for (int shift = 0; shift <= 16; shift += 8) {
                        int c = (tint >> shift) & 0xFF;
                        assertTrue(((light >> shift) & 0xFF) >= c, "lighten at d = " + d);
                        assertTrue(((dark >> shift) & 0xFF) <= c, "darken at d = " + d);
                    }
                }
            }
        }
    }

    @Test
    void grayIsTheHillshadeCommandsGrayBeforeRounding() {
        assertEquals(1 / 255.0, BlendMode.gray(-1), 1e-15);
        assertEquals(128 / 255.0, BlendMode.gray(0), 1e-15);
        assertEquals(1.0, BlendMode.gray(1), 1e-15);
        for (float dot = -1; dot <= 1; dot += 1f / 128) {
            int expected = HillshadeMethod.JDEM846.gray(dot, TONE);
            assertEquals(expected, 255 * BlendMode.gray(TONE.tone(dot)), 0.5 + 1e-9, "dot " + dot);
        }
    }

    @Test
    void multiplyComposesTintTimesGrayAndRoundsEachChannel() {
        // dot 0.4 → t = 0.3 → g = (1 + 127·1.3)/255 = 166.1/255; r = 153·166.1/255 = 99.66 → 100,
        // g = 51·166.1/255 = 33.22 → 33, b = 0; alpha kept
        int px = compositor(BlendMode.MULTIPLY, 1, TONE).compose(0x80_99_33_00, 0.4, 0, 0);
        assertEquals(0x80_64_21_00, px);
    }

    @Test
    void opacityMixesTheBareTintWithTheShadedOne() {
        // eq. 8 at dot 0.4: 153 → 183.6; with opacity 0.75 (the original's era A): 0.25·153 + 0.75·183.6 = 175.95 → 176
        assertEquals(176, red(compositor(BlendMode.JDEM846, 0.75, TONE).compose(0xFF_99_33_00, 0.4, 0, 0)));
        for (BlendMode mode : BlendMode.values()) {
            assertEquals(0xFF_99_33_00, compositor(mode, 0, TONE).compose(0xFF_99_33_00, -0.7, 0.5, 0), mode.name());
        }
        assertThrows(IllegalArgumentException.class, () -> new Blend(BlendMode.MULTIPLY, 1.01));
        assertThrows(IllegalArgumentException.class, () -> new Blend(BlendMode.MULTIPLY, -0.01));
        assertThrows(IllegalArgumentException.class, () -> new Blend(BlendMode.MULTIPLY, Double.NaN));
        assertThrows(NullPointerException.class, () -> new Blend(null, 1));
    }

    @Test
    void noDataStaysTransparentInEveryMode() {
        for (BlendMode mode : BlendMode.values()) {
            for (double opacity : new double[] {0, 0.5, 1}) {
                Compositor c = compositor(mode, opacity, TONE);
                assertEquals(0, c.compose(0x00000000, 0.5, 0, 0), mode.name());
                assertEquals(0, c.compose(0x00FFFFFF, 0.5, 0, 0), mode.name());
                assertEquals(0, c.compose(0xFF336699, Double.NaN, 0, 0), mode.name());
            }
        }
    }

    @Test
    void theDefaultBlendIsTheRenderWithoutOne() {
        Compositor plain = new Compositor(TONE, 0.4, LightModel.JDEM846, 0);
        Compositor explicit = compositor(BlendMode.JDEM846, 1, TONE);
        for (double d = -1; d <= 1; d += 1.0 / 50) {
            for (int v = 0; v < 256; v += 3) {
                int tint = 0xFF000000 | v << 16 | (255 - v) << 8 | v / 2;
                assertEquals(plain.compose(tint, d, 0.3, 0), explicit.compose(tint, d, 0.3, 0));
            }
        }
        assertEquals(Blend.DEFAULT, Scene.defaults().blend());
    }

    @Test
    void namesOnTheCommandLine() {
        assertEquals(BlendMode.SOFT_LIGHT, BlendMode.named("soft-light"));
        assertEquals(BlendMode.SOFT_LIGHT, BlendMode.named(" Soft_Light "));
        assertEquals(BlendMode.JDEM846_DARKEN, BlendMode.named("jdem846-darken"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> BlendMode.named("lighten"));
        assertEquals("unknown blend mode 'lighten'; expected one of jdem846, jdem846-lighten, jdem846-darken, "
                + "multiply, screen, overlay, soft-light", e.getMessage());
    }

    /**
     * A flat plane under a sun placed so that the plane's gray is each mode's neutral value renders as its tint:
     * soft light and overlay at gray ½ (t = −1/254: dot = sin e = −1/254 with dark intensity 1), multiply at white
     * (t = 1: the sun at the zenith, light intensity 1).
     */
    @Test
    void aFlatPlaneAtTheNeutralGrayRendersAsItsTint() throws InterruptedException {
        int n = 8;
        float[] heights = new float[n * n];
        Arrays.fill(heights, 500f);
        Dem flat = new Dem(heights, GridGeometry.metric(n, n, 30));
        Scene base = Scene.defaults().withTint(ColorRamp.named("hypsometric"))
                .withTintRange(ElevationStatistics.ofRange(0, 1500, 1, 1));
        int[] tint = new Renderer().render(flat, base.withHillshade(null).withBlend(new Blend(BlendMode.MULTIPLY, 0)))
                .argb();
        assertTrue(tint[0] != 0xFF808080 && (tint[0] >>> 24) == 0xFF);
        double half = Math.toDegrees(Math.asin(-1.0 / 254));
        for (BlendMode mode : new BlendMode[] {BlendMode.SOFT_LIGHT, BlendMode.OVERLAY}) {
            int[] px = new Renderer().render(flat, base.withLight(new LightDirection(320, half))
                    .withBlend(new Blend(mode, 1))).argb();
            assertTrue(Arrays.equals(tint, px), mode.name());
        }
        Scene zenith = base.withLight(new LightDirection(0, 90))
                .withHillshadeOptions(TONE.withIntensities(1, 1)).withBlend(new Blend(BlendMode.MULTIPLY, 1));
        assertTrue(Arrays.equals(tint, new Renderer().render(flat, zenith).argb()));
    }
}
