package io.github.jdem846.raster;

import java.util.Objects;

/**
 * A digital elevation model in memory: {@code width × height} float32 elevations in row-major order, row 0 = north,
 * with its {@link GridGeometry}.
 *
 * <p>No-data cells are stored as {@code NaN}, whatever value the file used; {@link #declaredNoData()} keeps that
 * value for reporting and for writing. Stages therefore test {@code Float.isNaN}. Min, max and the valid count
 * exclude no-data and are computed once, lazily and thread-safely.
 *
 * <p>Instances are immutable as long as nobody writes into {@link #backingArray()}.
 */
public final class Dem {

    private final float[] values;
    private final GridGeometry geometry;
    private final double declaredNoData;
    private volatile ElevationStatistics statistics;

    /**
     * Wraps {@code values} (not copied). Cells equal (as float32) to {@code declaredNoData} are replaced by NaN in
     * place; pass NaN when the data declares no no-data value (NaN cells are always no-data).
     *
     * @param values         elevations, row-major, row 0 = north
     * @param geometry       the grid's size, place and CRS
     * @param declaredNoData the no-data value of the source, or NaN
     * @throws IllegalArgumentException if the array length is not width × height
     */
    public Dem(float[] values, GridGeometry geometry, double declaredNoData) {
        this(values, geometry, declaredNoData, false);
    }

    private Dem(float[] values, GridGeometry geometry, double declaredNoData, boolean alreadyNormalized) {
        this.values = Objects.requireNonNull(values, "values");
        this.geometry = Objects.requireNonNull(geometry, "geometry");
        long expected = (long) geometry.width() * geometry.height();
        if (values.length != expected) {
            throw new IllegalArgumentException("expected " + expected + " values for " + geometry.width() + "×"
                    + geometry.height() + ", got " + values.length);
        }
        this.declaredNoData = declaredNoData;
        if (!alreadyNormalized) {
            NoData.normalize(values, declaredNoData);
        }
    }

    /**
     * Wraps {@code values} (not copied) whose no-data cells are already NaN, keeping {@code declaredNoData} for
     * reporting only: cells equal to it are <em>not</em> replaced. For readers that apply the no-data rule
     * before averaging, where a block mean may legitimately equal the declared value.
     *
     * @param values         elevations, row-major, NaN = no-data
     * @param geometry       the grid's size, place and CRS
     * @param declaredNoData the no-data value of the source, or NaN
     * @return the DEM
     */
    public static Dem ofNormalized(float[] values, GridGeometry geometry, double declaredNoData) {
        return new Dem(values, geometry, declaredNoData, true);
    }

    /**
     * {@link #ofNormalized(float[], GridGeometry, double)} for a reader that took the statistics of {@code values}
     * on its way (min, max and valid count of exactly these cells, as {@link ElevationStatistics#of} would give
     * them), so that {@link #statistics()} needs no pass of its own.
     *
     * @param values         elevations, row-major, NaN = no-data
     * @param geometry       the grid's size, place and CRS
     * @param declaredNoData the no-data value of the source, or NaN
     * @param statistics     the statistics of {@code values}
     * @return the DEM
     */
    public static Dem ofNormalized(float[] values, GridGeometry geometry, double declaredNoData,
                                   ElevationStatistics statistics) {
        Dem d = new Dem(values, geometry, declaredNoData, true);
        if (statistics.totalCount() != values.length) {
            throw new IllegalArgumentException("statistics of " + statistics.totalCount() + " cells for "
                    + values.length + " values");
        }
        d.statistics = statistics;
        return d;
    }

    /**
     * A DEM with no declared no-data value (NaN cells are still no-data).
     *
     * @param values   elevations, row-major, row 0 = north
     * @param geometry the grid's size, place and CRS
     */
    public Dem(float[] values, GridGeometry geometry) {
        this(values, geometry, Double.NaN);
    }

    /** @return columns */
    public int width() {
        return geometry.width();
    }

    /** @return rows */
    public int height() {
        return geometry.height();
    }

    /** @return the grid's size, place and CRS */
    public GridGeometry geometry() {
        return geometry;
    }

    /** @return the no-data value the source declared, or NaN when it declared none (or declared NaN) */
    public double declaredNoData() {
        return declaredNoData;
    }

    /**
     * Elevation of one cell. No bounds check beyond the array's.
     *
     * @param col column, 0 = west
     * @param row row, 0 = north
     * @return the elevation; NaN for no-data
     */
    public float get(int col, int row) {
        return values[row * geometry.width() + col];
    }

    /**
     * Whether a cell holds an elevation.
     *
     * @param col column, 0 = west
     * @param row row, 0 = north
     * @return true unless the cell is no-data
     */
    public boolean isValid(int col, int row) {
        return !Float.isNaN(get(col, row));
    }

    /**
     * The backing array, row-major, NaN = no-data. For fast read-only access by stages; callers must not modify
     * it.
     *
     * @return the cells
     */
    public float[] backingArray() {
        return values;
    }

    /** @return min, max and count of valid cells (computed once) */
    public ElevationStatistics statistics() {
        ElevationStatistics s = statistics;
        if (s == null) {
            s = ElevationStatistics.of(values);
            statistics = s;
        }
        return s;
    }

    /**
     * The same elevations (shared, not copied) on another geometry of the same size, e.g. with another ellipsoid;
     * this DEM when {@code g} is the same object.
     *
     * @param g the geometry, of this DEM's size
     * @return the DEM on {@code g}
     */
    public Dem withGeometry(GridGeometry g) {
        if (g == geometry) {
            return this;
        }
        if (g.width() != width() || g.height() != height()) {
            throw new IllegalArgumentException("geometry " + g.width() + "×" + g.height() + " does not fit a "
                    + width() + "×" + height() + " DEM");
        }
        Dem d = ofNormalized(values, g, declaredNoData);
        d.statistics = statistics;
        return d;
    }

    /**
     * Cells {@code [col, col+w) × [row, row+h)} as a new DEM with the matching geometry.
     *
     * @param col first column
     * @param row first row
     * @param w   columns
     * @param h   rows
     * @return the copy
     */
    public Dem crop(int col, int row, int w, int h) {
        if (col < 0 || row < 0 || w < 1 || h < 1 || col + w > width() || row + h > height()) {
            throw new IllegalArgumentException("window " + w + "×" + h + " at (" + col + ", " + row
                    + ") is not inside " + width() + "×" + height());
        }
        float[] out = new float[w * h];
        for (int r = 0; r < h; r++) {
            System.arraycopy(values, (row + r) * width() + col, out, r * w, w);
        }
        return ofNormalized(out, geometry.window(col, row, w, h), declaredNoData);
    }

    @Override
    public String toString() {
        return "Dem[" + width() + "×" + height() + ", " + geometry + "]";
    }
}
