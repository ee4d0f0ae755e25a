package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;

/**
 * A precomputed table of an exact tint for the whole-number elevations of a DEM's range, as gdaldem does for
 * 16-bit rasters: most DEMs are stored as integers, so most cells become one array read. Other values (fractions,
 * values outside the range, NaN) go to the exact function, so the result is always identical to it.
 */
final class IntegerLookupTint implements TintFunction {

    /** Largest table: 2^16 entries (256 KiB), enough for any 16-bit DEM. */
    static final int MAX_ENTRIES = 1 << 16;

    private final TintFunction exact;
    private final int first;
    private final int[] table;

    private IntegerLookupTint(TintFunction exact, int first, int count) {
        this.exact = exact;
        this.first = first;
        this.table = new int[count];
        for (int i = 0; i < count; i++) {
            table[i] = exact.argb(first + i);
        }
    }

    /** {@code exact} with a table over the whole numbers of {@code range}, when that range is small enough. */
    static TintFunction over(TintFunction exact, ElevationStatistics range) {
        if (range.isEmpty() || !Double.isFinite(range.min()) || !Double.isFinite(range.max())) {
            return exact;
        }
        double first = Math.ceil(range.min());
        double last = Math.floor(range.max());
        // Whole numbers up to 2^24 are exact in float32, so (int) e == e identifies them.
        if (last < first || last - first + 1 > MAX_ENTRIES || first < -(1 << 24) || last > (1 << 24)) {
            return exact;
        }
        return new IntegerLookupTint(exact, (int) first, (int) (last - first) + 1);
    }

    @Override
    public int argb(float elevation) {
        int whole = (int) elevation;
        int index = whole - first;
        if (whole == elevation && index >= 0 && index < table.length) {
            return table[index];
        }
        return exact.argb(elevation);
    }
}
