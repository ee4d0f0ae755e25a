package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.GridGeometry;
import java.time.ZonedDateTime;
import java.util.Arrays;
import java.util.Objects;

/**
 * One sun per tile of a grid: the article's "will often need to be recalculated for each latitude/longitude pair
 * for higher accuracy", at the granularity of the renderer's tiles (or rows). Each tile gets the sun seen from its
 * centre; a single tile covering the grid gives the original's default of one sun at the model centre
 * ({@code recalculateLightSourceOnEachPoint = false}).
 *
 * <p>Two views of each tile's sun: {@link #forTile} is the sun as seen on the sky (azimuth from true north), and
 * {@link #lightForTile}/{@link #lightForCell} is the light in the grid's own frame, azimuth measured clockwise from
 * the grid's "up" (the direction of decreasing row), which is what a hillshade computed on the grid needs. The two
 * differ by the grid convergence γ, the true bearing of grid-up ({@link #gridConvergenceDegrees}): 0 for a
 * geographic grid, up to a few degrees near the edge of a UTM zone. It is measured from the locator by a central
 * difference over one cell.
 *
 * <p>Longitudes from the locator are wrapped into [−180, 180), so grids across the antimeridian work. Immutable and
 * thread-safe once built.
 */
public final class SunPerTile {

    private final int width;
    private final int height;
    private final int tileWidth;
    private final int tileHeight;
    private final int tilesAcross;
    private final int tilesDown;
    private final SunPosition[] suns;
    private final double[] convergence;
    private final LightDirection[] lights;

    private SunPerTile(int width, int height, int tileWidth, int tileHeight, SunPosition[] suns,
                       double[] convergence) {
        this.width = width;
        this.height = height;
        this.tileWidth = tileWidth;
        this.tileHeight = tileHeight;
        this.tilesAcross = ceilDiv(width, tileWidth);
        this.tilesDown = ceilDiv(height, tileHeight);
        this.suns = suns;
        this.convergence = convergence;
        this.lights = new LightDirection[suns.length];
        for (int i = 0; i < suns.length; i++) {
            lights[i] = new LightDirection(suns[i].azimuthDegrees() - convergence[i], suns[i].elevationDegrees());
        }
    }

    /**
     * The sun for each {@code tileWidth × tileHeight} tile of {@code grid} (the last row and column of tiles may
     * be partial), seen from the tile's centre at {@code time}.
     *
     * @param grid the grid the tiles cover
     * @param locator latitude and longitude of a grid position
     * @param tileWidth cells per tile across, positive
     * @param tileHeight cells per tile down, positive
     * @param time the instant, in any zone
     * @param observer height, air and ΔT of the observer
     * @return the suns, one per tile
     * @throws IllegalArgumentException for non-positive tile sizes, a locator that gives no valid latitude and
     *                                  longitude (the message names the tile), or a time the SPA cannot take
     */
    public static SunPerTile compute(GridGeometry grid, LatLonLocator locator, int tileWidth, int tileHeight,
                                     ZonedDateTime time, Observer observer) {
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(locator, "locator");
        if (tileWidth < 1 || tileHeight < 1) {
            throw new IllegalArgumentException("tile size must be at least 1×1, got " + tileWidth + "×" + tileHeight);
        }
        SunAtInstant sun = SunAtInstant.of(time, observer);
        int across = ceilDiv(grid.width(), tileWidth);
        int down = ceilDiv(grid.height(), tileHeight);
        SunPosition[] suns = new SunPosition[across * down];
        double[] convergence = new double[across * down];
        for (int ty = 0; ty < down; ty++) {
            int row0 = ty * tileHeight;
            int row1 = Math.min(grid.height(), row0 + tileHeight);
            for (int tx = 0; tx < across; tx++) {
                int col0 = tx * tileWidth;
                int col1 = Math.min(grid.width(), col0 + tileWidth);
                // centre of cells [col0, col1) in cell-centre coordinates
                double col = 0.5 * (col0 + col1 - 1);
                double row = 0.5 * (row0 + row1 - 1);
                double[] ll = latLon(locator, col, row, tx, ty);
                suns[ty * across + tx] = sun.position(ll[0], LatLon.wrapLongitude(ll[1]));
                convergence[ty * across + tx] = convergence(locator, col, row, ll[0], tx, ty,
                        grid.ellipsoid().eccentricitySquared());
            }
        }
        return new SunPerTile(grid.width(), grid.height(), tileWidth, tileHeight, suns, convergence);
    }

    /**
     * One sun per row of cells (tiles as wide as the grid and one row high).
     *
     * @param grid the grid the rows cover
     * @param locator latitude and longitude of a grid position
     * @param time the instant, in any zone
     * @param observer height, air and ΔT of the observer
     * @return the suns, one per row
     */
    public static SunPerTile perRow(GridGeometry grid, LatLonLocator locator, ZonedDateTime time,
                                    Observer observer) {
        return compute(grid, locator, grid.width(), 1, time, observer);
    }

    /**
     * One sun for the whole grid, seen from its centre (the original's default).
     *
     * @param grid the grid
     * @param locator latitude and longitude of a grid position
     * @param time the instant, in any zone
     * @param observer height, air and ΔT of the observer
     * @return one sun, used for every cell
     */
    public static SunPerTile single(GridGeometry grid, LatLonLocator locator, ZonedDateTime time,
                                    Observer observer) {
        return compute(grid, locator, grid.width(), grid.height(), time, observer);
    }

