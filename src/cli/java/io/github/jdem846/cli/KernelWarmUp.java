package io.github.jdem846.cli;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Runs a command's own stage on a small synthetic DEM on a daemon thread while the command reads its file, so that
 * the JIT has compiled the per-cell loops before the real grid arrives (in a one-shot command the kernels otherwise
 * start interpreted on the full grid: docs/performance.md, "Whole commands vs gdaldem"). The synthetic grid is of
 * the input's kind, lat/lon or projected, since some stages take another loop on each (the sweep's step length per
 * row). The warm-up stops at {@link #stop()} or after its budget, whichever comes first; any failure is ignored.
 * Runs only with {@code -Djdem846.warmUp=on} ({@link WarmUpThread}).
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

    private KernelWarmUp() {
    }

    /**
     * Starts warming {@code stage} up on a grid of {@code input}'s kind (null = the bundled sample, projected) and
     * returns at once.
     */
    static KernelWarmUp start(Stage stage, DemInput input) {
        KernelWarmUp warmUp = new KernelWarmUp();
        WarmUpThread.start("jdem846-kernel-warm-up", () -> warmUp.run(stage, input));
        return warmUp;
    }

    /** Asks the warm-up to finish its current round and stop. */
    void stop() {
        stopped.set(true);
    }

    private void run(Stage stage, DemInput input) {
        Dem dem = syntheticHills(geometryOfKind(input));
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

    /**
     * A {@link #SIZE}² grid of about 30 m cells like {@code input}'s: 1″ cells at its latitude when its CRS is
     * geographic, else metric (also when the header cannot be read: the command reports that itself).
     */
    static GridGeometry geometryLike(Path input) {
        return geometryOfKind(input == null ? null : DemInput.of(input));
    }

    /** As {@link #geometryLike(Path)} for one file or a mosaic. */
    static GridGeometry geometryOfKind(DemInput input) {
        if (input != null) {
            try {
                GridGeometry g = DemReader.inspect(input).geometry();
                CrsInfo crs = g.crs();
                if (crs != null && crs.isGeographic()) {
                    double arcSecond = 1.0 / 3600;
                    double latitude = Math.max(-80, Math.min(80, g.originY() - g.height() / 2.0 * g.cellHeight()));
                    return new GridGeometry(SIZE, SIZE, 0, latitude, arcSecond, arcSecond, crs, PixelAnchor.CORNER);
                }
            } catch (IOException | RuntimeException e) {
                // the command reads the header again and reports what is wrong
            }
        }
        return GridGeometry.metric(SIZE, SIZE, 30);
    }

    /** Rolling hills, so that every branch of a kernel that real relief takes is taken. */
    private static Dem syntheticHills(GridGeometry geometry) {
        float[] v = new float[SIZE * SIZE];
        for (int r = 0; r < SIZE; r++) {
            for (int c = 0; c < SIZE; c++) {
                v[r * SIZE + c] = (float) (500 + 120 * Math.sin(c * 0.11) * Math.cos(r * 0.07)
                        + 40 * Math.sin((c + r) * 0.23));
            }
        }
        return new Dem(v, geometry);
    }
}
