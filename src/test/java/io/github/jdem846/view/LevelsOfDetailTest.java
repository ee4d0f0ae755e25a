package io.github.jdem846.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.RenderedRelief;
import org.junit.jupiter.api.Test;

/**
 * Levels of detail against uniform meshes: a far camera gets the uniform coarse picture exactly; near the camera the
 * picture is the full-resolution one; the seams between levels leave no holes.
 */
class LevelsOfDetailTest {

    private static final int N = 1024;
    private static final double CELL = 10;
    private static final int W = 200;
    private static final int H = 150;

    /**
     * Hills: 120 m waves 2.5 km long, with 6 m ripples 70 m long (detail that averaging by 6 cells removes and the
     * full resolution keeps).
     */
    private static Dem hills() {
        float[] z = new float[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                z[r * N + c] = (float) (200 + 120 * Math.sin(c * CELL / 400) * Math.cos(r * CELL / 330)
                        + 6 * Math.sin(c * CELL / 11) * Math.sin(r * CELL / 13));
            }
        }
        return new Dem(z, GridGeometry.metric(N, N, CELL));
    }

    /** A texture with no blue (the sky always has some): red and green from the position. */
    private static RenderedRelief texture(Dem dem) {
        int[] argb = new int[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                argb[r * N + c] = 0xFF000000 | (c * 7 % 256) << 16 | (r * 5 % 256) << 8;
            }
        }
        return new RenderedRelief(N, N, argb, dem.geometry());
    }

    private static boolean terrain(int argb) {
        return (argb & 255) == 0;
    }

    private static PerspectiveRenderer renderer() {
        return new PerspectiveRenderer(new RenderSettings(2, 64));
    }

    /**
     * From 80 km with an 8° field of view, a cell of the coarse grid (6 × 10 m) looks 0.8 pixel wide at the nearest
     * point: no finer level is used, and the picture is the uniform coarse mesh's, bit for bit.
     */
    @Test
    void aFarCameraDrawsTheUniformPicture() throws Exception {
        Dem dem = hills();
        int decimation = ViewJob.meshDecimation(N, N, new Camera(200, 35, 0, 8, W, H));
        assertEquals(6, decimation);
        TerrainSource source = TerrainSource.of(dem);
        Dem coarse = source.read(0, 0, N, N, decimation);
        Camera camera = new Camera(200, 35, 80_000, 8, W, H);
        RenderedRelief texture = texture(dem);
        int[] uniform = renderer().render(coarse, texture, camera, ViewOptions.defaults(), RenderProgress.NONE)
                .argb();
        int[] levels = renderer().render(source, decimation, texture, camera, ViewOptions.defaults(),
                RenderProgress.NONE).argb();
        assertArrayEquals(uniform, levels);
    }

    /**
     * A camera 30 m above the middle of the hills looking over them: where the full-resolution crop of 300 × 300
     * cells around it (rendered as a uniform mesh) shows terrain in the lower half of the picture, the picture with
     * levels of detail is the same (within 2 levels per channel) at 97 % of the pixels or more, and matches it
     * clearly better than the uniform coarse mesh does.
     */
    @Test
    void nearTheCameraTheDetailIsTheFullResolution() throws Exception {
        Dem dem = hills();
        TerrainSource source = TerrainSource.of(dem);
        int decimation = ViewJob.meshDecimation(N, N, new Camera(200, 35, 0, 60, W, H));
        Dem coarse = source.read(0, 0, N, N, decimation);
        double x = 5120;
        double y = 5120;
        LookAt at = new LookAt(x, y, height(dem, x, y) + 30, x + 2000, y + 1000, height(dem, x + 2000, y + 1000));
        Camera camera = Camera.lookingAt(at, 60, W, H);
        RenderedRelief texture = texture(dem);
        ViewOptions options = ViewOptions.defaults().withBase(false);
        int[] crop = renderer().render(dem.crop(362, 362, 300, 300), texture, camera, options, RenderProgress.NONE)
                .argb();
        int[] levels = renderer().render(source, decimation, texture, camera, options, RenderProgress.NONE).argb();
        int[] uniform = renderer().render(coarse, texture, camera, options, RenderProgress.NONE).argb();
        int compared = 0;
        int sameLevels = 0;
        int sameUniform = 0;
        for (int p = W * H / 2; p < W * H; p++) {
            if (!terrain(crop[p])) {
                continue;
            }
            compared++;
            sameLevels += close(crop[p], levels[p]) ? 1 : 0;
            sameUniform += close(crop[p], uniform[p]) ? 1 : 0;
        }
        assertTrue(compared > W * H / 4, "the crop fills most of the lower half: " + compared);
        assertTrue(sameLevels >= 0.97 * compared, sameLevels + " of " + compared + " pixels match");
        assertTrue(sameLevels > sameUniform + 0.2 * compared, "levels " + sameLevels + ", uniform " + sameUniform
                + " of " + compared);
    }

    /**
     * No cracks: on a flat grid seen from 20 m above its middle, looking level, every pixel more than 2 rows below
     * the horizon is terrain; on the hills, no background pixel has terrain on all four sides.
     */
    @Test
    void theLevelsLeaveNoCracks() throws Exception {
        Dem flat = new Dem(new float[N * N], GridGeometry.metric(N, N, CELL));
        int decimation = ViewJob.meshDecimation(N, N, new Camera(200, 35, 0, 60, W, H));
        for (double azimuth : new double[] {20, 135, 250}) {
            double a = Math.toRadians(azimuth);
            LookAt at = new LookAt(5003, 5007, 20, 5003 + 3000 * Math.sin(a), 5007 + 3000 * Math.cos(a), 20);
            int[] argb = renderer().render(TerrainSource.of(flat), decimation, texture(flat),
                    Camera.lookingAt(at, 60, W, H), ViewOptions.defaults(), RenderProgress.NONE).argb();
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    if (y + 0.5 > H / 2.0 + 2) {
                        assertTrue(terrain(argb[y * W + x]), "azimuth " + azimuth + ": pixel (" + x + ", " + y
                                + ") below the horizon is terrain");
                    }
                }
            }
        }
        Dem dem = hills();
        for (double azimuth : new double[] {20, 135, 250}) {
            double a = Math.toRadians(azimuth);
            LookAt at = new LookAt(5003, 5007, height(dem, 5003, 5007) + 40, 5003 + 3000 * Math.sin(a),
                    5007 + 3000 * Math.cos(a), Double.NaN);
            int[] argb = renderer().render(TerrainSource.of(dem), decimation, texture(dem),
                    Camera.lookingAt(at, 60, W, H), ViewOptions.defaults(), RenderProgress.NONE).argb();
            for (int y = 1; y < H - 1; y++) {
                for (int x = 1; x < W - 1; x++) {
                    int p = y * W + x;
                    boolean hole = !terrain(argb[p]) && terrain(argb[p - 1]) && terrain(argb[p + 1])
                            && terrain(argb[p - W]) && terrain(argb[p + W]);
                    assertTrue(!hole, "azimuth " + azimuth + ": a hole at (" + x + ", " + y + ")");
                }
            }
        }
    }

    /** Heights at a point of the metric grid, bilinear between cell centres. */
    private static double height(Dem dem, double x, double y) {
        double col = x / CELL - 0.5;
        double row = (N * CELL - y) / CELL - 0.5;
        int c = (int) Math.floor(col);
        int r = (int) Math.floor(row);
        double fc = col - c;
        double fr = row - r;
        return (1 - fr) * ((1 - fc) * dem.get(c, r) + fc * dem.get(c + 1, r))
                + fr * ((1 - fc) * dem.get(c, r + 1) + fc * dem.get(c + 1, r + 1));
    }

    private static boolean close(int a, int b) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs(((a >> shift) & 255) - ((b >> shift) & 255)) > 2) {
                return false;
            }
        }
        return true;
    }
}
