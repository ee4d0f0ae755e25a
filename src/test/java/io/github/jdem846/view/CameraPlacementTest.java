package io.github.jdem846.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.RenderedRelief;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * Cameras placed by position and look-at point, and cameras among the terrain (near-plane clipping), against
 * pictures predicted independently: the usual look-at construction and pinhole equations written out here, and rays
 * marched through the DEM.
 */
class CameraPlacementTest {

    private static final int GROUND = 0xFF20A040;

    /** A flat 41 × 41 grid of 40 m cells with a 200 m spike at its centre cell (20, 20), textured gray, the spike red. */
    private static Dem spike() {
        int n = 41;
        float[] heights = new float[n * n];
        heights[20 * n + 20] = 200;
        return new Dem(heights, GridGeometry.metric(n, n, 40));
    }

    private static RenderedRelief spikeTexture(Dem dem) {
        int n = dem.width();
        int[] texture = new int[n * n];
        Arrays.fill(texture, 0xFF808080);
        texture[20 * n + 20] = 0xFFFF0000;
        return new RenderedRelief(n, n, texture, dem.geometry());
    }

    /**
     * The camera of azimuth 200°, elevation 30°, 1000 m from the centre (cell (20, 20) at x = y = 820 m on the
     * metric grid, height 100 m: the middle of 0 … 200 m) stands at centre + 1000 (sin 200° cos 30°, cos 200°
     * cos 30°, sin 30°); given by that position and the centre as look-at point, it draws the same picture.
     */
    @Test
    void aLookAtCameraEqualToAnAzimuthElevationOneDrawsTheSamePicture() throws Exception {
        Dem dem = spike();
        RenderedRelief texture = spikeTexture(dem);
        double az = Math.toRadians(200);
        double el = Math.toRadians(30);
        LookAt at = new LookAt(820 + 1000 * Math.sin(az) * Math.cos(el), 820 + 1000 * Math.cos(az) * Math.cos(el),
                100 + 1000 * Math.sin(el), 820, 820, 100);
        PerspectiveRenderer renderer = new PerspectiveRenderer(new RenderSettings(2, 64));
        int[] byDirection = renderer.render(dem, texture, new Camera(200, 30, 1000, 50, 400, 300),
                ViewOptions.defaults(), RenderProgress.NONE).argb();
        int[] byPosition = renderer.render(dem, texture, Camera.lookingAt(at, 50, 400, 300),
                ViewOptions.defaults(), RenderProgress.NONE).argb();
        int differing = 0;
        for (int i = 0; i < byDirection.length; i++) {
            differing += byDirection[i] != byPosition[i] ? 1 : 0;
        }
        assertTrue(differing <= 5, differing + " pixels differ (rounding of the camera's position on edges)");
        // the look-at point's height from the terrain: at the centre cell, 200 m (the spike's top)
        int[] onTerrain = renderer.render(dem, texture, Camera.lookingAt(LookAt.onTerrain(at.x(), at.y(), at.z(),
                820, 820), 50, 400, 300), ViewOptions.defaults(), RenderProgress.NONE).argb();
        int[] top = topmostRed(onTerrain, 400, 300);
        assertEquals(200, top[0] + 0.5, 1, "the spike's top column is the picture's centre");
        assertTrue(top[1] + 0.5 >= 150 && top[1] + 0.5 <= 153, "the spike's top row is the picture's centre (the pyramid's point covers a pixel centre 1 to 3 rows below its apex): "
                + top[1]);
    }

