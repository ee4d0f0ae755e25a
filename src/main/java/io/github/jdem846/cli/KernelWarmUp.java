package io.github.jdem846.cli;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Runs a command's own stage on a small synthetic DEM on a daemon thread while the command reads its file, so that
 * the JIT has compiled the per-cell loops before the real grid arrives (in a one-shot command the kernels otherwise
 * start interpreted on the full grid: docs/performance.md, "Whole commands vs gdaldem"). The warm-up stops at
 * {@link #stop()} or after its budget, whichever comes first; any failure is ignored.
 */
final class KernelWarmUp {

    /** Edge of the synthetic DEM: a few tiles' worth of cells per round. */
    private static final int SIZE = 128;
    private static final int MAX_ROUNDS = 60;
    private static final long MAX_NANOS = 600_000_000L;

    /** One round of the command's stage on the given DEM. */
    interface Stage {
        void run(Dem dem) throws Exception;
    }

    private final AtomicBoolean stopped = new AtomicBoolean();
    private final Thread thread;

    private KernelWarmUp(Stage stage) {
        thread = new Thread(() -> run(stage), "jdem846-kernel-warm-up");
        thread.setDaemon(true);
    }

    /** Starts warming {@code stage} up and returns at once. */
    static KernelWarmUp start(Stage stage) {
        KernelWarmUp warmUp = new KernelWarmUp(stage);
        warmUp.thread.start();
        return warmUp;
    }

    /** Asks the warm-up to finish its current round and stop. */
    void stop() {
        stopped.set(true);
    }

    private void run(Stage stage) {
        Dem dem = syntheticHills();
        long start = System.nanoTime();
        try {
            for (int round = 0; round < MAX_ROUNDS && !stopped.get()
                    && System.nanoTime() - start < MAX_NANOS; round++) {
                stage.run(dem);
            }
        } catch (Exception | LinkageError e) {
            // ignored: see the class comment
        }
    }

    /** Rolling hills on 30 m cells, so that every branch of a kernel that real relief takes is taken. */
    private static Dem syntheticHills() {
        float[] v = new float[SIZE * SIZE];
        for (int r = 0; r < SIZE; r++) {
            for (int c = 0; c < SIZE; c++) {
                v[r * SIZE + c] = (float) (500 + 120 * Math.sin(c * 0.11) * Math.cos(r * 0.07)
                        + 40 * Math.sin((c + r) * 0.23));
            }
        }
        return new Dem(v, GridGeometry.metric(SIZE, SIZE, 30));
    }
}
