package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;

/** The light models' arithmetic, worked by hand, and the sky-view stage in the renderer. */
class SkyLightTest {

    @Test
    void theSkyModelAddsSunAndSky() {
        Compositor sky = new Compositor(HillshadeOptions.DEFAULTS, 0.4, LightModel.SKY, 0.35);
        // lit, dot 0.5, whole sky: L = 0.5 + 0.35 = 0.85, d = 0.7, light intensity 0.75 → 0.525
        assertEquals(0.525, sky.brightness(0.5, 0, 1, 0), 1e-12);
        // fully in cast shadow, sky-view 0.8: L = 0.28, d = −0.44 (dark intensity 1)
        assertEquals(-0.44, sky.brightness(0.5, 1, 0.8, 0), 1e-12);
        // facing away from the sun (dot < 0) counts as no sun, not as negative light: L = 0.35·0.6 = 0.21
        assertEquals(-0.58, sky.brightness(-0.7, 0, 0.6, 0), 1e-12);
        // half shadowed, with twilight fade 0.1: L = 0.8·0.5 + 0.35 = 0.75, d = 0.5 − 0.1 = 0.4 → 0.3
        assertEquals(0.3, sky.brightness(0.8, 0.5, 1, 0.1), 1e-12);
        // without sky light only the sun: L = 0.5·(1 − 0.5) = 0.25, d = −0.5
        Compositor sun = new Compositor(HillshadeOptions.DEFAULTS, 0.4, LightModel.SKY, 0);
        assertEquals(-0.5, sun.brightness(0.5, 0.5, 0.3, 0), 1e-12);
    }

    @Test
    void theOriginalModelWithoutSkyIsTheOriginalFormula() {
        Compositor old = new Compositor(HillshadeOptions.DEFAULTS, 0.4);
        Compositor none = new Compositor(HillshadeOptions.DEFAULTS, 0.4, LightModel.JDEM846, 0);
        SplittableRandom rnd = new SplittableRandom(846);
        for (int i = 0; i < 10000; i++) {
            double dot = rnd.nextDouble(-1, 1);
            double s = rnd.nextDouble();
            double v = rnd.nextDouble();
            double fade = rnd.nextDouble(0, 2);
            double d = dot - fade - 2 * 0.4 * s;
            double expected = HillshadeOptions.DEFAULTS.tone(Math.max(-1, Math.min(1, d)));
            assertEquals(expected, old.brightness(dot, s, fade), 0);
            assertEquals(expected, none.brightness(dot, s, v, fade), 0);
        }
        // with sky: (1 − W)·d + W·(2·svf − 1); dot 0.2 in shadow, svf 0.9, W 0.5: 0.5·(−0.6) + 0.5·0.8 = 0.1 → 0.075
        Compositor mixed = new Compositor(HillshadeOptions.DEFAULTS, 0.4, LightModel.JDEM846, 0.5);
        assertEquals(0.075, mixed.brightness(0.2, 1, 0.9, 0), 1e-12);
    }

    @Test
    void ambientOutsideZeroToOneIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> Scene.defaults().withAmbient(-0.1));
        assertThrows(IllegalArgumentException.class, () -> Scene.defaults().withAmbient(1.01));
        assertThrows(IllegalArgumentException.class, () -> Scene.defaults().withSkyDirections(2));
    }

    private static Set<String> stages(Renderer r, Dem dem, Scene scene, int[][] out) throws InterruptedException {
        Set<String> seen = ConcurrentHashMap.newKeySet();
        out[0] = r.render(dem, scene, (stage, done, total) -> seen.add(stage)).argb();
        return seen;
    }

    @Test
    void noSkyViewIsComputedWithoutSkyLightAndTheRenderThenIgnoresIt() throws IOException, InterruptedException {
        Dem dem = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"));
        Renderer r = new Renderer(RenderSettings.defaults().withParallelism(2));
        Scene base = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP).withLight(new LightDirection(100, 12));
        int[][] a = new int[1][];
        int[][] b = new int[1][];
        for (LightModel m : LightModel.values()) {
            Set<String> off = stages(r, dem, base.withLightModel(m).withAmbient(0), a);
            assertFalse(off.contains(Renderer.SKY_STAGE), off.toString());
            Set<String> on = stages(r, dem, base.withLightModel(m).withAmbient(0.35), b);
            assertTrue(on.contains(Renderer.SKY_STAGE), on.toString());
            assertFalse(java.util.Arrays.equals(a[0], b[0]), m.toString());
        }
        // the original model without sky light is Scene.defaults()' render, pixel for pixel
        stages(r, dem, base.withAmbient(0), a);
        stages(r, dem, base.withLightModel(LightModel.JDEM846), b);
        assertArrayEquals(a[0], b[0]);
    }

    @Test
    void theSkyViewLayerOfAnAreaIsThatOfTheWholeGrid() throws IOException, InterruptedException {
        Dem dem = DemReader.read(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"));
        Renderer r = new Renderer(RenderSettings.defaults().withParallelism(2));
        Scene scene = Scene.defaults().withSkyDirections(16);
        float[] whole = r.skyView(dem, scene, CellWindow.whole(dem.width(), dem.height()), RenderProgress.NONE);
        CellWindow area = new CellWindow(10, 20, 30, 40);
        float[] part = r.skyView(dem, scene, area, RenderProgress.NONE);
        for (int y = 0; y < area.height(); y++) {
            for (int x = 0; x < area.width(); x++) {
                assertEquals(whole[(y + 20) * dem.width() + x + 10], part[y * area.width() + x], 0f);
            }
        }
    }
}
