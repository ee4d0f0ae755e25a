package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.internal.Brightness;
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
    void grayIsTheDocumentedFormulaBitForBit() {
        // The branch-free gray of jdem846 and horn against their formulas as documented (the tone, eq. 8 through
        // Brightness; gdaldem's 1 + 254·cos i): floats across the whole range and densely in [-1, 1].
        HillshadeOptions[] all = {D, D.withIntensities(0.3, 0.9), D.withIntensities(1, 0), D.withIntensities(-0.0, 0.5),
            D.withSpotExponent(2), D.withSpotExponent(0.37).withIntensities(0.6, 0.2)};
        java.util.Random rnd = new java.util.Random(5);
        for (int n = 0; n < 600_000; n++) {
            float f = n < 400_000 ? (float) (rnd.nextDouble() * 2.2 - 1.1)
                    : n < 500_000 ? Float.intBitsToFloat(rnd.nextInt())
                    : Float.intBitsToFloat(Float.floatToRawIntBits(1f) - 50_000 + n - 500_000);
            if (n % 2 == 1) {
                f = -f;
            }
            check(f, all);
        }
        for (float f : new float[] {0f, -0f, 1f, -1f, Float.MIN_VALUE, -Float.MIN_VALUE, Float.MAX_VALUE,
            -Float.MAX_VALUE, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NaN, Math.nextUp(1f),
            Math.nextDown(1f), Math.nextDown(-1f), Math.nextUp(-1f), 0.5f / 254, 1.5f / 254, 253.5f / 254}) {
            check(f, all);
        }
    }

    private static void check(float f, HillshadeOptions[] all) {
        for (HillshadeOptions o : all) {
            int jdem = Float.isNaN(f) ? 0
                    : 1 + (int) Math.rint(254.0 * Brightness.adjustBrightness(0.5, o.tone(f)));
            assertEquals(jdem, HillshadeMethod.JDEM846.gray(f, o), () -> "jdem846 " + f + " " + o);
        }
        double cang254 = 254.0 * f;
        float value = (float) (cang254 <= 0 ? 1.0 : 1.0 + cang254);
        int horn = Float.isNaN(f) ? 0 : (int) Math.rint(Math.max(0f, Math.min(255f, value)));
        assertEquals(horn, HillshadeMethod.HORN.gray(f, D), () -> "horn " + f);
    }

    @Test
    void multidirectionalGrayNeverWritesNoDataForAValidCell() {
        HillshadeMethod m = HillshadeMethod.MULTIDIRECTIONAL;
        assertEquals(0, m.gray(Float.NaN, D));
        assertEquals(1, m.gray((float) Math.sin(Math.toRadians(-5)), D));
        assertEquals(255, m.gray(1f, D));
    }

    @Test
    void arrayConversionEqualsGrayCellByCellForEveryMethod() {
        // the loops written out for horn and jdem846 against gray(), on a slice that leaves the ends alone; NaN with
        // the sign bit set is the x86 default NaN that arithmetic on NaN gives
        java.util.Random rnd = new java.util.Random(19);
        float[] values = new float[200_000];
        for (int i = 0; i < values.length; i++) {
            values[i] = i % 3 == 0 ? Float.intBitsToFloat(rnd.nextInt()) : (float) (rnd.nextDouble() * 2.4 - 1.2);
        }
        float[] special = {Float.NaN, Float.intBitsToFloat(0xFFC00000), Float.intBitsToFloat(0x7F800001), 0f, -0f,
            1f, -1f, Math.nextUp(1f), Math.nextDown(-1f), Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
            Float.MAX_VALUE, -Float.MIN_VALUE, 0.5f / 254, 1.5f / 254, 253.5f / 254, -0.5f};
        System.arraycopy(special, 0, values, 5, special.length);
        HillshadeOptions[] all = {D, D.withIntensities(0.3, 0.9), D.withIntensities(1, 0), D.withSpotExponent(2)};
        for (HillshadeMethod m : HillshadeMethod.values()) {
            for (HillshadeOptions o : all) {
                byte[] out = new byte[values.length + 7];
                java.util.Arrays.fill(out, (byte) 77);
                m.toGray(values, 3, out, 5, values.length - 4, o);
                for (int i = 0; i < values.length - 4; i++) {
                    int expected = m.gray(values[3 + i], o);
                    if ((out[5 + i] & 0xFF) != expected) {
                        assertEquals(expected, out[5 + i] & 0xFF, m + " " + o + " at " + values[3 + i]);
                    }
                }
                assertEquals(77, out[4]);
                assertEquals(77, out[out.length - 2]);
            }
        }
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
