package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.InterruptedRun;
import io.github.jdem846.testing.TestDems;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Renders given one caller's {@link ForkJoinPool} ({@link RenderSettings#withPool}): several at once from several
 * threads give the same pictures as one after another on pools of their own, run on the shared pool's threads only
 * (no pool of the renderer's own), stop on interrupt as before, and leave the pool open with its parallelism.
 */
class SharedPoolTest {

    private static final String SHARED_NAME = "shared-pool-";
    private static final String OWN_WORKER_NAME = "jdem846-render-";
    private static final List<Path> DEMS = List.of(
            Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"),
            Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif"),
            Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.flt"),
            Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
    private static final Scene SCENE = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);

    private static ForkJoinPool namedPool(int parallelism) {
        return new ForkJoinPool(parallelism, p -> {
            ForkJoinWorkerThread t = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(p);
            t.setName(SHARED_NAME + t.getName());
            return t;
        }, null, false);
    }

    private static ReliefJob job(Path dem, RenderSettings execution) {
        return ReliefJob.of(dem).withScene(SCENE).withExecution(execution);
    }

    @Test
    void settingsWithAPoolTakeItsParallelismAndKeepIt() {
        ForkJoinPool pool = new ForkJoinPool(3);
        try {
            RenderSettings shared = new RenderSettings(1, 64).withPool(pool);
            assertEquals(3, shared.parallelism());
            assertEquals(64, shared.tileSize());
            assertEquals(pool, shared.withParallelism(7).pool());
            assertEquals(3, shared.withParallelism(7).parallelism());
            assertEquals(null, new RenderSettings(2, 64).pool());
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void concurrentRendersOnOneSharedPoolEqualSequentialDefaultRenders() throws Exception {
        List<int[]> sequential = new ArrayList<>();
        for (Path dem : DEMS) {
            sequential.add(job(dem, RenderSettings.defaults()).run(JobListener.NONE).argb());
        }
        ForkJoinPool pool = namedPool(2);
        ExecutorService callers = Executors.newFixedThreadPool(DEMS.size());
        try {
            RenderSettings shared = RenderSettings.defaults().withPool(pool);
            assertEquals(2, shared.parallelism(), "the pool's parallelism");
            Set<String> progressThreads = ConcurrentHashMap.newKeySet();
            JobListener threads = new JobListener() {
                @Override
                public void update(String stage, long done, long total) {
                    progressThreads.add(Thread.currentThread().getName());
                }
            };
            List<Future<int[]>> concurrent = new ArrayList<>();
            for (Path dem : DEMS) {
                concurrent.add(callers.submit(() -> job(dem, shared).run(threads).argb()));
            }
            for (int i = 0; i < DEMS.size(); i++) {
                assertArrayEquals(sequential.get(i), concurrent.get(i).get(), DEMS.get(i).toString());
            }
            assertTrue(progressThreads.stream().anyMatch(n -> n.startsWith(SHARED_NAME)),
                    "tiles ran on the shared pool: " + progressThreads);
            assertTrue(progressThreads.stream().noneMatch(n -> n.startsWith(OWN_WORKER_NAME)),
                    "no pool of the renderer's own: " + progressThreads);
            assertFalse(pool.isShutdown(), "the caller's pool is left open");
            assertEquals(2, pool.getParallelism());
        } finally {
            callers.shutdownNow();
            pool.shutdownNow();
        }
    }

    @Test
    void aRenderCancelledOnASharedPoolStopsPromptlyAndLeavesThePoolUsable() throws Exception {
        var bt = TestDems.load(TestDems.BIG_TUJUNGA);
        // Exact shadows at 5°: seconds of work, interrupted after 200 ms.
        Scene slow = Scene.defaults().withShadows(ShadowAlgorithm.EXACT).withLight(new LightDirection(300, 5));
        ForkJoinPool pool = namedPool(2);
        try {
            Renderer renderer = new Renderer(RenderSettings.defaults().withPool(pool));
            InterruptedRun run = InterruptedRun.of(() -> renderer.render(bt, slow), 200);
            assertInstanceOf(InterruptedException.class, run.thrown(), "ended by " + run.thrown());
            assertTrue(run.millisAfterInterrupt() < 500, run.millisAfterInterrupt() + " ms after the interrupt");
            assertFalse(run.interruptStatusAtEnd(), "InterruptedException clears the interrupt status");
            assertFalse(pool.isShutdown(), "the caller's pool is left open");
            assertTrue(pool.awaitQuiescence(10, TimeUnit.SECONDS), "no work of the cancelled render is left");

            Scene quick = Scene.defaults();
            assertArrayEquals(new Renderer().render(bt, quick, RenderProgress.NONE).argb(),
                    renderer.render(bt, quick).argb(), "the pool renders again afterwards");
            assertEquals(2, pool.getParallelism());
        } finally {
            pool.shutdownNow();
        }
    }
}
