package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.Window;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Pictures larger than their DEM, read from real files: the same pixels whatever the threads and the window. */
class EnlargedPictureTest {

    private static final Path LUXEMBOURG = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif");
    private static final Path VOLCANO = Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif");

    @Test
    void theThreadCountAndTileSizeDoNotChangeAPixel() throws Exception {
        ReliefJob lux = ReliefJob.of(LUXEMBOURG).withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
                .withSun(Sun.fixed(135, 20)).withSize(OutputSize.width(650));
        int[] one = lux.withExecution(new RenderSettings(1, 64)).run(JobListener.NONE).argb();
        int[] two = lux.withExecution(new RenderSettings(2, 64)).run(JobListener.NONE).argb();
        int[] large = lux.withExecution(new RenderSettings(2, 1024)).run(JobListener.NONE).argb();
        assertArrayEquals(one, two);
        assertArrayEquals(one, large);
        long partial = java.util.Arrays.stream(one).map(p -> p >>> 24).filter(a -> a > 0 && a < 255).count();
        assertTrue(partial > 500, "anti-aliased border pixels: " + partial);
    }

    /**
     * A window of an enlarged picture reads three cells around it (the interpolation's two, the hillshade's one):
     * its pixels are those of the whole file's picture at the same scale.
     */
    @Test
    void aWindowOfAnEnlargedPictureIsThatPartOfTheWholePicture() throws Exception {
        ReliefJob hs = ReliefJob.of(VOLCANO).withProduct(Product.HILLSHADE)
                .withScene(Scene.defaults().withHillshade(HillshadeMethod.HORN)).withSize(OutputSize.scale(8))
                .withExecution(new RenderSettings(2, 64));
        ReliefResult whole = hs.run(JobListener.NONE);
        ReliefResult part = hs.withWindow(Window.cells(20, 30, 20, 25)).run(JobListener.NONE);
        assertEquals(160, part.width());
        assertEquals(200, part.height());
        for (int r = 0; r < part.height(); r++) {
            for (int c = 0; c < part.width(); c++) {
                assertEquals(whole.gray()[(240 + r) * whole.width() + 160 + c], part.gray()[r * part.width() + c],
                        "pixel " + c + ", " + r);
            }
        }
    }
}