    /**
     * A camera at (300, 250, 350) looking at (900, 1000, 0) on the spike's grid: the spike's top (820, 820, 200)
     * projected by the camera frame built here (forward to the target, right = forward × up, up' = right ×
     * forward) lands in the column of its topmost red pixel (±1) and 0 to 2 rows above it.
     */
    @Test
    void aSpikeLandsWhereTheLookAtCameraPredicts() throws Exception {
        Dem dem = spike();
        double[] eye = {300, 250, 350};
        double[] target = {900, 1000, 0};
        RenderedView view = new PerspectiveRenderer(new RenderSettings(3, 64)).render(dem, spikeTexture(dem),
                Camera.lookingAt(new LookAt(eye[0], eye[1], eye[2], target[0], target[1], target[2]), 50, 400, 300),
                ViewOptions.defaults(), RenderProgress.NONE);
        double[] forward = normalize(minus(target, eye));
        double[] right = normalize(cross(forward, new double[] {0, 0, 1}));
        double[] up = cross(right, forward);
        double f = 150 / Math.tan(Math.toRadians(25));
        double[] p = minus(new double[] {820, 820, 200}, eye);
        double sx = 200 + f * dot(p, right) / dot(p, forward);
        double sy = 150 - f * dot(p, up) / dot(p, forward);
        int[] top = topmostRed(view.argb(), 400, 300);
        int column = top[0];
        int topmost = top[1];
        assertTrue(topmost >= 0, "the spike is drawn");
        assertEquals(sx, column + 0.5, 1, "the spike's top column");
        assertTrue(topmost + 0.5 >= sy && topmost + 0.5 <= sy + 2, "the spike's topmost red row " + topmost
                + " for a top predicted at " + sy);
    }

