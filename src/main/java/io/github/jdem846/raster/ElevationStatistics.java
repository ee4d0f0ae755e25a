package io.github.jdem846.raster;

/**
 * Range and count of the valid (non-NaN) cells of a DEM.
 *
 * @param min        lowest valid elevation, NaN when there is none
 * @param max        highest valid elevation, NaN when there is none
 * @param validCount number of cells that hold an elevation
 * @param totalCount number of cells
 */
public record ElevationStatistics(double min, double max, long validCount, long totalCount) {

    /** Scans {@code values}, skipping NaN. */
    public static ElevationStatistics of(float[] values) {
        float min = Float.POSITIVE_INFINITY;
        float max = Float.NEGATIVE_INFINITY;
        long valid = 0;
        for (float v : values) {
            if (v == v) {
                valid++;
                if (v < min) {
                    min = v;
                }
                if (v > max) {
                    max = v;
                }
            }
        }
        if (valid == 0) {
            return new ElevationStatistics(Double.NaN, Double.NaN, 0, values.length);
        }
        return new ElevationStatistics(min, max, valid, values.length);
    }

    /** Number of no-data cells. */
    public long noDataCount() {
        return totalCount - validCount;
    }

    /** True when no cell holds an elevation. */
    public boolean isEmpty() {
        return validCount == 0;
    }
}
