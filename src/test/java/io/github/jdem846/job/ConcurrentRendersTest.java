package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.InterruptedRun;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.ZoomRange;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The library used from many threads of one JVM: renders of {@link ReliefJob}, one shared {@link Renderer} and
 * {@link TileJob} started together on eight threads give, byte for byte, what the same renders give one after
 * another; a render or tile job stopped by interrupting its thread leaves none of its threads alive when it
 * returns (with a caller's pool, the pool idle and usable), no file behind, and its memory free again.
 */
class ConcurrentRendersTest {

    /** The name prefixes of every thread the library starts: the renderer's, the tile runner's, the reader's. */
    private static final List<String> WORKERS = List.of("jdem846-render-", "jdem846-tiles-", "jdem846-read");
    private static final List<Path> DEMS = List.of(
            Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"),
            Path.of("testdata/dem/luxembourg_srtm30s_wgs84.flt"),
            Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif"),
            Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
    private static final Scene SWEEP = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
    private static final Scene HORN_LOW_SUN = Scene.defaults().withHillshade(HillshadeMethod.HORN)
            .withShadows(ShadowAlgorithm.MARCH).withLight(new LightDirection(135, 12));

    @TempDir
    Path tmp;

    /** One piece of work whose result is compared as bytes. */
    private interface Work {
        byte[] run(int turn) throws Exception;
    }

    private static byte[] bytes(int[] argb) {
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(argb.length * 4);
        b.asIntBuffer().put(argb);
        return b.array();
    }

    private List<Work> works() {
        List<Work> works = new ArrayList<>();
        RenderSettings twoThreads = new RenderSettings(2, 128);
        for (Path dem : DEMS) {
            works.add(turn -> bytes(ReliefJob.of(dem).withScene(SWEEP).withExecution(twoThreads)
                    .run(JobListener.NONE).argb()));
        }
        Renderer shared = new Renderer(twoThreads);
        Dem bt = TestDems.load(TestDems.BIG_TUJUNGA);
        Dem lux = TestDems.load(TestDems.LUXEMBOURG);
        works.add(turn -> bytes(shared.render(bt, HORN_LOW_SUN).argb()));
        works.add(turn -> bytes(shared.render(lux, HORN_LOW_SUN).argb()));
        for (Path dem : List.of(DEMS.get(0), DEMS.get(3))) {
            works.add(turn -> {
                Path out = tmp.resolve(dem.getFileName() + "-" + turn + ".pmtiles");
                TileJob.of(dem, new ZoomRange(9, 11)).withScene(SWEEP).withExecution(twoThreads)
                        .run(out, JobListener.NONE);
                return Files.readAllBytes(out);
            });
        }
        return works;
    }

    @Test
    void eightRendersStartedTogetherEqualTheSameRendersOneAfterAnother() throws Exception {
        List<Work> works = works();
        List<byte[]> sequential = new ArrayList<>();
        for (Work w : works) {
            sequential.add(w.run(0));
        }
        ExecutorService callers = Executors.newFixedThreadPool(works.size());
        try {
            CountDownLatch start = new CountDownLatch(1);
            List<Future<byte[]>> concurrent = new ArrayList<>();
            for (Work w : works) {
                concurrent.add(callers.submit(() -> {
                    start.await();
                    return w.run(1);
                }));
            }
            start.countDown();
            for (int i = 0; i < works.size(); i++) {
                assertArrayEquals(sequential.get(i), concurrent.get(i).get(), "work " + i);
            }
        } finally {
            callers.shutdownNow();
        }
    }

    private static Set<String> liveWorkers() {
        Set<String> live = new HashSet<>();
        for (String prefix : WORKERS) {
            live.addAll(InterruptedRun.liveThreads(prefix));
        }
        return live;
    }

    private static void assertNoNewWorkers(Set<String> before, String what) {
        Set<String> left = new HashSet<>(liveWorkers());
        left.removeAll(before);
        assertEquals(Set.of(), left, what + ": the library's threads have ended when it returns");
    }

    /** Exact shadows of Big Tujunga at a low sun: seconds of work, interrupted after {@code delay} ms. */
    @Test
    void aReliefJobInterruptedAtAnyPointLeavesNoThreadAndNoFile() throws Exception {
        ReliefJob job = ReliefJob.of(DEMS.get(0)).withExecution(new RenderSettings(2, 128))
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.EXACT).withLight(new LightDirection(300, 5)));
        for (long delay : new long[] {0, 5, 30, 300}) {
            Path out = tmp.resolve("cancelled-" + delay + ".tif");
            Set<String> before = liveWorkers();
            InterruptedRun run = InterruptedRun.of(() -> job.runAndWrite(out,
                    io.github.jdem846.output.WriteOptions.defaults(), JobListener.NONE), delay);
            assertStopped(run, "interrupted after " + delay + " ms");
            assertNoNewWorkers(before, "interrupted after " + delay + " ms");
            assertEquals(List.of(), listing(tmp), "nothing written");
        }
    }

    @Test
    void aTileJobInterruptedLeavesNoThreadNoFileAndItsSharedPoolIdle() throws Exception {
        ForkJoinPool pool = new ForkJoinPool(2);
        try {
            TileJob job = TileJob.of(DEMS.get(0), new ZoomRange(9, 12))
                    .withScene(Scene.defaults().withShadows(ShadowAlgorithm.EXACT))
                    .withSun(Sun.fixed(300, 5));
            for (RenderSettings execution : List.of(new RenderSettings(2, 128),
                    RenderSettings.defaults().withPool(pool))) {
                for (long delay : new long[] {5, 300}) {
                    String what = (execution.pool() != null ? "shared pool" : "own threads") + ", after " + delay
                            + " ms";
                    Set<String> before = liveWorkers();
                    Path out = tmp.resolve("tiles.pmtiles");
                    InterruptedRun run = InterruptedRun.of(() -> job.withExecution(execution).run(out,
                            JobListener.NONE), delay);
                    assertStopped(run, what);
                    assertNoNewWorkers(before, what);
                    assertEquals(List.of(), listing(tmp), what + ": nothing written");
                    assertFalse(pool.isShutdown(), what);
                    assertTrue(pool.awaitQuiescence(10, TimeUnit.SECONDS), what + ": no work left on the pool");
                    assertEquals(0, pool.getActiveThreadCount(), what + ": the pool is idle");
                }
            }
            // the pool renders again, the same tiles as threads of the job's own
            Path a = tmp.resolve("own.pmtiles");
            Path b = tmp.resolve("shared.pmtiles");
            TileJob quick = TileJob.of(DEMS.get(0), new ZoomRange(9, 10));
            quick.withExecution(new RenderSettings(2, 128)).run(a, JobListener.NONE);
            quick.withExecution(RenderSettings.defaults().withPool(pool)).run(b, JobListener.NONE);
            assertArrayEquals(Files.readAllBytes(a), Files.readAllBytes(b));
        } finally {
            pool.shutdownNow();
        }
    }

    /**
     * A render interrupted while it shades, when its picture (int per pixel) and shadow layer (float per cell) of
     * 12.3 million cells, 98 MB together, are allocated: once it has thrown, a garbage collection brings the heap
     * back to where it was before the render, within 16 MB, on its own pool and on a shared one.
     */
    @Test
    void anInterruptedRenderReleasesItsMemory() throws Exception {
        Dem bt = TestDems.load(TestDems.BIG_TUJUNGA);
        Dem large = SyntheticDems.mirrored(bt, 4 * bt.width(), 4 * bt.height());
        Scene scene = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
        ForkJoinPool pool = new ForkJoinPool(2);
        try {
            for (RenderSettings execution : List.of(new RenderSettings(2, 256),
                    RenderSettings.defaults().withPool(pool))) {
                long baseline = usedAfterGc();
                Thread caller = Thread.currentThread();
                AtomicBoolean interrupted = new AtomicBoolean();
                RenderProgress interruptWhileShading = (stage, done, total) -> {
                    if (stage.equals("shading") && done > 0 && interrupted.compareAndSet(false, true)) {
                        caller.interrupt();
                    }
                };
                Throwable thrown = null;
                try {
                    new Renderer(execution).render(large, scene, interruptWhileShading);
                } catch (InterruptedException e) {
                    thrown = e;
                }
                assertTrue(interrupted.get(), "interrupted while shading");
                assertInstanceOf(InterruptedException.class, thrown);
                long after = usedAfterGc();
                assertTrue(after - baseline < 16L << 20, (execution.pool() != null ? "shared pool" : "own pool")
                        + ": " + (after - baseline) / 1e6 + " MB more in use than before the render");
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static long usedAfterGc() throws InterruptedException {
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        long used = Long.MAX_VALUE;
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
            used = Math.min(used, memory.getHeapMemoryUsage().getUsed());
        }
        return used;
    }

    private static void assertStopped(InterruptedRun run, String what) {
        assertInstanceOf(InterruptedException.class, run.thrown(), what + ": ended by " + run.thrown());
        assertFalse(run.interruptStatusAtEnd(), what + ": InterruptedException clears the interrupt status");
    }

    private static List<Path> listing(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.toList();
        }
    }
}
