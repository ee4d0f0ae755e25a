package io.github.jdem846.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.RenderedRelief;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.util.Arrays;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.Test;

/**
 * The perspective renderer against pictures predicted by hand: a flat terrain seen straight down is its 2-D relief,
 * a spike's top lands on the pixel the pinhole equations give, a globe's limb has the angular size the body's radius
 * gives; and the picture does not depend on the thread count.
 */
class PerspectiveRendererTest {

    /** A real relief (the bundled sample, 120 × 80 cells of SRTM 30 m, UTM) with sweep shadows. */
    private static Dem sample() throws Exception {
        return DemReader.read(java.nio.file.Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif")).crop(200, 150, 120, 80);
    }

    private static RenderedRelief relief(Dem dem) throws InterruptedException {
        return new Renderer(new RenderSettings(1, 64)).render(dem, Scene.defaults().withShadows(ShadowAlgorithm.SWEEP));
    }

    /**
     * Straight down (azimuth 180: north up) from the distance at which the grid's height in cells fills the
     * picture's height in pixels, the pixel centres fall on the cell centres: with the terrain flattened (an
     * exaggeration of 10⁻⁹ leaves it flat to a micrometre), each pixel is its cell's colour in the 2-D relief. The
     * tolerance: 1 level per channel inside (texture positions in float), and the outermost ring of pixels, whose
     * centres lie on the terrain's very edge, may be background.
     */
    @Test
    void aFlatTerrainFromStraightAboveIsThe2dRelief() throws Exception {
        Dem dem = sample();
        RenderedRelief relief = relief(dem);
        double cell = dem.geometry().cellHeightMeters(0);
        double fov = 40;
        double distance = dem.height() * cell / 2 / Math.tan(Math.toRadians(fov / 2));
        Camera camera = new Camera(180, 90, distance, fov, dem.width(), dem.height());
        RenderedView view = new PerspectiveRenderer(new RenderSettings(2, 64)).render(dem, relief, camera,
                ViewOptions.defaults().withExaggeration(1e-9), RenderProgress.NONE);
        int w = dem.width();
        int h = dem.height();
        int worst = 0;
        int edgeOthers = 0;
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                int d = maxChannelDifference(view.argb()[r * w + c], relief.argb()[r * w + c]);
                boolean edge = r == 0 || c == 0 || r == h - 1 || c == w - 1;
                if (edge) {
                    edgeOthers += d > 1 ? 1 : 0;
                } else {
                    worst = Math.max(worst, d);
                }
            }
        }
        assertTrue(worst <= 1, "inside, a pixel differs from its cell by " + worst + " levels");
        assertTrue(edgeOthers <= 2 * (w + h), "edge pixels differing: " + edgeOthers);
    }

    /**
     * A 200 m spike on flat ground, seen from azimuth 200°, elevation 30°, 1000 m: the camera's frame built here
     * from the usual look-at construction (right = forward × up, up' = right × forward) and the pinhole equations
     * predict where the spike's top lands; the red of the spike's cell is drawn just below that point (within 2
     * pixels, the sampling at pixel centres) and nothing of it above.
     */
    @Test
    void aSpikeProjectsToThePredictedPixel() throws Exception {
        int n = 41;
        double cell = 40;
        float[] heights = new float[n * n];
        heights[20 * n + 20] = 200;
        GridGeometry g = GridGeometry.metric(n, n, cell);
        Dem dem = new Dem(heights, g);
        int[] texture = new int[n * n];
        Arrays.fill(texture, 0xFF808080);
        texture[20 * n + 20] = 0xFFFF0000;
        Camera camera = new Camera(200, 30, 1000, 50, 400, 300);
        RenderedView view = new PerspectiveRenderer(new RenderSettings(3, 64)).render(dem,
                new RenderedRelief(n, n, texture, g), camera, ViewOptions.defaults(), RenderProgress.NONE);

        // the target: the grid's centre (cell 20, 20) at the middle of the heights, 100 m
        double az = Math.toRadians(200);
        double el = Math.toRadians(30);
        double[] target = {0, 0, 100};
        double[] eye = {target[0] + 1000 * Math.sin(az) * Math.cos(el), target[1] + 1000 * Math.cos(az)
                * Math.cos(el), target[2] + 1000 * Math.sin(el)};
        double[] forward = normalize(minus(target, eye));
        double[] right = normalize(cross(forward, new double[] {0, 0, 1}));
        double[] up = cross(right, forward);
        double f = 150 / Math.tan(Math.toRadians(25));
        double[] p = minus(new double[] {0, 0, 200}, eye);
        double sx = 200 + f * dot(p, right) / dot(p, forward);
        double sy = 150 - f * dot(p, up) / dot(p, forward);

        int below = view.argb()[(int) Math.floor(sy + 4) * 400 + (int) Math.floor(sx)];
        assertTrue(red(below) > green(below) + 60, "just below the predicted top (" + sx + ", " + sy + ") the "
                + "spike is red: " + Integer.toHexString(below));
        int topmost = Integer.MAX_VALUE;
        for (int y = 0; y < 300 && topmost == Integer.MAX_VALUE; y++) {
            for (int x = 0; x < 400; x++) {
                int c = view.argb()[y * 400 + x];
                if (red(c) > green(c) + 30) {
                    topmost = y;
                    assertEquals(sx, x + 0.5, 1, "the spike's top column");
                    break;
                }
            }
        }
        // pixels are sampled at their centres: the pyramid's point is covered only once it is wider than a pixel's
        // spacing, so its first row lies up to 2 pixels below the top, and none above
        assertTrue(topmost + 0.5 >= sy && topmost + 0.5 <= sy + 2, "the spike's topmost red row " + topmost
                + " for a top predicted at " + sy);
    }

    /**
     * On a spherical body (the Moon, radius R), seen straight down from d metres above a small DEM, the body's
     * disc has the angular radius asin(R / (R + d)): across the picture's middle row, 2 f tan(asin(R / (R + d)))
     * pixels are not space.
     */
    @Test
    void aGlobesLimbHasTheBodysAngularSize() throws Exception {
        double radius = Ellipsoid.MOON.semiMajorAxis();
        CrsInfo moon = CrsInfo.geographic("Moon", null, Ellipsoid.MOON);
        GridGeometry g = new GridGeometry(20, 20, 10, 20, 0.01, 0.01, moon, PixelAnchor.CORNER);
        Dem dem = new Dem(new float[400], g);
        int[] texture = new int[400];
        Arrays.fill(texture, 0xFFFFFFFF);
        double d = 3_000_000;
        Camera camera = new Camera(180, 90, d, 90, 601, 601);
        RenderedView view = new PerspectiveRenderer(new RenderSettings(2, 64)).render(dem,
                new RenderedRelief(20, 20, texture, g), camera, ViewOptions.defaults().withGlobe(true),
                RenderProgress.NONE);
        int notSpace = 0;
        for (int x = 0; x < 601; x++) {
            notSpace += view.argb()[300 * 601 + x] != ViewOptions.SPACE ? 1 : 0;
        }
        double f = 300.5 / Math.tan(Math.toRadians(45));
        double expected = 2 * f * Math.tan(Math.asin(radius / (radius + d)));
        assertEquals(expected, notSpace, 2.0);
        assertEquals(0xFFFFFFFF, view.argb()[300 * 601 + 300], "the DEM itself, white, at the centre");
    }

    /** The picture is the same, bit for bit, on 1, 2 or 5 threads and on a shared pool. */
    @Test
    void theViewIsIdenticalForAnyThreadCount() throws Exception {
        Dem dem = sample();
        RenderedRelief relief = relief(dem);
        Camera camera = new Camera(200, 35, 0, 40, 300, 200);
        ViewOptions options = ViewOptions.defaults().withExaggeration(2);
        int[] one = new PerspectiveRenderer(new RenderSettings(1, 64)).render(dem, relief, camera, options,
                RenderProgress.NONE).argb();
        for (int threads : new int[] {2, 5}) {
            assertArrayEquals(one, new PerspectiveRenderer(new RenderSettings(threads, 64)).render(dem, relief,
                    camera, options, RenderProgress.NONE).argb(), threads + " threads");
        }
        ForkJoinPool pool = new ForkJoinPool(3);
        try {
            assertArrayEquals(one, new PerspectiveRenderer(new RenderSettings(1, 64).withPool(pool)).render(dem,
                    relief, camera, options, RenderProgress.NONE).argb(), "shared pool");
        } finally {
            pool.shutdown();
        }
        long sky = Arrays.stream(one).filter(c -> c == one[0]).count();
        assertTrue(sky > 0 && sky < one.length * 3 / 4, "some background, mostly terrain: " + sky);
    }

    /**
     * Straight down from 400 m over a 41 × 41 grid of 10 m cells with a 50° field of view on a square picture,
     * the camera sees ±400 tan 25° ≈ ±187 m around the centre: cells 1 … 38 (those within 18.7 cells of the centre,
     * and the ones straddling that edge), not the whole grid; from far away it sees all 40 × 40 cells.
     */
    @Test
    void onlyTheCellsInViewAreVisible() {
        int n = 41;
        Dem dem = new Dem(new float[n * n], GridGeometry.metric(n, n, 10));
        int[] close = PerspectiveRenderer.visibleCells(dem, new Camera(180, 90, 400, 50, 100, 100),
                ViewOptions.defaults());
        assertArrayEquals(new int[] {1, 1, 38, 38}, close);
        int[] far = PerspectiveRenderer.visibleCells(dem, new Camera(180, 90, 4000, 50, 100, 100),
                ViewOptions.defaults());
        assertArrayEquals(new int[] {0, 0, 39, 39}, far);
    }

    /**
     * No-data cells are holes: straight down on a flat 40 × 40 grid whose middle 10 × 10 cells are no-data, the
     * middle of the picture is background and a point well inside the valid ring is terrain.
     */
    @Test
    void noDataCellsAreHoles() throws Exception {
        int n = 40;
        float[] heights = new float[n * n];
        for (int r = 15; r < 25; r++) {
            Arrays.fill(heights, r * n + 15, r * n + 25, Float.NaN);
        }
        GridGeometry g = GridGeometry.metric(n, n, 10);
        int[] texture = new int[n * n];
        Arrays.fill(texture, 0xFF20A040);
        double distance = n * 10 / 2 / Math.tan(Math.toRadians(20));
        RenderedView view = new PerspectiveRenderer(new RenderSettings(2, 64)).render(new Dem(heights, g),
                new RenderedRelief(n, n, texture, g), new Camera(180, 90, distance, 40, n, n), ViewOptions.defaults(),
                RenderProgress.NONE);
        assertTrue(view.argb()[20 * n + 20] != 0xFF20A040, "the hole shows the background");
        assertEquals(0xFF20A040, view.argb()[5 * n + 5], "the terrain around it is drawn");
    }

    /**
     * The base: seen from 20° above the horizon, a grid textured in one colour shows walls below its near edge
     * in that colour at {@link PerspectiveRenderer#WALL_BRIGHTNESS} (200 → 90); without the base, none.
     */
    @Test
    void theBaseIsDrawnBelowTheEdges() throws Exception {
        int n = 20;
        GridGeometry g = GridGeometry.metric(n, n, 10);
        int[] texture = new int[n * n];
        Arrays.fill(texture, 0xFFC8C8C8);
        Camera camera = new Camera(180, 20, 0, 40, 200, 150);
        PerspectiveRenderer renderer = new PerspectiveRenderer(new RenderSettings(2, 64));
        RenderedRelief relief = new RenderedRelief(n, n, texture, g);
        float[] ramp = new float[n * n];
        for (int i = 0; i < ramp.length; i++) {
            ramp[i] = 5 * (i / n); // 0 m in the north to 95 m in the south: a base 9.5 m below 0
        }
        Dem sloped = new Dem(ramp, g);
        long with = Arrays.stream(renderer.render(sloped, relief, camera, ViewOptions.defaults(), RenderProgress.NONE)
                .argb()).filter(c -> c == 0xFF5A5A5A).count();
        long without = Arrays.stream(renderer.render(sloped, relief, camera, ViewOptions.defaults().withBase(false),
                RenderProgress.NONE).argb()).filter(c -> c == 0xFF5A5A5A).count();
        assertTrue(with > 100, "wall pixels: " + with);
        assertEquals(0, without);
    }

    private static int maxChannelDifference(int a, int b) {
        int d = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            d = Math.max(d, Math.abs(((a >> shift) & 255) - ((b >> shift) & 255)));
        }
        return d;
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
