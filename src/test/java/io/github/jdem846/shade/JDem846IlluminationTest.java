package io.github.jdem846.shade;

import static io.github.jdem846.shade.ShadeTestSupport.illuminate;
import static io.github.jdem846.shade.ShadeTestSupport.planeCosine;
import static io.github.jdem846.testing.SyntheticDems.surface;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.Random;
import org.junit.jupiter.api.Test;

class JDem846IlluminationTest {

    private static final HillshadeOptions TRUE_HEIGHTS = HillshadeOptions.DEFAULTS.withLightMultiple(1);
    private static final IlluminationStage STAGE = new JDem846Illumination(TRUE_HEIGHTS);

    @Test
    void flatTerrainGivesExactlySinElevationEverywhereIncludingEdgesAndNextToHoles() {
        float[] v = new float[9 * 7];
        java.util.Arrays.fill(v, 123.25f);
        v[3 * 9 + 4] = Float.NaN;
        Dem dem = SyntheticDems.metric(9, 7, 30, v);
        for (double e : new double[] {0, 0.01, 25, 45, 89.99, 90}) {
            for (double az : new double[] {0, 90, 180, 270, 320, 33.3}) {
                float[] out = illuminate(new JDem846Illumination(HillshadeOptions.DEFAULTS), dem,
                        new LightDirection(az, e));
                for (int i = 0; i < out.length; i++) {
                    if (i == 3 * 9 + 4) {
                        assertTrue(Float.isNaN(out[i]), "a no-data cell stays no-data");
                    } else {
                        assertEquals((float) Math.sin(Math.toRadians(e)), out[i], 0.0f,
                                "cell " + i + ", elevation " + e + ", azimuth " + az);
                    }
                }
            }
        }
    }

    @Test
    void planeTiltedTowardTheSunGivesTheCosineWorkedByHand() {
        // A plane rising 20° toward the east faces west; the sun in the west (270°) at 30°. The normal leans 20°
        // from the zenith toward the sun, so the angle of incidence is 90° − 30° − 20° = 40°: cos 40° = 0.766044.
        double tan20 = Math.tan(Math.toRadians(20));
        Dem dem = surface(6, 5, 30, (x, y) -> 500 + tan20 * x);
        float[] out = illuminate(STAGE, dem, new LightDirection(270, 30));
        for (float d : out) {
            assertEquals(0.766044, d, 1e-6);
        }
        // With the original's light multiple 0.75 the normals see a slope of atan(0.75·tan 20°) = 15.268°, so the
        // incidence is 90° − 30° − 15.268° = 44.732° and its cosine 0.710412.
        float[] toned = illuminate(new JDem846Illumination(HillshadeOptions.DEFAULTS), dem,
                new LightDirection(270, 30));
        for (float d : toned) {
            assertEquals(0.710412, d, 1e-6);
        }
        // The sun behind the same plane (east, 90°): incidence 90° − 30° + 20° = 80°, cos 80° = 0.173648.
        for (float d : illuminate(STAGE, dem, new LightDirection(90, 30))) {
            assertEquals(0.173648, d, 1e-6);
        }
    }

    @Test
    void anyPlaneGivesItsAnalyticCosineInEveryCellIncludingEdges() {
        // Dyadic slopes, so that every height is exact in float32 for each cell size below.
        double a = 0.375;
        double b = -0.8125;
        for (double cell : new double[] {0.5, 30, 111_320}) { // tiny cells, SRTM, a 1° cell in metres
            Dem dem = surface(7, 6, cell, (x, y) -> 1000 + a * x + b * y);
            for (double[] light : new double[][] {{320, 25}, {33.3, 10}, {200, 70}, {90, 0.01}}) {
                float[] out = illuminate(STAGE, dem, new LightDirection(light[0], light[1]));
                double expected = planeCosine(a, b, light[0], light[1]);
                for (float d : out) {
                    assertEquals(expected, d, 1e-6, "cell size " + cell + ", light " + light[0] + "/" + light[1]);
                }
            }
        }
    }

    @Test
    void aNoDataHoleInATiltedPlaneMakesNoRing() {
        double a = 0.5;
        double b = 0.25;
        Dem dem = surface(12, 10, 10, (x, y) -> {
            boolean hole = x > 40 && x < 80 && y > 30 && y < 60;
            return hole ? Double.NaN : a * x + b * y;
        });
        LightDirection light = new LightDirection(320, 25);
        float[] out = illuminate(STAGE, dem, light);
        double expected = planeCosine(a, b, 320, 25);
        int holes = 0;
        for (int i = 0; i < out.length; i++) {
            if (Float.isNaN(dem.backingArray()[i])) {
                holes++;
                assertTrue(Float.isNaN(out[i]));
            } else {
                assertEquals(expected, out[i], 2e-6, "cell " + i + " (next to the hole?)");
            }
        }
        assertEquals(12, holes);
        // Why not the original's "substitute the centre value": next to the hole it would flatten one side of the
        // cell and visibly change its light (a ring), e.g. for a cell whose east neighbour is missing:
        double[] n = new double[3];
        JDem846Illumination.vertexNormal(10, 10, 0 /* E := C */, -a * 10, b * 10, -b * 10, n);
        LightDirection l = light;
        double substituted = n[0] * l.east() + n[1] * l.north() + n[2] * l.up();
        assertTrue(Math.abs(substituted - expected) > 0.02, "centre substitution would make a ring: "
                + substituted + " vs " + expected);
    }

