package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.TestDems;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.BiFunction;
import org.junit.jupiter.api.Test;

/**
 * The interior fast paths of the three hillshade stages give bit for bit the floats of the general path (the same
 * stage with the fast path switched off, where every cell goes through the edge and no-data rules), on the real
 * test DEMs and on random DEMs with no-data holes, infinities, a geographic grid reaching a pole, zero cell sizes,
 * huge z-factors and lights above, on and below the horizon.
 */
class InteriorFastPathTest {

    private static final List<BiFunction<HillshadeOptions, Boolean, IlluminationStage>> STAGES = List.of(
            JDem846Illumination::new, HornIllumination::new, MultidirectionalIllumination::new);

    @Test
    void realDemsGiveIdenticalBits() {
        List<LightDirection> lights = List.of(new LightDirection(320, 25), new LightDirection(315, 45),
                new LightDirection(67, 8), new LightDirection(200, -5));
        int compared = 0;
        for (String name : List.of(TestDems.BIG_TUJUNGA, TestDems.JACKSBORO, TestDems.LUXEMBOURG,
                TestDems.VANCOUVER, TestDems.VOLCANO)) {
            Dem dem = TestDems.load(name);
            for (HillshadeOptions options : List.of(HillshadeOptions.DEFAULTS,
                    HillshadeOptions.DEFAULTS.withZFactor(3).withHorizontalScale(111120))) {
                for (LightDirection light : lights) {
                    compared += assertSameBits(dem, options, light, name);
                }
            }
        }
        assertTrue(compared > 1_000_000, "compared " + compared + " cells");
    }

    @Test
    void randomDemsWithHolesAndExtremesGiveIdenticalBits() {
        SplittableRandom random = new SplittableRandom(846);
        for (int trial = 0; trial < 40; trial++) {
            int w = 1 + random.nextInt(40);
            int h = 1 + random.nextInt(40);
            float[] v = new float[w * h];
            double noDataShare = random.nextDouble() * 0.4;
            for (int i = 0; i < v.length; i++) {
                double u = random.nextDouble();
                if (u < noDataShare) {
                    v[i] = Float.NaN;
                } else if (u < noDataShare + 0.01) {
                    v[i] = random.nextBoolean() ? Float.POSITIVE_INFINITY : -Float.MAX_VALUE;
                } else if (u < noDataShare + 0.2) {
                    v[i] = 100f; // flat patches: zero gradients, zero cross-product components
                } else {
                    v[i] = (float) (random.nextDouble() * 2000 - 500);
                }
            }
            GridGeometry geometry = switch (trial % 3) {
                case 0 -> GridGeometry.metric(w, h, 0.5 + random.nextDouble() * 100);
                // Geographic up to the north pole: the top row's east-west spacing is 0.
                case 1 -> new GridGeometry(w, h, 10, 90, 0.5, 0.5, CrsInfo.geographic("WGS 84", 4326,
                        Ellipsoid.WGS84), PixelAnchor.CENTER);
                default -> new GridGeometry(w, h, 0, 0, 1e-3, 1e-3, CrsInfo.UNKNOWN, PixelAnchor.CORNER);
            };
            Dem dem = new Dem(v, geometry, Double.NaN);
            double z = switch (trial % 4) {
                case 0 -> 1;
                case 1 -> 1e-3;
                case 2 -> 37.5;
                default -> HillshadeOptions.MAX_HEIGHT_FACTOR;
            };
            HillshadeOptions options = HillshadeOptions.DEFAULTS.withZFactor(z);
            LightDirection light = new LightDirection(random.nextDouble() * 720 - 360,
                    random.nextDouble() * 180 - 90);
            assertSameBits(dem, options, light, "trial " + trial);
        }
    }

    /** Compares fast and general path of every stage over the whole DEM and a sub-rectangle; returns cells. */
    private static int assertSameBits(Dem dem, HillshadeOptions options, LightDirection light, String what) {
        int cells = 0;
        for (BiFunction<HillshadeOptions, Boolean, IlluminationStage> make : STAGES) {
            IlluminationStage fast = make.apply(options, true);
            IlluminationStage general = make.apply(options, false);
            int w = dem.width();
            int h = dem.height();
            float[] a = new float[w * h];
            float[] b = new float[w * h];
            fast.illuminate(dem, light, 0, 0, w, h, a);
            general.illuminate(dem, light, 0, 0, w, h, b);
            for (int i = 0; i < a.length; i++) {
                if (Float.floatToRawIntBits(a[i]) != Float.floatToRawIntBits(b[i])) {
                    assertEquals(b[i], a[i], fast.getClass().getSimpleName() + " on " + what + " at column "
                            + i % w + ", row " + i / w + " (" + light + ", z " + options.zFactor() + ")");
                    assertEquals(Float.floatToRawIntBits(b[i]), Float.floatToRawIntBits(a[i]), "sign of zero");
                }
            }
            cells += a.length;
        }
        return cells;
    }
}
