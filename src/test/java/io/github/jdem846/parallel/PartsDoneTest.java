package io.github.jdem846.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.testing.PoolExtension;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/** The count of parts done that {@link Cancellation#invokeAll(ForkJoinPool, int, Cancellation.Part,
 * java.util.function.IntConsumer)} reports. */
class PartsDoneTest {

    @RegisterExtension
    static final PoolExtension POOLS = new PoolExtension(1, 3);

    @Test
    void everyCountFromOneToThePartsComesOnceInOrderOnAnyPool() {
        for (ForkJoinPool pool : new ForkJoinPool[] {POOLS.get(1), POOLS.get(3), ForkJoinPool.commonPool()}) {
            for (int parts : new int[] {0, 1, 7, 500}) {
                List<Integer> counts = new ArrayList<>();
                Cancellation.invokeAll(pool, parts, (i, c) -> Thread.onSpinWait(), counts::add);
                assertEquals(IntStream.rangeClosed(1, parts).boxed().toList(), counts, parts + " parts");
            }
        }
    }
}
