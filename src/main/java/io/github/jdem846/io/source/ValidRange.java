package io.github.jdem846.io.source;

import io.github.jdem846.raster.ElevationStatistics;

/**
 * Turns decoded cells into elevations in place, a row at a time, and takes their statistics on the way: the
 * declared no-data value becomes NaN, then the {@link ValueScale} applies, then min, max and valid count are
 * updated. One pass over cells just decoded (still in the processor's cache), in a method short and often called
 * enough to be compiled early in a cold JVM. Not thread-safe: one per read.
 */
final class ValidRange {

    private final boolean hasNoData;
    private final float noData;
    private final ValueScale scale;
    private float min = Float.POSITIVE_INFINITY;
    private float max = Float.NEGATIVE_INFINITY;
    private long valid;

    /**
     * @param noData      the declared no-data value as float32 ({@code hasNoData} false: none)
     * @param hasNoData   whether there is one
     * @param scale       how stored values unpack
     */
    ValidRange(float noData, boolean hasNoData, ValueScale scale) {
        this.noData = noData;
        this.hasNoData = hasNoData;
        this.scale = scale;
    }

    /** Applies the no-data rule and the scale to {@code cells[from, to)} in place and counts them. */
    void take(float[] cells, int from, int to) {
        if (!scale.isIdentity()) {
            unpack(cells, from, to);
        } else if (hasNoData) {
            takeWithNoData(cells, from, to);
        } else {
            takeAll(cells, from, to);
        }
    }

    private void takeWithNoData(float[] cells, int from, int to) {
        float nd = noData;
        float lo = min;
        float hi = max;
        long n = valid;
        for (int i = from; i < to; i++) {
            float v = cells[i];
            if (v == nd) {
                cells[i] = Float.NaN;
            } else if (v == v) {
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
                n++;
            }
        }
        min = lo;
        max = hi;
        valid = n;
    }

    private void takeAll(float[] cells, int from, int to) {
        float lo = min;
        float hi = max;
        long n = valid;
        for (int i = from; i < to; i++) {
            float v = cells[i];
            if (v == v) {
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
                n++;
            }
        }
        min = lo;
        max = hi;
        valid = n;
    }

    /** The rare case of a GDAL scale or offset: the same rule, cell by cell, then the unpacking. */
    private void unpack(float[] cells, int from, int to) {
        double s = scale.scale();
        double o = scale.offset();
        for (int i = from; i < to; i++) {
            float v = cells[i];
            if (hasNoData && v == noData) {
                cells[i] = Float.NaN;
                continue;
            }
            v = (float) (v * s + o);
            cells[i] = v;
            if (v == v) {
                min = v < min ? v : min;
                max = v > max ? v : max;
                valid++;
            }
        }
    }

    /** The statistics of the cells taken, {@code total} of them in all. */
    ElevationStatistics statistics(long total) {
        return ElevationStatistics.ofRange(min, max, valid, total);
    }
}
