package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class HillshadeMethodTest {

    private static final HillshadeOptions D = HillshadeOptions.DEFAULTS;

    @Test
    void stagesAreTheDocumentedClasses() {
        assertInstanceOf(JDem846Illumination.class, HillshadeMethod.JDEM846.stage(D));
        assertInstanceOf(HornIllumination.class, HillshadeMethod.HORN.stage(D));
        assertInstanceOf(MultidirectionalIllumination.class, HillshadeMethod.MULTIDIRECTIONAL.stage(D));
    }

    @Test
    void jdem846GrayIsEq8OnMidGrayAfterTheTone() {
        HillshadeMethod m = HillshadeMethod.JDEM846;
        assertEquals(0, m.gray(Float.NaN, D));
        assertEquals(1, m.gray(-1f, D));               // dark intensity 1.0: −1 → channel 0 → 1
        assertEquals(128, m.gray(0f, D));              // channel 0.5 → 1 + 127
        assertEquals(223, m.gray(1f, D));              // 1 · 0.75 → 0.5 + 0.5·0.75 = 0.875 → 1 + 222.25 → 223
        assertEquals(255, m.gray(1f, D.withIntensities(1, 1)));
        // −0.5: channel 0.25 → 254 · 0.25 = 63.5 → 64 (ties to even) → 65
        assertEquals(65, m.gray(-0.5f, D));
        for (float d = -1; d <= 1; d += 0.01f) {
            int g = m.gray(d, D);
            assertTrue(g >= 1 && g <= 255, "valid cells never map to the no-data byte");
        }
    }

    @Test
    void hornGrayIsGdaldems() {
        HillshadeMethod m = HillshadeMethod.HORN;
        assertEquals(0, m.gray(Float.NaN, D));
        assertEquals(1, m.gray(-0.3f, D));
        assertEquals(1, m.gray(0f, D));
        assertEquals(255, m.gray(1f, D));
        assertEquals(128, m.gray(0.5f, D));   // 1 + 127
        assertEquals(181, m.gray((float) Math.sin(Math.toRadians(45)), D)); // 1 + 179.605 → 181 (gdaldem, flat)
    }

    @Test
    void multidirectionalGrayNeverWritesNoDataForAValidCell() {
        HillshadeMethod m = HillshadeMethod.MULTIDIRECTIONAL;
        assertEquals(0, m.gray(Float.NaN, D));
        assertEquals(1, m.gray((float) Math.sin(Math.toRadians(-5)), D));
        assertEquals(255, m.gray(1f, D));
    }

    @Test
    void toGrayMapsEveryCell() {
        byte[] g = HillshadeMethod.HORN.toGray(new float[] {Float.NaN, 0.5f, 1f}, D);
        assertEquals(0, g[0] & 0xFF);
        assertEquals(128, g[1] & 0xFF);
        assertEquals(255, g[2] & 0xFF);
    }

    @Test
    void optionsRejectNonsenseWithAMessage() {
        assertEquals(1.0, D.zFactor());
        assertEquals(0.75, D.lightMultiple());
        assertEquals(0.75, D.relativeLightIntensity());
        assertEquals(1.0, D.relativeDarkIntensity());
        assertEquals(1.0, D.spotExponent());
        assertTrue(Double.isNaN(D.horizontalScale()));
        assertMessage(() -> D.withZFactor(0), "z-factor");
        assertMessage(() -> D.withZFactor(Double.NaN), "z-factor");
        assertMessage(() -> D.withZFactor(1e9), "z-factor");
        assertMessage(() -> D.withLightMultiple(-1), "light multiple");
        assertMessage(() -> D.withIntensities(1.5, 1), "light intensity");
        assertMessage(() -> D.withIntensities(0.5, -0.1), "dark intensity");
        assertMessage(() -> D.withSpotExponent(0), "spot exponent");
        assertMessage(() -> D.withHorizontalScale(-3), "horizontal scale");
        assertMessage(() -> D.withHorizontalScale(Double.POSITIVE_INFINITY), "horizontal scale");
    }

    private static void assertMessage(org.junit.jupiter.api.function.Executable e, String fragment) {
        IllegalArgumentException x = assertThrows(IllegalArgumentException.class, e);
        assertTrue(x.getMessage().contains(fragment), x.getMessage());
    }
}
