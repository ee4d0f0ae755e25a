package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.InterruptedRun;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.TestDems;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link ShadowAlgorithm#compute} alone stops promptly when its calling thread is interrupted, inside the long
 * stage itself: each case runs for seconds uninterrupted (two threads of a 2-core machine, warm, idle to loaded:
 * exact on Big Tujunga at 5° 3.7–23 s, the soft sweep on Big Tujunga mirror-tiled 4 × 4 1.1–2.5 s in one walk and
 * 5–11 s level by level (thin features), the soft march at 2° 2 s), is interrupted after 200 ms and must end with
 * {@link CancellationException} within 500 ms, interrupt status set, leaving the pool idle so that it shuts down at
 * once.
 */
class ShadowCancellationTest {

    private static final long INTERRUPT_AFTER_MS = 200;
    private static final double BOUND_MS = 500;

    private static final Dem BT = TestDems.load(TestDems.BIG_TUJUNGA);
    private static final Dem BT_4X4 = SyntheticDems.mirrored(BT, 4 * BT.width(), 4 * BT.height());

    /** One way of calling the library on {@code pool} (or on the common pool). */
    @FunctionalInterface
    private interface Call {
        Object run(ForkJoinPool pool);
    }

    static Stream<Arguments> longComputations() {
        LightDirection five = new LightDirection(300, 5);
        ShadowOptions soft = ShadowOptions.DEFAULTS.withSoftShadows(true);
        int[] allCells = IntStream.range(0, BT.width() * BT.height()).toArray();
        return Stream.of(
                Arguments.of("exact, Big Tujunga, 5°", (Call) pool ->
                        ShadowAlgorithm.EXACT.compute(BT, five, ShadowOptions.DEFAULTS, pool)),
                Arguments.of("exact, the common pool", (Call) pool ->
                        ShadowAlgorithm.EXACT.compute(BT, five, ShadowOptions.DEFAULTS)),
                Arguments.of("exact, computeCells of every cell", (Call) pool ->
                        ShadowAlgorithm.EXACT.computeCells(BT, five, ShadowOptions.DEFAULTS, pool, allCells)),
                Arguments.of("soft sweep in one walk, mirrored 4 × 4", (Call) pool ->
                        ShadowAlgorithm.SWEEP.compute(BT_4X4, five, soft, pool)),
                Arguments.of("soft sweep level by level (thin features), mirrored 4 × 4", (Call) pool ->
                        ShadowAlgorithm.SWEEP.compute(BT_4X4, five, soft.withThinFeatures(true), pool)),
                Arguments.of("soft march, 2°", (Call) pool ->
                        ShadowAlgorithm.MARCH.compute(BT, new LightDirection(300, 2), soft, pool)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("longComputations")
    void anInterruptStopsTheComputationPromptly(String name, Call call) throws InterruptedException {
        // a pool of its own, not a PoolExtension: the test records its worker threads and watches them end
        List<Thread> workers = new CopyOnWriteArrayList<>();
        ForkJoinPool pool = new ForkJoinPool(2, p -> {
            ForkJoinWorkerThread t = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(p);
            workers.add(t);
            return t;
        }, null, false);
        try {
            InterruptedRun run = InterruptedRun.of(() -> call.run(pool), INTERRUPT_AFTER_MS);
            assertInstanceOf(CancellationException.class, run.thrown(), "ended by " + run.thrown());
            assertTrue(run.millisAfterInterrupt() < BOUND_MS, run.millisAfterInterrupt() + " ms after the interrupt");
            assertTrue(run.interruptStatusAtEnd(), "the interrupt status stays set");
            assertTrue(pool.isQuiescent() || pool.awaitQuiescence(50, TimeUnit.MILLISECONDS),
                    "no part of the computation left running");
        } finally {
            pool.shutdown();
        }
        assertTrue(pool.awaitTermination(1, TimeUnit.SECONDS), "the pool shuts down at once");
        for (Thread t : workers) {
            t.join(1000);
            assertFalse(t.isAlive(), t.getName() + " still running");
        }
    }
}
