package io.github.jdem846.tiles;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.render.StageProgress;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletionService;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One run of a {@link TilePlan} on this machine: its groups spread over the job's threads, each group's tiles
 * rendered on its thread and handed to the sink.
 */
final class PyramidRun {

    private final TilePlan plan;
    private final TileSink sink;
    private final JobListener listener;

    PyramidRun(TilePlan plan, TileSink sink, JobListener listener) {
        this.plan = plan;
        this.sink = sink;
        this.listener = listener;
    }

    TileReport execute(Path output, TileFormat format) throws IOException, InterruptedException {
        List<TileGroup> groups = plan.groups();
        Map<Integer, Long> written = new ConcurrentHashMap<>();
        AtomicLong bytes = new AtomicLong();
        long all = plan.tileCount();
        StageProgress progress = new StageProgress(listener, "tiles", all).start();
        AtomicInteger threadNumber = new AtomicInteger();
        List<Thread> threads = new CopyOnWriteArrayList<>();
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(plan.job().execution().parallelism(),
                Math.max(1, groups.size())), r -> {
                    Thread t = new Thread(r, "jdem846-tiles-" + threadNumber.incrementAndGet());
                    t.setDaemon(true);
                    threads.add(t);
                    return t;
                });
        CompletionService<Void> completion = new ExecutorCompletionService<>(pool);
        List<Future<Void>> futures = new ArrayList<>();
        try {
            for (TileGroup g : groups) {
                futures.add(completion.submit(() -> {
                    for (EncodedTile t : plan.render(g)) {
                        sink.write(t.tile(), t.png());
                        written.merge(g.z(), 1L, Long::sum);
                        bytes.addAndGet(t.png().length);
                    }
                    progress.add(g.size());
                    return null;
                }));
            }
            for (int i = 0; i < futures.size(); i++) {
                Future<Void> f = completion.take();
                try {
                    f.get();
                } catch (ExecutionException e) {
                    throw rethrow(e.getCause());
                }
            }
        } finally {
            pool.shutdownNow();
            boolean interrupted = Thread.interrupted();
            try {
                while (!pool.awaitTermination(10, TimeUnit.SECONDS)) {
                    // the workers stop at their next tile or stage check
                }
                for (Thread t : threads) {
                    t.join();   // terminated, but a worker may still be ending: none is left when this returns
                }
            } catch (InterruptedException e) {
                interrupted = true;
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
        if (Thread.interrupted()) {
            throw new InterruptedException();
        }
        return plan.report(output, format, written, bytes.get());
    }

    private static IOException rethrow(Throwable cause) throws IOException, InterruptedException {
        if (cause instanceof IOException e) {
            throw e;
        }
        if (cause instanceof UncheckedIOException e) {
            throw e.getCause();
        }
        if (cause instanceof InterruptedException e) {
            throw e;
        }
        if (cause instanceof RuntimeException e) {
            throw e;
        }
        if (cause instanceof Error e) {
            throw e;
        }
        return new IOException(cause);
    }
}
