package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowMask;
import io.github.jdem846.testing.TestDems;
import io.github.jdem846.tint.ColorRamp;
import io.github.jdem846.tint.TintFunction;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

class RendererTest {

    private static final Dem LUX = TestDems.load(TestDems.LUXEMBOURG);
    private static final Dem BT = TestDems.load(TestDems.BIG_TUJUNGA).crop(300, 100, 300, 200);

    @Test
    void outputIsIdenticalForAnyTileSizeAndThreadCount() throws InterruptedException {
        Scene scene = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP).withLight(new LightDirection(250, 10));
        int[] reference = new Renderer(new RenderSettings(1, 4096)).render(BT, scene).argb();
        for (int threads : new int[] {1, 2, 3}) {
            for (int tile : new int[] {16, 17, 64, 255}) {
                int[] px = new Renderer(new RenderSettings(threads, tile)).render(BT, scene).argb();
                assertArrayEquals(reference, px, "threads " + threads + ", tile " + tile);
            }
        }
    }

    @Test
    void shadowBytesAreTheShadowedFractionsTimes255RoundedHalfUp() throws InterruptedException {
        io.github.jdem846.shadow.CellWindow area = new io.github.jdem846.shadow.CellWindow(11, 7, 251, 170);
        for (ShadowAlgorithm alg : new ShadowAlgorithm[] {ShadowAlgorithm.SWEEP, ShadowAlgorithm.EXACT, null}) {
            Scene scene = Scene.defaults().withShadows(alg).withLight(new LightDirection(250, 6));
            if (alg == ShadowAlgorithm.SWEEP) {
                scene = scene.withShadowOptions(scene.shadowOptions().withSoftShadows(true));
            }
            float[] fractions = new Renderer(new RenderSettings(1, 4096)).shadows(BT, scene, area, RenderProgress.NONE);
            int partial = 0;
            for (int threads : new int[] {1, 3}) {
                byte[] bytes = new Renderer(new RenderSettings(threads, 16)).shadowBytes(BT, scene, area,
                        RenderProgress.NONE);
                assertEquals(fractions.length, bytes.length);
                for (int i = 0; i < bytes.length; i++) {
                    int expected = Math.round(Math.max(0f, Math.min(1f, fractions[i])) * 255f);
                    assertEquals(expected, bytes[i] & 0xFF, alg + " cell " + i + " of " + fractions[i]);
                    partial += expected > 0 && expected < 255 ? 1 : 0;
                }
            }
            assertEquals(alg == ShadowAlgorithm.SWEEP, partial > 0, alg + ": cells partly in shadow " + partial);
        }
    }

    @Test
    void anAreaRendersLikeTheSameCellsOfTheWholeGrid() throws InterruptedException {
        io.github.jdem846.shadow.CellWindow area = new io.github.jdem846.shadow.CellWindow(37, 21, 150, 90);
        for (ShadowAlgorithm alg : new ShadowAlgorithm[] {ShadowAlgorithm.MARCH, ShadowAlgorithm.EXACT}) {
            Scene scene = Scene.defaults().withShadows(alg).withLight(new LightDirection(250, 10));
            Renderer renderer = new Renderer(new RenderSettings(2, 64));
            RenderedRelief whole = renderer.render(BT, scene);
            RenderedRelief part = renderer.render(BT, scene, area, RenderProgress.NONE);
            assertEquals(area.width(), part.width());
            assertEquals(BT.geometry().window(37, 21, 150, 90), part.geometry());
            for (int r = 0; r < area.height(); r++) {
                for (int c = 0; c < area.width(); c++) {
                    assertEquals(whole.argb()[(area.row() + r) * BT.width() + area.col() + c],
                            part.argb()[r * area.width() + c], alg + " cell " + c + "," + r);
                }
            }
        }
    }

    @Test
    void grayHillshadeIsTheGrayOfTheIlluminationForAnyTiling() throws InterruptedException {
        io.github.jdem846.shade.HillshadeOptions options = io.github.jdem846.shade.HillshadeOptions.DEFAULTS;
        io.github.jdem846.light.LightField light = io.github.jdem846.light.LightField.uniform(
                new LightDirection(315, 45));
        for (HillshadeMethod method : HillshadeMethod.values()) {
            float[] dot = new Renderer(new RenderSettings(1, 4096)).illumination(LUX, method.stage(options), light,
                    RenderProgress.NONE);
            byte[] expected = method.toGray(dot, options);
            for (int tile : new int[] {16, 33, 4096}) {
                byte[] gray = new Renderer(new RenderSettings(2, tile)).hillshadeGray(LUX, method, options, light,
                        RenderProgress.NONE);
                assertArrayEquals(expected, gray, method + ", tile " + tile);
            }
        }
    }

    @Test
    void eachPixelIsTheCompositionOfTheStages() throws InterruptedException {
        LightDirection light = new LightDirection(300, 20);
        Scene scene = Scene.defaults().withShadows(ShadowAlgorithm.MARCH).withLight(light);
        int[] px = new Renderer().render(BT, scene).argb();

        TintFunction tint = ColorRamp.defaultRamp().bind(BT.statistics());
        float[] dot = new float[BT.width() * BT.height()];
        HillshadeMethod.JDEM846.stage(scene.hillshadeOptions())
                .illuminate(BT, light, 0, 0, BT.width(), BT.height(), dot);
        ShadowMask mask = ShadowAlgorithm.MARCH.compute(BT, light, scene.shadowOptions());
        Compositor compositor = new Compositor(scene.hillshadeOptions(), 0.4);
        long shadowed = 0;
        for (int i = 0; i < px.length; i++) {
            float s = mask.backingArray()[i];
            shadowed += s > 0 ? 1 : 0;
            int expected = compositor.compose(tint.argb(BT.backingArray()[i]), dot[i], s, 0);
            assertEquals(expected, px[i], "pixel " + i);
        }
        assertTrue(shadowed > 0, "a 20° sun over the San Gabriels casts shadows");
    }

    @Test
    void castShadowsOnlyEverDarken() throws InterruptedException {
        Scene lit = Scene.defaults().withLight(new LightDirection(160, 8));
        int[] without = new Renderer().render(BT, lit).argb();
        int[] with = new Renderer().render(BT, lit.withShadows(ShadowAlgorithm.SWEEP)).argb();
        int darker = 0;
        for (int i = 0; i < with.length; i++) {
            int a = luminance(without[i]);
            int b = luminance(with[i]);
            assertTrue(b <= a, "pixel " + i + " got lighter with shadows");
            darker += b < a ? 1 : 0;
        }
        assertTrue(darker > with.length / 100, "low sun darkens more than 1 % of the cells, got " + darker);
    }

    @Test
    void noDataIsTransparentAndValidCellsOpaque() throws InterruptedException {
        int[] px = new Renderer().render(LUX, Scene.defaults()).argb();
        int transparent = 0;
        for (int i = 0; i < px.length; i++) {
            boolean noData = Float.isNaN(LUX.backingArray()[i]);
            assertEquals(noData ? 0 : 0xFF, px[i] >>> 24, "alpha of pixel " + i);
            transparent += noData ? 1 : 0;
        }
        assertEquals(3942, transparent);
    }

    @Test
    void disabledStagesLeaveThePlainTint() throws InterruptedException {
        Scene tintOnly = Scene.defaults().withHillshade(null);
        int[] px = new Renderer().render(LUX, tintOnly).argb();
        TintFunction tint = ColorRamp.defaultRamp().bind(LUX.statistics());
        for (int i = 0; i < px.length; i++) {
            assertEquals(tint.argb(LUX.backingArray()[i]), px[i]);
        }
        Scene grayOnly = Scene.defaults().withTint(null).withHillshade(null);
        int[] gray = new Renderer().render(LUX, grayOnly).argb();
        for (int i = 0; i < gray.length; i++) {
            assertEquals(Float.isNaN(LUX.backingArray()[i]) ? 0 : Renderer.PLAIN_GRAY, gray[i]);
        }
    }

    @Test
    void progressReachesTheTotalAndInterruptStops() throws InterruptedException {
        AtomicLong last = new AtomicLong();
        AtomicLong total = new AtomicLong();
        new Renderer(new RenderSettings(2, 32)).render(BT, Scene.defaults(), (stage, done, n) -> {
            last.accumulateAndGet(done, Math::max);
            total.set(n);
        });
        assertEquals(total.get(), last.get());
        assertTrue(total.get() >= 60);

        Thread.currentThread().interrupt();
        assertThrows(InterruptedException.class,
                () -> new Renderer(new RenderSettings(2, 16)).render(BT, Scene.defaults()));
        Thread.interrupted();
    }

    @Test
    void poolIsReleasedAfterRendering() throws InterruptedException {
        // Many renders in a row must not accumulate worker threads.
        int before = Thread.activeCount();
        for (int i = 0; i < 20; i++) {
            new Renderer(new RenderSettings(2, 64)).render(LUX, Scene.defaults());
        }
        assertTrue(Thread.activeCount() < before + 10, "threads leaked: " + before + " → " + Thread.activeCount());
        assertTrue(ForkJoinPool.commonPool().getParallelism() >= 1);
    }

    private static int luminance(int argb) {
        return ((argb >> 16) & 0xff) + ((argb >> 8) & 0xff) + (argb & 0xff);
    }
}
