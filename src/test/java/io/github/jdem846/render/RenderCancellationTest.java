package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.IlluminationStage;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.testing.InterruptedRun;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.HashSet;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

/**
 * Interrupting the thread that called the renderer stops it inside the running stage, not at the next stage: the
 * call ends with {@link InterruptedException} within 500 ms of the interrupt (at 200 ms into work that takes
 * seconds), the interrupt status cleared, and none of the renderer's threads is left.
 */
class RenderCancellationTest {

    private static final long INTERRUPT_AFTER_MS = 200;
    private static final double BOUND_MS = 500;
    private static final Dem BT = TestDems.load(TestDems.BIG_TUJUNGA);

    @Test
    void anExactShadowRenderStopsInsideTheShadowStage() throws InterruptedException {
        // Big Tujunga (1197 × 643), exact shadows at 5°: 3.7–23 s on two threads uninterrupted (idle to loaded).
        Scene scene = Scene.defaults().withShadows(ShadowAlgorithm.EXACT).withLight(new LightDirection(300, 5));
        assertStopsPromptly(() -> new Renderer(new RenderSettings(2, 256)).render(BT, scene));
    }

    @Test
    void theShadowLayerAloneStopsToo() throws InterruptedException {
        // Soft shadows by the sweep (all levels in one walk of the lines), Big Tujunga mirror-tiled 4 × 4: 1.1–2.5 s.
        Dem large = SyntheticDems.mirrored(BT, 4 * BT.width(), 4 * BT.height());
        Scene scene = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP).withLight(new LightDirection(300, 5))
                .withShadowOptions(ShadowOptions.DEFAULTS.withSoftShadows(true));
        assertStopsPromptly(() -> new Renderer(new RenderSettings(2, 256)).shadows(large, scene,
                RenderProgress.NONE));
    }

    @Test
    void aTileStageStopsBetweenTiles() throws InterruptedException {
        // 16-cell tiles of 20 ms each: 3075 tiles, 30 s on two threads uninterrupted.
        Queue<Long> starts = new ConcurrentLinkedQueue<>();
        IlluminationStage slow = (dem, light, col0, row0, w, h, out) -> {
            starts.add(System.nanoTime());
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        };
        LightField light = LightField.uniform(new LightDirection(315, 45));
        Set<String> before = InterruptedRun.liveThreads(Renderer.WORKER_NAME);
        InterruptedRun run = InterruptedRun.of(() -> new Renderer(new RenderSettings(2, 16)).illumination(BT, slow,
                light, RenderProgress.NONE), INTERRUPT_AFTER_MS);
        assertOutcome(run, before);
        assertTrue(starts.size() < 100, starts.size() + " tiles ran");
        long startedAfter = starts.stream().filter(t -> t > run.interruptedAt()).count();
        assertTrue(startedAfter <= 2, startedAfter + " tiles started after the interrupt (at most one per thread "
                + "that had passed its test just before)");
    }

    private static void assertStopsPromptly(java.util.concurrent.Callable<?> render) throws InterruptedException {
        Set<String> before = InterruptedRun.liveThreads(Renderer.WORKER_NAME);
        assertOutcome(InterruptedRun.of(render, INTERRUPT_AFTER_MS), before);
    }

    private static void assertOutcome(InterruptedRun run, Set<String> before) {
        assertInstanceOf(InterruptedException.class, run.thrown(), "ended by " + run.thrown());
        assertTrue(run.millisAfterInterrupt() < BOUND_MS, run.millisAfterInterrupt() + " ms after the interrupt");
        assertFalse(run.interruptStatusAtEnd(), "InterruptedException clears the interrupt status");
        Set<String> left = new HashSet<>(InterruptedRun.liveThreads(Renderer.WORKER_NAME));
        left.removeAll(before);
        assertEquals(Set.of(), left, "the renderer's threads have ended when it returns");
    }
}
