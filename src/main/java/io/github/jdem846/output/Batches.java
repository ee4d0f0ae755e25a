package io.github.jdem846.output;

import java.io.IOException;
import java.util.function.IntFunction;
import java.util.stream.IntStream;

/**
 * Independent pieces of work (compressing PNG segments, TIFF strips, COG tiles) done in batches, a batch at a time
 * on all processors when asked (the pool of the calling thread: the common ForkJoinPool or the one it runs in),
 * their results handed on in order. A batch bounds the results held before they are written; neither the batches
 * nor the threads change the results.
 */
final class Batches {

    /** Takes the results in order. */
    @FunctionalInterface
    interface Consumer<T> {
        void accept(T result) throws IOException;
    }

    private Batches() {
    }

    /** Pieces per batch: {@code perProcessor} per processor, at most {@code max}; 1 when not parallel. */
    static int size(boolean parallel, int perProcessor, int max) {
        return parallel ? Math.max(1, Math.min(max, perProcessor * Runtime.getRuntime().availableProcessors())) : 1;
    }

    /** Computes {@code work(0 … count − 1)}, {@code batch} at a time, and hands each result to {@code sink}. */
    static <T> void run(int count, int batch, boolean parallel, IntFunction<T> work, Consumer<T> sink)
            throws IOException {
        for (int first = 0; first < count; first += batch) {
            int start = first;
            int end = (int) Math.min(count, (long) first + batch);
            Object[] done = new Object[end - start];
            IntStream range = IntStream.range(start, end);
            (parallel && end - start > 1 ? range.parallel() : range).forEach(i -> done[i - start] = work.apply(i));
            for (Object result : done) {
                @SuppressWarnings("unchecked")
                T t = (T) result;
                sink.accept(t);
            }
        }
    }
}
