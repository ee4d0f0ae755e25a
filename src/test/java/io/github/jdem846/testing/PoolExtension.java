package io.github.jdem846.testing;

import java.util.concurrent.ForkJoinPool;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * A ForkJoinPool shared by the tests of one class: created before the first test, shut down after the last.
 * Register it as {@code @RegisterExtension static final PoolExtension POOL = new PoolExtension(2);} and use
 * {@link #get()} in the tests.
 */
public final class PoolExtension implements BeforeAllCallback, AfterAllCallback {

    private final int parallelism;
    private ForkJoinPool pool;

    public PoolExtension(int parallelism) {
        this.parallelism = parallelism;
    }

    /** The pool of the running test class. */
    public ForkJoinPool get() {
        if (pool == null) {
            throw new IllegalStateException("the pool exists only while its test class runs");
        }
        return pool;
    }

    @Override
    public void beforeAll(ExtensionContext context) {
        pool = new ForkJoinPool(parallelism);
    }

    @Override
    public void afterAll(ExtensionContext context) {
        pool.shutdownNow();
        pool = null;
    }
}
