package io.github.jdem846.raster;

/**
 * Range and count of the valid (non-NaN) cells of a DEM.
 *
 * @param min        lowest valid elevation, NaN when there is none
 * @param max        highest valid elevation, NaN when there is none
 * @param validCount number of cells that hold an elevation
 * @param totalCount number of cells
 * @serial exclude
 */
public record ElevationStatistics(double min, double max, long validCount, long totalCount)
        implements java.io.Serializable {

    private static final long serialVersionUID = 1L;

    /**
     * Scans cells, skipping NaN.
     *
     * @param values the cells
     * @return their statistics
     */
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
        return ofRange(min, max, valid, values.length);
    }

    /**
     * Statistics already taken.
     *
     * @param min   lowest valid elevation (ignored when none is valid)
     * @param max   highest valid elevation (ignored when none is valid)
     * @param valid number of cells that hold an elevation
     * @param total number of cells
     * @return the statistics, with NaN bounds when no cell is valid
     */
    public static ElevationStatistics ofRange(double min, double max, long valid, long total) {
        return valid == 0 ? new ElevationStatistics(Double.NaN, Double.NaN, 0, total)
                : new ElevationStatistics(min, max, valid, total);
    }

    /**
     * The statistics of two sets of cells together.
     *
     * @param other the statistics of the other cells
     * @return the statistics of both
     */
    public ElevationStatistics merge(ElevationStatistics other) {
        if (other.isEmpty()) {
            return new ElevationStatistics(min, max, validCount, totalCount + other.totalCount);
        }
        if (isEmpty()) {
            return new ElevationStatistics(other.min, other.max, other.validCount, totalCount + other.totalCount);
        }
        return new ElevationStatistics(Math.min(min, other.min), Math.max(max, other.max),
                validCount + other.validCount, totalCount + other.totalCount);
    }

    /** {@return the number of no-data cells} */
    public long noDataCount() {
        return totalCount - validCount;
    }

    /** {@return true when no cell holds an elevation} */
    public boolean isEmpty() {
        return validCount == 0;
    }
}
