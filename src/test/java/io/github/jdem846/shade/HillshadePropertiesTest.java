package io.github.jdem846.shade;

import static io.github.jdem846.shade.ShadeTestSupport.illuminate;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Properties every hillshade method must have, on real DEMs. */
class HillshadePropertiesTest {

    private static final LightDirection LIGHT = new LightDirection(320, 25);

    @ParameterizedTest
    @EnumSource(HillshadeMethod.class)
    void anyRectangleEqualsTheCropOfTheFullComputation(HillshadeMethod method) {
        for (Dem dem : new Dem[] {TestDems.load(TestDems.LUXEMBOURG), TestDems.load(TestDems.VOLCANO)}) {
            IlluminationStage stage = method.stage(HillshadeOptions.DEFAULTS);
            float[] full = illuminate(stage, dem, LIGHT);
            Random rnd = new Random(42);
            for (int k = 0; k < 60; k++) {
                int w = 1 + rnd.nextInt(dem.width());
                int h = 1 + rnd.nextInt(dem.height());
                int c0 = rnd.nextInt(dem.width() - w + 1);
                int r0 = rnd.nextInt(dem.height() - h + 1);
                float[] tile = new float[w * h];
                stage.illuminate(dem, LIGHT, c0, r0, w, h, tile);
                for (int r = 0; r < h; r++) {
                    for (int c = 0; c < w; c++) {
                        float expected = full[(r0 + r) * dem.width() + c0 + c];
                        assertEquals(Float.floatToIntBits(expected), Float.floatToIntBits(tile[r * w + c]),
                                method + " tile " + w + "×" + h + " at " + c0 + "," + r0);
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(HillshadeMethod.class)
    void addingAConstantHeightChangesNothing(HillshadeMethod method) {
        Dem dem = TestDems.load(TestDems.LUXEMBOURG);
        float[] raised = dem.backingArray().clone();
        for (int i = 0; i < raised.length; i++) {
            raised[i] += 1000; // NaN stays NaN; integers stay exact
        }
        // z-factor 5: Luxembourg's 30″ cells are gentle, and combined and igor darken only by the slope
        IlluminationStage stage = method.stage(HillshadeOptions.DEFAULTS.withZFactor(5));
        float[] before = illuminate(stage, dem, LIGHT);
        assertArrayEquals(before, illuminate(stage, new Dem(raised, dem.geometry()), LIGHT));
        // Not trivially constant: the real DEM has relief.
        assertTrue(spread(before) > 0.1, method + " spread " + spread(before));
    }

    @ParameterizedTest
    @EnumSource(value = HillshadeMethod.class, names = {"JDEM846", "HORN"})
    void rotatingTheDemAndTheAzimuthBy90DegreesRotatesTheResult(HillshadeMethod method) {
        Dem dem = TestDems.load(TestDems.VOLCANO); // square 10 m cells
        Dem turned = SyntheticDems.rotateClockwise(dem);
        IlluminationStage stage = method.stage(HillshadeOptions.DEFAULTS);
        for (double az : new double[] {320, 33.3, 180}) {
            float[] expected = SyntheticDems.rotateClockwise(
                    illuminate(stage, dem, new LightDirection(az, 25)), dem.width(), dem.height());
            float[] actual = illuminate(stage, turned, new LightDirection(az + 90, 25));
            int w = turned.width();
            int h = turned.height();
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    boolean corner = (r == 0 || r == h - 1) && (c == 0 || c == w - 1);
                    if (method == HillshadeMethod.HORN && corner) {
                        continue; // gdaldem's corner quirk is not rotation-symmetric (see HornIlluminationTest)
                    }
                    assertEquals(expected[r * w + c], actual[r * w + c], 1e-6,
                            method + " azimuth " + az + " at " + c + "," + r);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(HillshadeMethod.class)
    void noDataCellsAreNaNAndEveryOtherCellIsInRange(HillshadeMethod method) {
        Dem dem = TestDems.load(TestDems.LUXEMBOURG);
        for (double e : new double[] {-5, 0, 0.01, 25, 89.99, 90}) {
            float[] out = illuminate(method.stage(HillshadeOptions.DEFAULTS), dem, new LightDirection(123, e));
            for (int i = 0; i < out.length; i++) {
                if (Float.isNaN(dem.backingArray()[i])) {
                    assertTrue(Float.isNaN(out[i]));
                } else {
                    assertTrue(out[i] >= -1 && out[i] <= 1, method + " elevation " + e + ": " + out[i]);
                }
            }
        }
    }

    private static double spread(float[] a) {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (float v : a) {
            if (!Float.isNaN(v)) {
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
        }
        return max - min;
    }
}
