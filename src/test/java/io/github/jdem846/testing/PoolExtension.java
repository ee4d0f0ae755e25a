package io.github.jdem846.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * ForkJoinPools shared by the tests of one class: created before the first test, shut down after the last.
 * Register it as {@code @RegisterExtension static final PoolExtension POOL = new PoolExtension(2);} and use
 * {@link #get()} in the tests; a class that compares pool sizes registers {@code new PoolExtension(1, 2, 3)} and
 * takes {@link #all()} or {@link #get(int)}.
 */
public final class PoolExtension implements BeforeAllCallback, AfterAllCallback {

    private final int[] parallelisms;
    private List<ForkJoinPool> pools;

    /** One pool per parallelism given, in that order; at least one. */
    public PoolExtension(int... parallelisms) {
        if (parallelisms.length == 0) {
            throw new IllegalArgumentException("give the parallelism of at least one pool");
        }
        this.parallelisms = parallelisms.clone();
    }

    /** The (first) pool of the running test class. */
    public ForkJoinPool get() {
        return all().get(0);
    }

    /** The pool of the running test class with {@code parallelism} threads. */
    public ForkJoinPool get(int parallelism) {
        for (ForkJoinPool p : all()) {
            if (p.getParallelism() == parallelism) {
                return p;
            }
        }
        throw new IllegalArgumentException("no pool of " + parallelism + " threads registered");
    }

    /** The pools of the running test class, in the order of their parallelisms. */
    public List<ForkJoinPool> all() {
        if (pools == null) {
            throw new IllegalStateException("the pools exist only while their test class runs");
        }
        return pools;
    }

    @Override
    public void beforeAll(ExtensionContext context) {
        List<ForkJoinPool> created = new ArrayList<>();
        for (int p : parallelisms) {
            created.add(new ForkJoinPool(p));
        }
        pools = List.copyOf(created);
    }

    @Override
    public void afterAll(ExtensionContext context) {
        for (ForkJoinPool p : pools) {
            p.shutdownNow();
        }
        pools = null;
    }
}
