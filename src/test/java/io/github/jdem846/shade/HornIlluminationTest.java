package io.github.jdem846.shade;

import static io.github.jdem846.shade.ShadeTestSupport.illuminate;
import static io.github.jdem846.shade.ShadeTestSupport.planeCosine;
import static io.github.jdem846.testing.SyntheticDems.surface;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.SyntheticDems;
import org.junit.jupiter.api.Test;

/** Horn and multidirectional against hand-worked planes, including gdaldem's edge and no-data rules. */
class HornIlluminationTest {

    private static final IlluminationStage HORN = new HornIllumination(HillshadeOptions.DEFAULTS);
    private static final IlluminationStage MULTI = new MultidirectionalIllumination(HillshadeOptions.DEFAULTS);

    @Test
    void hornGivesThePlanesCosineEverywhereButTheFourCorners() {
        double a = 0.375;
        double b = -0.25;
        int w = 6;
        int h = 5;
        Dem dem = surface(w, h, 2, (x, y) -> 100 + a * x + b * y);
        float[] out = illuminate(HORN, dem, new LightDirection(320, 25));
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                boolean corner = (r == 0 || r == h - 1) && (c == 0 || c == w - 1);
                // gdaldem's first and last rows repeat the edge column at the corners instead of extrapolating it,
                // so Horn's east–west difference there covers one cell instead of two: half the slope.
                double expected = corner ? planeCosine(a / 2, b, 320, 25) : planeCosine(a, b, 320, 25);
                assertEquals(expected, out[r * w + c], 1e-6, "cell " + c + "," + r);
            }
        }
    }

    @Test
    void hornReplacesNoDataNeighboursByTheCentreLikeGdaldem() {
        // A 3×3 plane rising 1 m per 1 m eastward with its east column missing: the window becomes
        // w2 = w5 = w8 = centre, so ∂z/∂east = (4·c − 4·(c − 1)) / 8 = 0.5: half the slope.
        float[] v = {0, 1, Float.NaN, 0, 1, Float.NaN, 0, 1, Float.NaN};
        Dem dem = SyntheticDems.metric(3, 3, 1, v);
        float[] out = illuminate(HORN, dem, new LightDirection(270, 30));
        assertEquals(planeCosine(0.5, 0, 270, 30), out[4], 1e-6);
        assertEquals(Float.NaN, out[2]);
    }

    @Test
    void hornUsesTheLightAsGivenBelowTheHorizon() {
        // gdaldem does not special-case a negative altitude: a 20° slope facing a sun at −5° gets cos 75°.
        double tan20 = Math.tan(Math.toRadians(20));
        Dem dem = surface(5, 5, 10, (x, y) -> tan20 * x);
        float[] out = illuminate(HORN, dem, new LightDirection(270, -5));
        assertEquals(Math.cos(Math.toRadians(75)), out[2 * 5 + 2], 1e-6);
    }

    @Test
    void multidirectionalOnFlatGroundIsSinAltitudeAndOnAPlaneTheWeightedMean() {
        Dem flat = surface(4, 4, 30, (x, y) -> 50);
        for (float d : illuminate(MULTI, flat, new LightDirection(0, 40))) {
            assertEquals((float) Math.sin(Math.toRadians(40)), d, 0f);
        }
        // A plane facing due west (rising eastward, slope 1). gdaldem weights the azimuth az by cos²(A − az), A = 270°
        // the compass direction the slope faces: W225 = 1/2, W270 = 1, W315 = 1/2, W360 = 0 (sum 2). The cosines
        // by hand: normal (−1, 0, 1)/√2, light at az: (cos e·sin az, cos e·cos az, sin e).
        double e = Math.toRadians(30);
        double c225 = Math.max(0, (-Math.cos(e) * Math.sin(Math.toRadians(225)) + Math.sin(e)) / Math.sqrt(2));
        double c270 = Math.max(0, (Math.cos(e) + Math.sin(e)) / Math.sqrt(2));
        double c315 = Math.max(0, (-Math.cos(e) * Math.sin(Math.toRadians(315)) + Math.sin(e)) / Math.sqrt(2));
        double expected = (0.5 * c225 + 1.0 * c270 + 0.5 * c315) / 2; // = 0.876246
        Dem plane = surface(5, 5, 1, (x, y) -> x);
        float[] out = illuminate(MULTI, plane, new LightDirection(123 /* ignored */, 30));
        for (int r = 1; r < 4; r++) {
            for (int c = 0; c < 5; c++) {
                assertEquals(expected, out[r * 5 + c], 1e-6, "cell " + c + "," + r);
            }
        }
    }
}
