package io.github.jdem846.sun;

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
    private final LightDirection[] lights;

    private SunPerTile(int width, int height, int tileWidth, int tileHeight, SunPosition[] suns) {
        this.width = width;
        this.height = height;
        this.tileWidth = tileWidth;
        this.tileHeight = tileHeight;
        this.tilesAcross = ceilDiv(width, tileWidth);
        this.tilesDown = ceilDiv(height, tileHeight);
        this.suns = suns;
        this.lights = Arrays.stream(suns).map(SunPosition::toLightDirection).toArray(LightDirection[]::new);
    }

    /**
     * The sun for each {@code tileWidth × tileHeight} tile of {@code grid} (the last row and column of tiles may
     * be partial), seen from the tile's centre at {@code time}.
     *
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
        for (int ty = 0; ty < down; ty++) {
            int row0 = ty * tileHeight;
            int row1 = Math.min(grid.height(), row0 + tileHeight);
            for (int tx = 0; tx < across; tx++) {
                int col0 = tx * tileWidth;
                int col1 = Math.min(grid.width(), col0 + tileWidth);
                // centre of cells [col0, col1) in cell-centre coordinates
                double col = 0.5 * (col0 + col1 - 1);
                double row = 0.5 * (row0 + row1 - 1);
                suns[ty * across + tx] = sunAt(sun, locator, col, row, tx, ty);
            }
        }
        return new SunPerTile(grid.width(), grid.height(), tileWidth, tileHeight, suns);
    }

    /** One sun per row of cells (tiles as wide as the grid and one row high). */
    public static SunPerTile perRow(GridGeometry grid, LatLonLocator locator, ZonedDateTime time,
                                    Observer observer) {
        return compute(grid, locator, grid.width(), 1, time, observer);
    }

    /** One sun for the whole grid, seen from its centre (the original's default). */
    public static SunPerTile single(GridGeometry grid, LatLonLocator locator, ZonedDateTime time,
                                    Observer observer) {
        return compute(grid, locator, grid.width(), grid.height(), time, observer);
    }

    private static SunPosition sunAt(SunAtInstant sun, LatLonLocator locator, double col, double row, int tx,
                                     int ty) {
        double[] ll = locator.latLon(col, row);
        if (ll == null || ll.length != 2 || !Double.isFinite(ll[0]) || !Double.isFinite(ll[1])
                || Math.abs(ll[0]) > 90) {
            throw new IllegalArgumentException("the locator gave no valid latitude/longitude for tile (" + tx + ", "
                    + ty + ") at cell (" + col + ", " + row + "): " + (ll == null ? "null" : Arrays.toString(ll)));
        }
        return sun.position(ll[0], LatLon.wrapLongitude(ll[1]));
    }

    private static int ceilDiv(int a, int b) {
        return (a + b - 1) / b;
    }

    public int tileWidth() {
        return tileWidth;
    }

    public int tileHeight() {
        return tileHeight;
    }

    public int tilesAcross() {
        return tilesAcross;
    }

    public int tilesDown() {
        return tilesDown;
    }

    /** The sun of tile ({@code tileCol}, {@code tileRow}). */
    public SunPosition forTile(int tileCol, int tileRow) {
        if (tileCol < 0 || tileCol >= tilesAcross || tileRow < 0 || tileRow >= tilesDown) {
            throw new IndexOutOfBoundsException("tile (" + tileCol + ", " + tileRow + ") is outside " + tilesAcross
                    + "×" + tilesDown + " tiles");
        }
        return suns[tileRow * tilesAcross + tileCol];
    }

    /** The sun of the tile that holds cell ({@code col}, {@code row}). */
    public SunPosition forCell(int col, int row) {
        checkCell(col, row);
        return suns[(row / tileHeight) * tilesAcross + col / tileWidth];
    }

    /** The light direction of the tile that holds cell ({@code col}, {@code row}) (no allocation). */
    public LightDirection lightForCell(int col, int row) {
        checkCell(col, row);
        return lights[(row / tileHeight) * tilesAcross + col / tileWidth];
    }

    private void checkCell(int col, int row) {
        if (col < 0 || col >= width || row < 0 || row >= height) {
            throw new IndexOutOfBoundsException("cell (" + col + ", " + row + ") is outside the " + width + "×"
                    + height + " grid");
        }
    }

    /** The largest minus the smallest elevation over all tiles, in degrees. */
    public double elevationSpreadDegrees() {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (SunPosition s : suns) {
            min = Math.min(min, s.elevationDegrees());
            max = Math.max(max, s.elevationDegrees());
        }
        return max - min;
    }

    /** The narrowest arc of azimuths that holds every tile's sun, in degrees (360 minus the widest gap). */
    public double azimuthSpreadDegrees() {
        double[] az = Arrays.stream(suns).mapToDouble(SunPosition::azimuthDegrees).sorted().toArray();
        double widestGap = az[0] + 360 - az[az.length - 1];
        for (int i = 1; i < az.length; i++) {
            widestGap = Math.max(widestGap, az[i] - az[i - 1]);
        }
        return 360 - widestGap;
    }
}
