package io.github.jdem846.render;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The progress of one stage, counted by any number of threads and passed on to a {@link RenderProgress} as the
 * contract says: {@code done} only grows, never passes {@code total}, and the stage ends with {@code done == total}
 * ({@link #finish()}). Updates are thinned to about {@value #STEPS} per stage, so that counting per row costs one
 * atomic addition; the listener is called under this object's lock, never by two threads at once for this stage.
 */
public final class StageProgress {

    /** About how many updates a stage reports at most (one per step of total / STEPS units, and the last). */
    public static final int STEPS = 200;

    private final RenderProgress progress;
    private final String stage;
    private final long total;
    private final long step;
    private final AtomicLong done = new AtomicLong();
    private long reported = -1;

    /**
     * Counts the progress of {@code stage} for {@code progress}; the constructor reports nothing.
     *
     * @param progress told of the stage
     * @param stage    the stage's name
     * @param total    units in the stage, ≥ 0
     */
    public StageProgress(RenderProgress progress, String stage, long total) {
        this.progress = Objects.requireNonNull(progress, "progress");
        this.stage = Objects.requireNonNull(stage, "stage");
        if (total < 0) {
            throw new IllegalArgumentException("a stage's total must be ≥ 0, got " + total);
        }
        this.total = total;
        this.step = Math.max(1, total / STEPS);
    }

    /**
     * Reports {@code 0 / total}, the stage's start.
     *
     * @return this
     */
    public StageProgress start() {
        report(0);
        return this;
    }

    /**
     * Counts {@code units} more done (from any thread); reports when a step is passed.
     *
     * @param units finished units, ≥ 0
     */
    public void add(long units) {
        long now = done.addAndGet(units);
        if (now / step != (now - units) / step || now >= total) {
            report(now);
        }
    }

    /**
     * Reports {@code done} units finished in all, when more than reported so far (for work that counts itself).
     *
     * @param doneSoFar units finished in all
     */
    public void reached(long doneSoFar) {
        long before = done.getAndAccumulate(doneSoFar, Math::max);
        if (doneSoFar > before && (doneSoFar / step != before / step || doneSoFar >= total)) {
            report(doneSoFar);
        }
    }

    /** Reports {@code total / total}: the stage is done. */
    public void finish() {
        report(total);
    }

    /** {@return the stage's units in all} */
    public long total() {
        return total;
    }

    private synchronized void report(long value) {
        long v = Math.min(value, total);
        if (v > reported) {
            reported = v;
            progress.update(stage, v, total);
        }
    }
}
