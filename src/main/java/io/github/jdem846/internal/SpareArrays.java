package io.github.jdem846.internal;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.IntFunction;
import java.util.function.ToIntFunction;

/**
 * Arrays handed back after use, so that the pieces of one job (tiles of a picture, segments of a PNG) reuse as many
 * arrays as are in use at once instead of allocating one each: fresh heap costs the operating system a page fault
 * and a cleared page per 4 KiB, which a one-shot command pays in full (64 MB of tiles for a 4000² hillshade).
 * Thread-safe; an array taken holds whatever its last user left in it.
 *
 * @param <T> the array type
 */
public final class SpareArrays<T> {

    private final ConcurrentLinkedQueue<T> spare = new ConcurrentLinkedQueue<>();
    private final IntFunction<T> create;
    private final ToIntFunction<T> length;

    private SpareArrays(IntFunction<T> create, ToIntFunction<T> length) {
        this.create = create;
        this.length = length;
    }

    /** Spare {@code float[]}. */
    public static SpareArrays<float[]> floats() {
        return new SpareArrays<>(float[]::new, a -> a.length);
    }

    /** Spare {@code byte[]}. */
    public static SpareArrays<byte[]> bytes() {
        return new SpareArrays<>(byte[]::new, a -> a.length);
    }

    /**
     * An array of at least {@code minLength} elements, not cleared.
     *
     * @param minLength the elements needed
     * @return a spare array if the next one is long enough, else a new one
     */
    public T take(int minLength) {
        T array = spare.poll();
        return array != null && length.applyAsInt(array) >= minLength ? array : create.apply(minLength);
    }

    /** Hands {@code array} back for a later {@link #take}; the caller no longer uses it. */
    public void give(T array) {
        spare.offer(array);
    }
}
