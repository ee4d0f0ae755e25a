package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import io.github.jdem846.raster.Upsampling;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.TestDems;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * An honest reference for enlarged pictures: a real 30 m DEM is averaged down by a factor f, enlarged back by f
 * with each {@link Upsampling}, and its hillshade and cast shadows are compared with those of the real DEM at full
 * resolution (docs/scale.md, "Pictures larger than the DEM").
 */
class UpsamplingAccuracyTest {

    private static final LightDirection SUN = new LightDirection(315, 25);
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withParallelism(2);

    /** Hillshade RMS (gray levels) and shadow disagreement of one method at one factor. */
    record Error(double hillshadeRms, double shadowDisagreement) {
    }

    private static final class Reference {
        final Dem full;
        final float[] illumination;
        final float[] shadows;

        Reference(Dem full) throws InterruptedException {
            this.full = full;
            this.illumination = illumination(full);
            this.shadows = shadows(full);
        }
    }

    private static float[] illumination(Dem dem) throws InterruptedException {
        return new Renderer(SETTINGS).illumination(dem, HillshadeMethod.HORN.stage(HillshadeOptions.DEFAULTS),
                LightField.uniform(SUN), RenderProgress.NONE);
    }

    private static float[] shadows(Dem dem) throws InterruptedException {
        Scene scene = Scene.defaults().withTint(null).withShadows(ShadowAlgorithm.SWEEP).withLight(SUN);
        return new Renderer(SETTINGS).shadows(dem, scene, RenderProgress.NONE);
    }

    /** The real DEM cropped to whole blocks of 8 cells. */
    private static Dem real(String name) {
        Dem dem = TestDems.load(name);
        return dem.crop(0, 0, dem.width() / 8 * 8, dem.height() / 8 * 8);
    }

    private static Error error(Reference ref, int factor, Upsampling method) throws InterruptedException {
        Dem full = ref.full;
        Dem coarse = DemResampler.resample(full, full.width() / factor, full.height() / factor);
        Dem back = DemResampler.resample(coarse, full.width(), full.height(), method);
        float[] light = illumination(back);
        float[] shade = shadows(back);
        int margin = 2 * factor + 2;
        double sum = 0;
        long n = 0;
        long differ = 0;
        for (int r = margin; r < full.height() - margin; r++) {
            for (int c = margin; c < full.width() - margin; c++) {
                int i = r * full.width() + c;
                double d = 255 * (light[i] - ref.illumination[i]);
                sum += d * d;
                n++;
                if (Math.abs(shade[i] - ref.shadows[i]) > 0.5f) {
                    differ++;
                }
            }
        }
        return new Error(Math.sqrt(sum / n), (double) differ / n);
    }

    /**
     * Measured (docs/scale.md): at 8× bilinear 36.4, Catmull-Rom 33.5, clamped 33.5, monotone 35.4 gray levels;
     * shadows differ on 10.0, 9.0, 9.0, 9.0 % of pixels, and with the default on 5.3 % at 4×, 2.4 % at 2×.
     */
    @Test
    void smoothSurfacesComeCloserToTheRealHillshadeAndShadowsConverge() throws InterruptedException {
        Reference ref = new Reference(real(TestDems.BIG_TUJUNGA));
        Error bilinear = error(ref, 8, Upsampling.BILINEAR);
        Error catmullRom = error(ref, 8, Upsampling.CATMULL_ROM);
        Error chosen = error(ref, 8, DemResampler.DEFAULT_UPSAMPLING);
        assertTrue(chosen.hillshadeRms() < 0.95 * bilinear.hillshadeRms(), chosen + " vs " + bilinear);
        assertTrue(chosen.hillshadeRms() < 1.01 * catmullRom.hillshadeRms(), chosen + " vs " + catmullRom);
        assertTrue(chosen.shadowDisagreement() < bilinear.shadowDisagreement(), chosen + " vs " + bilinear);
        double previous = chosen.shadowDisagreement();
        for (int f : new int[] {4, 2}) {
            Error e = error(ref, f, DemResampler.DEFAULT_UPSAMPLING);
            assertTrue(e.shadowDisagreement() < 0.75 * previous, f + "×: " + e + ", twice coarser: " + previous);
            previous = e.shadowDisagreement();
        }
        assertTrue(previous < 0.03, "2×: shadows differ on " + previous);
    }

    /**
     * Prints the table of docs/scale.md: every method at 2×, 4× and 8× on two real DEMs.
     *
     * @param args none
     * @throws InterruptedException never (no interrupt)
     */
    public static void main(String[] args) throws InterruptedException {
        for (String name : new String[] {TestDems.BIG_TUJUNGA, TestDems.JACKSBORO}) {
            Reference ref = new Reference(real(name));
            for (int f : new int[] {2, 4, 8}) {
                for (Upsampling m : Upsampling.values()) {
                    Error e = error(ref, f, m);
                    System.out.printf(Locale.ROOT, "%s %d× %-15s hillshade RMS %.2f gray levels, shadows differ"
                            + " on %.2f %% of pixels%n", name, f, m, e.hillshadeRms(), 100 * e.shadowDisagreement());
                }
            }
        }
    }
}
