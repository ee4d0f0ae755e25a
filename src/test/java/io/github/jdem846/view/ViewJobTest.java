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
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayStyle;
import io.github.jdem846.raster.GridGeometry;
import java.awt.Color;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;

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

    /**
     * An overlay is drawn onto the relief before it is draped: a yellow line in the DEM's CRS down the centres of
     * column 260 of Big Tujunga, seen straight down (north up) over the window of columns 200 … 319 and rows 150 …
     * 229 on the flattened terrain, from the distance where the window's rows fill the picture's, lands in column
     * 60 of the picture (±1) on every row inside; seen obliquely on the exaggerated terrain it is still drawn.
     */
    @Test
    void anOverlayLineIsDrapedWhereAFlatViewPredicts() throws Exception {
        GridGeometry g = DemReader.inspect(io.github.jdem846.io.DemInput.of(TUJUNGA)).geometry();
        double x = g.originX() + 260.5 * g.cellWidth();
        double north = g.originY() - 100 * g.cellHeight();
        double south = g.originY() - 300 * g.cellHeight();
        Overlay line = new Overlay("line", List.of(new GeometryFactory().createLineString(new Coordinate[] {
            new Coordinate(x, north), new Coordinate(x, south)})), null,
                new OverlayStyle(Color.YELLOW, 1, null, 3));
        ReliefJob relief = ReliefJob.of(TUJUNGA).withWindow(Window.cells(200, 150, 120, 80));
        double fov = 40;
        double distance = 80 * g.cellHeight() / 2 / Math.tan(Math.toRadians(fov / 2));
        RenderedView down = new ViewJob(relief, new Camera(180, 90, distance, fov, 120, 80),
                ViewOptions.defaults().withExaggeration(1e-9)).withOverlays(List.of(line)).run(JobListener.NONE);
        for (int r = 1; r < 79; r++) {
            int best = -1;
            int bestScore = -1;
            for (int c = 0; c < 120; c++) {
                int score = yellowness(down.argb()[r * 120 + c]);
                if (score > bestScore) {
                    bestScore = score;
                    best = c;
                }
            }
            assertEquals(60, best, 1, "row " + r + ": the line's column");
            assertEquals(true, bestScore > 150, "row " + r + ": the line is yellow, " + bestScore);
        }
        RenderedView oblique = new ViewJob(relief, new Camera(200, 35, 0, 40, 240, 160),
                ViewOptions.defaults().withExaggeration(1.5)).withOverlays(List.of(line)).run(JobListener.NONE);
        RenderedView plain = new ViewJob(relief, new Camera(200, 35, 0, 40, 240, 160),
                ViewOptions.defaults().withExaggeration(1.5)).run(JobListener.NONE);
        long yellow = java.util.Arrays.stream(oblique.argb()).filter(c -> yellowness(c) > 60).count();
        long yellowBefore = java.util.Arrays.stream(plain.argb()).filter(c -> yellowness(c) > 60).count();
        assertEquals(true, yellow > yellowBefore + 40, "yellow pixels " + yellow + ", without the overlay "
                + yellowBefore);
    }

    /** How yellow a colour is: red and green above blue. */
    private static int yellowness(int argb) {
        int r = (argb >> 16) & 255;
        int g = (argb >> 8) & 255;
        int b = argb & 255;
        return Math.min(r, g) - b;
    }
}
