package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import org.junit.jupiter.api.Test;

/** With a z-factor the cast shadows are those of the exaggerated terrain the hillshade shows. */
class ExaggeratedShadowsTest {

    private static final int N = 101;
    private static final double CELL = 10;

    /** Flat ground at 0 m with one spike of {@code h} metres in the middle. */
    private static Dem spike(float h) {
        float[] v = new float[N * N];
        v[(N / 2) * N + N / 2] = h;
        return new Dem(v, GridGeometry.metric(N, N, CELL));
    }

    /** Cells in shadow on the row of the spike, west of it (sun in the east). */
    private static int shadowLength(float[] mask) {
        int row = N / 2;
        int n = 0;
        for (int c = N / 2 - 1; c >= 0 && mask[row * N + c] > 0.5f; c--) {
            n++;
        }
        return n;
    }

    @Test
    void zFactorLengthensShadowsAsExaggeratedHeightsWould() throws InterruptedException {
        float h = 100;
        double e = 30;
        Scene base = Scene.defaults().withTint(null).withShadows(ShadowAlgorithm.SWEEP)
                .withLight(new LightDirection(90, e));
        for (double k : new double[] {0.5, 1, 2, 3}) {
            Scene scene = base.withHillshadeOptions(base.hillshadeOptions().withZFactor(k));
            float[] mask = new Renderer().shadows(spike(h), scene, RenderProgress.NONE);
            int expected = (int) Math.floor(k * h / Math.tan(Math.toRadians(e)) / CELL);
            assertEquals(expected, shadowLength(mask), 1, "z-factor " + k + ": shadow of a " + k * h + " m spike");
            float[] scaled = ShadowAlgorithm.SWEEP.compute(spike((float) (k * h)), new LightDirection(90, e),
                    ShadowOptions.DEFAULTS).backingArray();
            assertEquals(shadowLength(scaled), shadowLength(mask), "the same as tracing heights × " + k);
        }
    }

    @Test
    void scaledLightKeepsAzimuthAndScalesTheSlope() {
        LightDirection sun = new LightDirection(250, 20);
        for (double k : new double[] {1e-3, 0.5, 2, 10, 1e3}) {
            LightDirection s = sun.forHeightsScaledBy(k);
            assertEquals(250, s.azimuthDegrees());
            assertEquals(Math.tan(Math.toRadians(20)), k * Math.tan(Math.toRadians(s.elevationDegrees())), 1e-12);
        }
        assertSame(sun, sun.forHeightsScaledBy(1));
        LightDirection zenith = new LightDirection(10, 90);
        LightDirection night = new LightDirection(10, -3);
        assertSame(zenith, zenith.forHeightsScaledBy(5));
        assertSame(night, night.forHeightsScaledBy(5));
        assertThrows(IllegalArgumentException.class, () -> sun.forHeightsScaledBy(0));
        assertThrows(IllegalArgumentException.class, () -> sun.forHeightsScaledBy(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> sun.forHeightsScaledBy(Double.POSITIVE_INFINITY));
    }
}