    private static double[] latLon(LatLonLocator locator, double col, double row, int tx, int ty) {
        double[] ll = locator.latLon(col, row);
        if (ll == null || ll.length != 2 || !Double.isFinite(ll[0]) || !Double.isFinite(ll[1])
                || Math.abs(ll[0]) > 90) {
            throw new IllegalArgumentException("the locator gave no valid latitude/longitude for tile (" + tx + ", "
                    + ty + ") at cell (" + col + ", " + row + "): " + (ll == null ? "null" : Arrays.toString(ll)));
        }
        return ll;
    }

    /**
     * The true bearing of grid-up at ({@code col}, {@code row}), in degrees (clockwise from north), from the
     * locator half a cell above and below: atan2(Δλ·cos φ·N/M, Δφ), N and M the ellipsoid's radii of curvature.
     */
    private static double convergence(LatLonLocator locator, double col, double row, double lat, int tx, int ty,
                                      double e2) {
        double[] up = latLon(locator, col, row - 0.5, tx, ty);
        double[] down = latLon(locator, col, row + 0.5, tx, ty);
        double dLat = up[0] - down[0];
        double dLon = LatLon.wrapLongitude(up[1] - down[1]);
        if (dLat == 0 && dLon == 0) {
            return 0;
        }
        double phi = Math.toRadians(lat);
        double s = Math.sin(phi);
        double nOverM = (1 - e2 * s * s) / (1 - e2);
        return Math.toDegrees(Math.atan2(dLon * Math.cos(phi) * nOverM, dLat));
    }

    private static int ceilDiv(int a, int b) {
        return (a + b - 1) / b;
    }

    /** {@return cells per tile across} */
    public int tileWidth() {
        return tileWidth;
    }

    /** {@return cells per tile down (the last row of tiles may be shorter)} */
    public int tileHeight() {
        return tileHeight;
    }

    /** {@return the number of tile columns} */
    public int tilesAcross() {
        return tilesAcross;
    }

    /** {@return the number of tile rows} */
    public int tilesDown() {
        return tilesDown;
    }

    /**
     * The sun on the sky (azimuth from true north) of tile ({@code tileCol}, {@code tileRow}).
     *
     * @param tileCol tile column, from 0 at the left
     * @param tileRow tile row, from 0 at the top
     * @return the tile's sun
     */
    public SunPosition forTile(int tileCol, int tileRow) {
        return suns[tileIndex(tileCol, tileRow)];
    }

    /**
     * The sun on the sky (azimuth from true north) of the tile that holds cell ({@code col}, {@code row}).
     *
     * @param col cell column, from 0 at the left
     * @param row cell row, from 0 at the top
     * @return the sun of the cell's tile
     */
    public SunPosition forCell(int col, int row) {
        return suns[cellIndex(col, row)];
    }

    /**
     * The light of tile ({@code tileCol}, {@code tileRow}) in the grid's frame (azimuth from grid-up).
     *
     * @param tileCol tile column, from 0 at the left
     * @param tileRow tile row, from 0 at the top
     * @return the light in the grid's frame, the sun's elevation unchanged
     */
    public LightDirection lightForTile(int tileCol, int tileRow) {
        return lights[tileIndex(tileCol, tileRow)];
    }

    /**
     * The light of the tile that holds cell ({@code col}, {@code row}) in the grid's frame (azimuth from grid-up),
     * for the hillshade and shadow stages; no allocation.
     *
     * @param col cell column, from 0 at the left
     * @param row cell row, from 0 at the top
     * @return the light of the cell's tile, the same instance on every call
     */
    public LightDirection lightForCell(int col, int row) {
        return lights[cellIndex(col, row)];
    }

    /**
     * The grid convergence γ of tile ({@code tileCol}, {@code tileRow}): true bearing of grid-up, degrees.
     *
     * @param tileCol tile column, from 0 at the left
     * @param tileRow tile row, from 0 at the top
     * @return the convergence in degrees, clockwise from true north to grid-up; 0 where grid-up is north
     */
    public double gridConvergenceDegrees(int tileCol, int tileRow) {
        return convergence[tileIndex(tileCol, tileRow)];
    }

    private int tileIndex(int tileCol, int tileRow) {
        if (tileCol < 0 || tileCol >= tilesAcross || tileRow < 0 || tileRow >= tilesDown) {
            throw new IndexOutOfBoundsException("tile (" + tileCol + ", " + tileRow + ") is outside " + tilesAcross
                    + "×" + tilesDown + " tiles");
        }
        return tileRow * tilesAcross + tileCol;
    }

    private int cellIndex(int col, int row) {
        checkCell(col, row);
        return (row / tileHeight) * tilesAcross + col / tileWidth;
    }

    private void checkCell(int col, int row) {
        if (col < 0 || col >= width || row < 0 || row >= height) {
            throw new IndexOutOfBoundsException("cell (" + col + ", " + row + ") is outside the " + width + "×"
                    + height + " grid");
        }
    }

    /** {@return the largest minus the smallest elevation over all tiles, in degrees} */
    public double elevationSpreadDegrees() {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (SunPosition s : suns) {
            min = Math.min(min, s.elevationDegrees());
            max = Math.max(max, s.elevationDegrees());
        }
        return max - min;
    }

    /** {@return the narrowest arc of azimuths that holds every tile's sun, in degrees (360 minus the widest gap)} */
    public double azimuthSpreadDegrees() {
        double[] az = Arrays.stream(suns).mapToDouble(SunPosition::azimuthDegrees).sorted().toArray();
        double widestGap = az[0] + 360 - az[az.length - 1];
        for (int i = 1; i < az.length; i++) {
            widestGap = Math.max(widestGap, az[i] - az[i - 1]);
        }
        return 360 - widestGap;
    }
}