    @Test
    void isolatedCellsAndOneCellWideGridsGetZeroSlopeAlongTheMissingAxis() {
        // A single cell: no neighbour at all → flat.
        Dem single = SyntheticDems.metric(1, 1, 30, new float[] {42});
        assertEquals((float) Math.sin(Math.toRadians(25)), illuminate(STAGE, single, new LightDirection(0, 25))[0]);
        // One row rising 1 m per 1 m eastward: only the east-west slope is known; N–S gets zero slope.
        Dem row = SyntheticDems.metric(4, 1, 1, new float[] {0, 1, 2, 3});
        for (float d : illuminate(STAGE, row, new LightDirection(270, 30))) {
            assertEquals(planeCosine(1, 0, 270, 30), d, 1e-6);
        }
    }

    @Test
    void belowTheHorizonNothingIsLit() {
        Dem dem = TestDems.load(TestDems.VOLCANO);
        for (double e : new double[] {-5, -0.01, 0, -90}) {
            float[] out = illuminate(STAGE, dem, new LightDirection(135, e));
            int dark = 0;
            for (float d : out) {
                assertTrue(d <= 0, "elevation " + e + " lit a cell: " + d);
                dark += d < -0.05 ? 1 : 0;
            }
            if (e < -1) {
                assertTrue(dark > 0, "slopes facing away still darken");
            }
        }
        // Flat ground under a sun 5° below the horizon: sin(−5°).
        Dem flat = surface(3, 3, 10, (x, y) -> 7);
        for (float d : illuminate(STAGE, flat, new LightDirection(10, -5))) {
            assertEquals((float) Math.sin(Math.toRadians(-5)), d, 0f);
        }
        // Just above the horizon a slope facing the sun is lit: 0.01° over a 20° slope toward the sun.
        double tan20 = Math.tan(Math.toRadians(20));
        Dem slope = surface(4, 4, 30, (x, y) -> tan20 * x);
        for (float d : illuminate(STAGE, slope, new LightDirection(270, 0.01))) {
            assertEquals(Math.cos(Math.toRadians(90 - 20 - 0.01)), d, 1e-6);
        }
    }

    @Test
    void equivalentAzimuthsGiveIdenticalResults() {
        Dem dem = TestDems.load(TestDems.VOLCANO);
        float[] north = illuminate(STAGE, dem, new LightDirection(0, 30));
        assertArrayEquals(north, illuminate(STAGE, dem, new LightDirection(360, 30)));
        assertArrayEquals(north, illuminate(STAGE, dem, new LightDirection(-720, 30)));
        assertArrayEquals(north, illuminate(STAGE, dem, new LightDirection(-0.0, 30)));
        assertArrayEquals(illuminate(STAGE, dem, new LightDirection(280, 30)),
                illuminate(STAGE, dem, new LightDirection(1e6, 30)));
        // And different azimuths do differ (the comparison can fail).
        float[] east = illuminate(STAGE, dem, new LightDirection(90, 30));
        assertTrue(maxAbsDiff(north, east) > 0.1);
    }

    @Test
    void zenithLightGivesTheCosineOfTheSlope() {
        Dem dem = surface(5, 5, 10, (x, y) -> 0.3 * x - 0.4 * y);
        for (float d : illuminate(STAGE, dem, new LightDirection(123, 90))) {
            assertEquals(1 / Math.sqrt(1 + 0.09 + 0.16), d, 1e-6); // cos of a 0.5 gradient: 1/√1.25
        }
        for (float d : illuminate(STAGE, dem, new LightDirection(123, 89.99))) {
            assertEquals(planeCosine(0.3, -0.4, 123, 89.99), d, 1e-6);
        }
    }

    @Test
    void zFactorIsTheSameAsScalingTheHeights() {
        Dem dem = TestDems.load(TestDems.VOLCANO);
        float[] doubled = dem.backingArray().clone();
        for (int i = 0; i < doubled.length; i++) {
            doubled[i] *= 2;
        }
        Dem twice = new Dem(doubled, dem.geometry());
        LightDirection light = new LightDirection(320, 25);
        float[] z2 = illuminate(new JDem846Illumination(HillshadeOptions.DEFAULTS.withZFactor(2)), dem, light);
        assertArrayEquals(illuminate(new JDem846Illumination(HillshadeOptions.DEFAULTS), twice, light), z2);
        assertTrue(maxAbsDiff(z2, illuminate(new JDem846Illumination(HillshadeOptions.DEFAULTS), dem, light)) > 0.05);
        // Light multiple 0 ignores the relief: flat light everywhere.
        for (float d : illuminate(new JDem846Illumination(TRUE_HEIGHTS.withLightMultiple(0)), dem, light)) {
            assertEquals((float) Math.sin(Math.toRadians(25)), d, 0f);
        }
    }