    /**
     * A camera 2 m above a flat 2 km square of 10 m cells, in the middle of a cell, looking level: the horizon is
     * the picture's middle row (the grid's far edge is 0.1° below it). Every pixel whose centre is more than 2 rows
     * below the middle is terrain, down to the bottom row, whose ray meets the ground 3.5 m ahead (so the cells
     * around the camera, crossing the near plane, are drawn), and every pixel above the middle is sky.
     */
    @Test
    void aCameraJustAboveAPlaneSeesTerrainEverywhereBelowTheHorizon() throws Exception {
        int n = 201;
        GridGeometry g = GridGeometry.metric(n, n, 10);
        Dem dem = new Dem(new float[n * n], g);
        int[] texture = new int[n * n];
        Arrays.fill(texture, GROUND);
        for (double azimuth : new double[] {0, 37, 90, 200}) {
            double a = Math.toRadians(azimuth);
            LookAt at = new LookAt(1003, 1004, 2, 1003 + 500 * Math.sin(a), 1004 + 500 * Math.cos(a), 2);
            int w = 320;
            int h = 240;
            int[] argb = new PerspectiveRenderer(new RenderSettings(2, 64)).render(dem,
                    new RenderedRelief(n, n, texture, g), Camera.lookingAt(at, 60, w, h),
                    ViewOptions.defaults().withBase(false), RenderProgress.NONE).argb();
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int c = argb[y * w + x];
                    if (y + 0.5 > h / 2.0 + 2) {
                        assertEquals(GROUND, c, "azimuth " + azimuth + ": pixel (" + x + ", " + y
                                + ") below the horizon is terrain");
                    } else if (y + 0.5 < h / 2.0) {
                        assertTrue(c != GROUND, "azimuth " + azimuth + ": pixel (" + x + ", " + y
                                + ") above the horizon is sky");
                    }
                }
            }
        }
    }

    /**
     * A camera 40 m above the floor of Big Tujunga Canyon (SRTM 30 m, UTM 11N), looking down the valley to the
     * east: each pixel is terrain exactly where a ray marched through the DEM (bilinear heights, 3 m steps) from
     * the camera meets the ground within the grid. Triangles and bilinear patches differ a little and a marched
     * ray can step over a thin crest, so at most 1.5 % of the pixels may disagree, and none in the lower third of
     * the picture, where the rays meet the ground close to the camera.
     */
    @Test
    void aCameraLowInARealValleyMatchesMarchedRays() throws Exception {
        Dem dem = DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"));
        GridGeometry g = dem.geometry();
        assertEquals(g.cellWidth(), g.cellWidthMeters(0), 1e-9, "a projected grid in metres");
        double[] eye = {cx(g, 205), cy(g, 392), 0};
        eye[2] = bilinear(dem, 205, 392) + 40;
        double[] target = {cx(g, 280), cy(g, 390), bilinear(dem, 280, 390)};
        int[] texture = new int[dem.width() * dem.height()];
        Arrays.fill(texture, GROUND);
        int w = 160;
        int h = 120;
        double fov = 70;
        int[] argb = new PerspectiveRenderer(new RenderSettings(2, 64)).render(dem,
                new RenderedRelief(dem.width(), dem.height(), texture, g),
                Camera.lookingAt(new LookAt(eye[0], eye[1], eye[2], target[0], target[1], target[2]), fov, w, h),
                ViewOptions.defaults().withBase(false), RenderProgress.NONE).argb();

        double[] forward = normalize(minus(target, eye));
        double[] right = normalize(cross(forward, new double[] {0, 0, 1}));
        double[] up = cross(right, forward);
        double f = h / 2.0 / Math.tan(Math.toRadians(fov / 2));
        int disagree = 0;
        int terrain = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double a = (x + 0.5 - w / 2.0) / f;
                double b = -(y + 0.5 - h / 2.0) / f;
                double[] ray = normalize(new double[] {forward[0] + a * right[0] + b * up[0],
                    forward[1] + a * right[1] + b * up[1], forward[2] + a * right[2] + b * up[2]});
                boolean hit = march(dem, eye, ray);
                boolean drawn = argb[y * w + x] == GROUND;
                terrain += drawn ? 1 : 0;
                if (hit != drawn) {
                    disagree++;
                    assertTrue(y < 2 * h / 3, "pixel (" + x + ", " + y + ") in the lower third: marched "
                            + (hit ? "hit" : "missed") + ", drawn " + (drawn ? "terrain" : "sky"));
                }
            }
        }
        assertTrue(disagree <= 0.015 * w * h, disagree + " pixels disagree");
        assertTrue(terrain > w * h / 3 && terrain < w * h, "terrain and sky: " + terrain);
    }

    /** A camera standing on the point it looks at is refused. */
    @Test
    void aCameraOnItsTargetIsRefused() {
        Dem dem = spike();
        Camera camera = Camera.lookingAt(new LookAt(100, 100, 50, 100, 100, 50), 40, 100, 100);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PerspectiveRenderer(
                new RenderSettings(1, 64)).render(dem, spikeTexture(dem), camera, ViewOptions.defaults(),
                RenderProgress.NONE));
        assertTrue(e.getMessage().contains("look-at"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new LookAt(Double.NaN, 0, 0, 1, 1, 1));
    }

    /** {column, row} of the first red pixel in reading order, or {-1, -1}. */
    private static int[] topmostRed(int[] argb, int w, int h) {
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int c = argb[y * w + x];
                if (red(c) > green(c) + 30) {
                    return new int[] {x, y};
                }
            }
        }
        return new int[] {-1, -1};
    }

    /** True when the ray from {@code eye} meets the ground within the grid's cell centres. */
    private static boolean march(Dem dem, double[] eye, double[] ray) {
        GridGeometry g = dem.geometry();
        for (double t = 1; t < 60_000; t += 3) {
            double x = eye[0] + t * ray[0];
            double y = eye[1] + t * ray[1];
            double z = eye[2] + t * ray[2];
            double col = (x - g.originX()) / g.cellWidth() - 0.5;
            double row = (g.originY() - y) / g.cellHeight() - 0.5;
            if (col < 0 || row < 0 || col > dem.width() - 1 || row > dem.height() - 1 || z < 0) {
                return false;
            }
            if (z <= bilinear(dem, col, row)) {
                return true;
            }
        }
        return false;
    }

    private static double bilinear(Dem dem, double col, double row) {
        int c0 = (int) Math.min(dem.width() - 2, Math.floor(col));
        int r0 = (int) Math.min(dem.height() - 2, Math.floor(row));
        double fc = col - c0;
        double fr = row - r0;
        return (1 - fr) * ((1 - fc) * dem.get(c0, r0) + fc * dem.get(c0 + 1, r0))
                + fr * ((1 - fc) * dem.get(c0, r0 + 1) + fc * dem.get(c0 + 1, r0 + 1));
    }

    private static double cx(GridGeometry g, double col) {
        return g.originX() + (col + 0.5) * g.cellWidth();
    }

    private static double cy(GridGeometry g, double row) {
        return g.originY() - (row + 0.5) * g.cellHeight();
    }

    private static int red(int c) {
        return (c >> 16) & 255;
    }

    private static int green(int c) {
        return (c >> 8) & 255;
    }

    private static double[] minus(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] normalize(double[] a) {
        double l = Math.sqrt(dot(a, a));
        return new double[] {a[0] / l, a[1] / l, a[2] / l};
    }
}
