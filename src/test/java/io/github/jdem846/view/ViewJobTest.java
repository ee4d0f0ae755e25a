package io.github.jdem846.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** A view of a real DEM file, from file to pixels. */
class ViewJobTest {

    private static final Path TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    private static final Path MAUNGAWHAU = Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif");

    /** The view of Big Tujunga with cast shadows is the same picture on one thread and on three. */
    @Test
    void aFileViewIsIdenticalForAnyThreadCount() throws Exception {
        ReliefJob relief = ReliefJob.of(TUJUNGA).withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP));
        Camera camera = new Camera(200, 35, 0, 40, 240, 160);
        ViewOptions options = ViewOptions.defaults().withExaggeration(1.5);
        RenderedView one = new ViewJob(relief.withExecution(new RenderSettings(1, 64)), camera, options)
                .run(JobListener.NONE);
        RenderedView three = new ViewJob(relief.withExecution(new RenderSettings(3, 128)), camera, options)
                .run(JobListener.NONE);
        assertEquals(240, one.width());
        assertEquals(160, one.height());
        assertArrayEquals(one.argb(), three.argb());
    }

    /**
     * The terrain is read box-averaged to about one cell per picture pixel, and the relief at most 4 texture pixels
     * per picture pixel, or enlarged up to one per pixel for a small DEM.
     */
    @Test
    void onlyWhatThePictureShowsIsComputed() {
        Camera small = Camera.defaults().withSize(300, 200);
        assertEquals(1, ViewJob.meshDecimation(300, 200, small));
        assertEquals(2, ViewJob.meshDecimation(600, 400, small));
        assertEquals(4, ViewJob.meshDecimation(1000, 800, small));
        assertEquals(OutputSize.FULL, ViewJob.textureSize(600, 400, small));
        assertEquals(0.5, ViewJob.textureSize(1200, 800, small).scale(), 1e-12);
        assertEquals(2, ViewJob.textureSize(150, 100, small).scale(), 1e-12);
        assertEquals(ViewJob.MAX_UPSAMPLING, ViewJob.textureSize(10, 10, small).scale(), 1e-12);
    }

    /** A gray product is draped as gray: a hillshade's view has only gray pixels where the terrain is. */
    @Test
    void aHillshadeIsDrapedAsGray() throws Exception {
        ReliefJob hillshade = ReliefJob.of(TUJUNGA).withProduct(io.github.jdem846.job.Product.HILLSHADE);
        RenderedView view = new ViewJob(hillshade, new Camera(180, 60, 0, 40, 120, 80), ViewOptions.defaults())
                .run(JobListener.NONE);
        int centre = view.argb()[40 * 120 + 60];
        assertEquals((centre >> 16) & 255, centre & 255, Integer.toHexString(centre));
        assertEquals((centre >> 8) & 255, centre & 255, Integer.toHexString(centre));
    }

    /** Globe mode needs latitudes and longitudes: a CRS known only by its GeoKeys (NZTM here) is refused. */
    @Test
    void aGlobeOfAGridWithoutLatitudesIsRefused() {
        ViewJob job = new ViewJob(ReliefJob.of(DemInput.of(MAUNGAWHAU)), Camera.defaults().withSize(60, 40),
                ViewOptions.defaults().withGlobe(true));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> job.run(JobListener.NONE));
        assertEquals(true, e.getMessage().contains("latitudes and longitudes"), e.getMessage());
    }
}
