package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;

/** The [min, max] that percent stops refer to: a DEM's valid range, [0, 0] when it has no valid cell. */
record DataRange(double min, double max) {

    static DataRange of(ElevationStatistics stats) {
        if (stats.isEmpty() || (Double.isNaN(stats.min()) && Double.isNaN(stats.max()))) {
            return new DataRange(0, 0);
        }
        double min = stats.min();
        double max = stats.max();
        if (!Double.isFinite(min) || !Double.isFinite(max)) {
            throw new IllegalArgumentException("the DEM's elevations span [" + min + ", " + max + "], which is not "
                    + "finite, so percent colour stops cannot be placed; declare the no-data value (±∞ cells are "
                    + "usually an undeclared no-data marker) or use a ramp with absolute stops such as etopo1");
        }
        if (min > max) {
            throw new IllegalArgumentException("elevation statistics have min " + min + " > max " + max);
        }
        return new DataRange(min, max);
    }

    double span() {
        return max - min;
    }

    /** gdaldem's placement of a percent stop: min + (percent / 100)·(max − min). */
    double elevationAt(double percent) {
        return min + percent / 100.0 * (max - min);
    }
}
