package io.github.jdem846.shadow;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;

/**
 * The sky-view factor of every cell: the share of the sky a cell sees, from the horizons in D azimuths (Zakšek,
 * Oštir and Kokalj 2011):
 *
 * <pre>    SVF = 1 − (1/D) · Σ sin φ_d,    φ_d = max(0°, the horizon's elevation angle in azimuth d)</pre>
 *
 * <p>1 on a flat plane and on a peak, lower in valleys and pits; at the bottom of a V-shaped valley whose walls rise
 * at β, φ_d = atan(|sin(d − valley azimuth)|·tan β). Terrain beyond the grid is a horizon at 0°. Each azimuth is one
 * O(cells) sweep ({@link HorizonSweep}): lines parallel to it, one cell apart, each carrying the upper convex hull of
 * its terrain; distances in ground metres per row, so lat/lon grids are measured right at every latitude. The
 * horizon angle is measured on the bilinear surface along the lines and interpolated between the two lines around
 * a cell; on the axes and diagonals it is exact. No-data cells get NaN; no-data terrain is skipped. With a search
 * radius ({@link SkyViewOptions#radius()}) only terrain within it counts ({@link WindowedHulls}), and a piece of the
 * grid read with {@link #haloCells} around it gives the whole grid's factors.
 *
 * <p>Work: D sweeps of the grid; azimuths one after another, each split into blocks of lines on the pool. The result
 * does not depend on the thread count. Interrupting the calling thread stops the work ({@link CancellationException}).
 */
public final class SkyView {

    /**
     * Cells of terrain read around a window or a tile for its sky-view factor without a search radius: a grid read
     * in pieces sees horizons this far beyond each piece (the whole grid is seen when it is read whole).
     */
    public static final int HALO_CELLS = 128;

    private SkyView() {
    }

    /**
     * The cells of terrain to read around a window or a tile of {@code grid} for its sky-view factor: {@link
     * #HALO_CELLS} without a search radius; with one, the radius in cells of the grid's smallest ground size and 2
     * more (a bilinear sample's second cell and the cell's first step), so that the piece's factor equals that of
     * the whole grid, whose horizons then lie within the halo.
     *
     * @param grid    the grid the piece is cut from (its rows give the cells' ground sizes)
     * @param options the directions, height scale and search radius
     * @return the halo in cells, at least 2
     */
    public static int haloCells(GridGeometry grid, SkyViewOptions options) {
        if (!options.bounded()) {
            return HALO_CELLS;
        }
        double smallest = Double.POSITIVE_INFINITY;
        for (int r = 0; r < grid.height(); r++) {
            smallest = Math.min(smallest, Math.min(grid.cellWidthMeters(r), grid.cellHeightMeters(r)));
        }
        double cells = Math.floor(options.radius() / smallest) + 2;
        return (int) Math.min(Integer.MAX_VALUE / 4, Math.max(2, cells));
    }

    /**
     * The sky-view factor of every cell of {@code dem}.
     *
     * @param dem     the terrain
     * @param options directions and height scale
     * @param pool    the threads
     * @return row-major factors in [0, 1], NaN for no-data
     */
    public static float[] compute(Dem dem, SkyViewOptions options, ForkJoinPool pool) {
        return compute(dem, options, pool, CellWindow.whole(dem.width(), dem.height()));
    }

    /**
     * The sky-view factor of the cells of {@code area}, horizons seen over the whole of {@code dem}.
     *
     * @param dem     the terrain
     * @param options directions and height scale
     * @param pool    the threads
     * @param area    the cells wanted, inside the grid
     * @return row-major factors of the area's cells (row length {@code area.width()}), NaN for no-data
     */
    public static float[] compute(Dem dem, SkyViewOptions options, ForkJoinPool pool, CellWindow area) {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(options, "options");
        Objects.requireNonNull(pool, "pool");
        if (!area.isInside(dem.width(), dem.height())) {
            throw new IllegalArgumentException("area " + area + " is not inside the " + dem.width() + "×"
                    + dem.height() + " DEM");
        }
        float[] sum = new float[area.width() * area.height()];
        int d = options.directions();
        for (int k = 0; k < d; k++) {
            new HorizonSweep(dem, options.azimuth(k), options.heightScale(), options.radius()).addSines(area, sum,
                    pool);
        }
        float[] v = dem.backingArray();
        int w = dem.width();
        for (int r = 0; r < area.height(); r++) {
            int in = (area.row() + r) * w + area.col();
            int out = r * area.width();
            for (int c = 0; c < area.width(); c++) {
                float z = v[in + c];
                sum[out + c] = z == z ? (float) Math.max(0, 1 - sum[out + c] / (double) d) : Float.NaN;
            }
        }
        return sum;
    }
}
