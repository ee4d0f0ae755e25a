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
 * <p>A grid enlarged from a coarser one may also carry a coverage per cell ({@link #coverage}): the share of the
 * cell that is data, between 0 and 1, with which the edges of no-data are anti-aliased.
 *
 * <p>Instances are immutable as long as nobody writes into {@link #backingArray()}.
 */
public final class Dem {

    private final float[] values;
    private final GridGeometry geometry;
    private final double declaredNoData;
    /** The share of each cell that is data, or null: 1 for every cell that is data, 0 for no-data. */
    private final float[] coverage;
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
        this(values, geometry, declaredNoData, alreadyNormalized, null);
    }

    private Dem(float[] values, GridGeometry geometry, double declaredNoData, boolean alreadyNormalized,
                float[] coverage) {
        this.coverage = coverage;
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

    /** {@return columns} */
    public int width() {
        return geometry.width();
    }

    /** {@return rows} */
    public int height() {
        return geometry.height();
    }

    /** {@return the grid's size, place and CRS} */
    public GridGeometry geometry() {
        return geometry;
    }

    /** {@return the no-data value the source declared, or NaN when it declared none (or declared NaN)} */
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

    /** {@return min, max and count of valid cells (computed once)} */
    public ElevationStatistics statistics() {
        ElevationStatistics s = statistics;
        if (s == null) {
            s = ElevationStatistics.of(values);
            statistics = s;
        }
        return s;
    }

    /**
     * Whether every cell is known to be a finite number without looking at the cells: the statistics are known
     * already (a reader took them on its way, or {@link #statistics()} ran) and count no no-data, with a finite
     * min and max. False says nothing: the cells may still all be finite.
     *
     * @return true when every cell is finite, as far as is known for free
     */
    public boolean knownAllFinite() {
        ElevationStatistics s = statistics;
        return s != null && s.validCount() == s.totalCount() && Double.isFinite(s.min())
                && Double.isFinite(s.max());
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
        Dem d = new Dem(values, g, declaredNoData, true, coverage);
        d.statistics = statistics;
        return d;
    }

    /**
     * This DEM with a coverage per cell (an enlarged grid's anti-aliased no-data edges).
     *
     * @param shares the share of each cell that is data, 0 to 1, row-major (not copied); 0 where a cell is
     *               no-data
     * @return the DEM with that coverage
     * @throws IllegalArgumentException when the array is not one value per cell
     */
    public Dem withCoverage(float[] shares) {
        if (shares.length != values.length) {
            throw new IllegalArgumentException("expected " + values.length + " coverage values, got "
                    + shares.length);
        }
        Dem d = new Dem(values, geometry, declaredNoData, true, shares);
        d.statistics = statistics;
        return d;
    }

    /**
     * The share of a cell that is data: from {@link #withCoverage} when given, else 1 for data and 0 for no-data.
     *
     * @param col column
     * @param row row
     * @return 0 to 1
     */
    public float coverage(int col, int row) {
        int i = row * width() + col;
        return coverage != null ? coverage[i] : Float.isNaN(values[i]) ? 0 : 1;
    }

    /** {@return true when the DEM carries a coverage of its own ({@link #withCoverage})} */
    public boolean hasCoverage() {
        return coverage != null;
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
        float[] shares = coverage == null ? null : new float[w * h];
        for (int r = 0; r < h; r++) {
            System.arraycopy(values, (row + r) * width() + col, out, r * w, w);
            if (shares != null) {
                System.arraycopy(coverage, (row + r) * width() + col, shares, r * w, w);
            }
        }
        return new Dem(out, geometry.window(col, row, w, h), declaredNoData, true, shares);
    }

    @Override
    public String toString() {
        return "Dem[" + width() + "×" + height() + ", " + geometry + "]";
    }
}
