package io.github.jdem846.tint;

/** A percent ramp bound to a DEM's range: eq. 1 turns an elevation into the ratio a, the stop table does the rest. */
final class RatioTint implements TintFunction {

    private final StopTable table;
    private final double min;
    private final double max;
    private final double span;

    /** @param table stops at ratios in [0, 1] (percent / 100) */
    RatioTint(StopTable table, DataRange range) {
        this.table = table;
        this.min = range.min();
        this.max = range.max();
        this.span = range.span();
    }

    @Override
    public int argb(float elevation) {
        return table.argb(ratio(elevation));
    }

    /**
     * eq. 1: a = (elevation − minimum) / (maximum − minimum). On a flat DEM (maximum = minimum) the ratio of its one
     * elevation is 0; anything below or above it lies beyond the ends. NaN stays NaN (no-data).
     */
    double ratio(double elevation) {
        if (span > 0 || elevation != elevation) {
            return (elevation - min) / span;
        }
        return elevation < min ? Double.NEGATIVE_INFINITY : elevation > max ? Double.POSITIVE_INFINITY : 0;
    }
}