    @Test
    void float32ExtremesNeverGiveNaNOrInfinity() {
        float big = 3.0e38f;
        float[] v = new float[6 * 5];
        Random rnd = new Random(846);
        for (int i = 0; i < v.length; i++) {
            v[i] = switch (rnd.nextInt(4)) {
                case 0 -> big;
                case 1 -> -big;
                case 2 -> Float.MAX_VALUE;
                default -> -Float.MAX_VALUE;
            };
        }
        for (double cell : new double[] {0.5, 30}) {
            Dem dem = SyntheticDems.metric(6, 5, cell, v.clone());
            for (HillshadeMethod m : HillshadeMethod.values()) {
                for (double z : new double[] {1, HillshadeOptions.MAX_HEIGHT_FACTOR}) {
                    float[] out = illuminate(m.stage(HillshadeOptions.DEFAULTS.withZFactor(z)
                            .withLightMultiple(HillshadeOptions.MAX_HEIGHT_FACTOR)), dem, new LightDirection(320, 25));
                    for (float d : out) {
                        assertTrue(d >= -1 && d <= 1, m + ", z " + z + ": " + d);
                    }
                }
            }
        }
    }

    @Test
    void geographicRowsAtThePoleGiveNoNaN() {
        // 3″ cells from 90°N down to 89.9°N (cell width → 0 m at the top row), and a grid whose top row is centred
        // exactly on the pole (width 0).
        for (double north : new double[] {90.0, 90.0 + 0.05}) {
            double cell = north == 90.0 ? 1.0 / 1200 : 0.1;
            int rows = (int) Math.round(0.1 / cell);
            GridGeometry g = new GridGeometry(8, rows, 10, north, cell, cell,
                    CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
            float[] v = new float[8 * rows];
            Random rnd = new Random(1);
            for (int i = 0; i < v.length; i++) {
                v[i] = 100 + rnd.nextInt(50);
            }
            Dem dem = new Dem(v, g);
            for (HillshadeMethod m : HillshadeMethod.values()) {
                for (float d : illuminate(m.stage(HillshadeOptions.DEFAULTS), dem, new LightDirection(30, 20))) {
                    assertTrue(d >= -1 && d <= 1, m + " at the pole: " + d);
                }
            }
            // Flat ground at the pole is still flat.
            float[] flat = new float[8 * rows];
            java.util.Arrays.fill(flat, 5);
            for (float d : illuminate(STAGE, new Dem(flat, g), new LightDirection(30, 20))) {
                assertEquals((float) Math.sin(Math.toRadians(20)), d, 0f);
            }
        }
    }

    @Test
    void geographicCellsUseTheRowsMetricSize() {
        // 1° cells at 40–46°N. Each row rises 1 m per metre eastward, measured with that row's own cell width, and
        // column 2 is at height 0 in every row: there the slope is exactly 45° toward the west-facing light, so
        // the cosine is 1, although a degree of longitude shrinks by 12 % across the grid.
        int w = 5;
        int h = 6;
        GridGeometry g = new GridGeometry(w, h, 0, 46, 1, 1, CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84),
                PixelAnchor.CORNER);
        float[] v = new float[w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                v[r * w + c] = (float) ((c - 2) * g.cellWidthMeters(r));
            }
        }
        Dem dem = new Dem(v, g);
        float[] metric = illuminate(STAGE, dem, new LightDirection(270, 45));
        float[] degrees = illuminate(new JDem846Illumination(TRUE_HEIGHTS.withHorizontalScale(111120)), dem,
                new LightDirection(270, 45));
        for (int r = 0; r < h; r++) {
            assertEquals(1.0, metric[r * w + 2], 1e-6, "row " + r);
            // gdaldem's -s 111120 takes every degree as 111120 m: the slope reads too gentle, the light too low.
            assertTrue(degrees[r * w + 2] < 0.995, "row " + r + ": " + degrees[r * w + 2]);
        }
    }

    @Test
    void badRectanglesAreRejectedWithAMessage() {
        Dem dem = SyntheticDems.metric(4, 3, 1, new float[12]);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> STAGE.illuminate(dem, new LightDirection(0, 45), 2, 0, 3, 3, new float[9]));
        assertTrue(e.getMessage().contains("inside the 4×3 DEM"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> STAGE.illuminate(dem, new LightDirection(0, 45), 0, 0, 4, 3, new float[5]));
        assertTrue(e.getMessage().contains("needs 12"), e.getMessage());
    }

    static double maxAbsDiff(float[] a, float[] b) {
        double m = 0;
        for (int i = 0; i < a.length; i++) {
            m = Math.max(m, Math.abs(a[i] - b[i]));
        }
        return m;
    }
}
