package io.github.jdem846.tiles;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.geo.WebMercator;

/**
 * One web-map tile: zoom {@code z}, column {@code x} from the antimeridian eastward, row {@code y} from the north
 * edge of the Web Mercator world (±{@link WebMercator#MAX_LATITUDE}) southward, the "XYZ" or "slippy map" scheme of
 * OpenStreetMap and most web maps (TMS counts rows from the south instead: {@link #tmsY()}). At zoom z the world is
 * 2^z × 2^z tiles of {@value #SIZE} × {@value #SIZE} pixels.
 *
 * @param z zoom, 0 to {@link #MAX_ZOOM}
 * @param x column, 0 to 2^z − 1
 * @param y row, 0 to 2^z − 1
 * @serial exclude
 */
public record WebMercatorTile(int z, int x, int y) implements java.io.Serializable {

    private static final long serialVersionUID = 1L;

    /** Pixels on a side of a tile. */
    public static final int SIZE = 256;

    /** Deepest zoom: its world, 256·2^22 pixels wide, still fits an int (a 9.3 mm pixel at the equator). */
    public static final int MAX_ZOOM = 22;

    /**
     * Checks that the zoom is 0 to {@link #MAX_ZOOM} and the tile exists at that zoom.
     *
     * @param z zoom, 0 to {@link #MAX_ZOOM}
     * @param x column, 0 to 2^z − 1
     * @param y row, 0 to 2^z − 1
     */
    public WebMercatorTile {
        if (z < 0 || z > MAX_ZOOM) {
            throw new IllegalArgumentException("zoom must be 0 to " + MAX_ZOOM + ", got " + z);
        }
        int n = 1 << z;
        if (x < 0 || x >= n || y < 0 || y >= n) {
            throw new IllegalArgumentException("tile " + z + "/" + x + "/" + y + " is outside zoom " + z
                    + " (x and y must be 0 to " + (n - 1) + ")");
        }
    }

    /**
     * The tile at zoom {@code z} that holds the point: longitude wrapped into [−180, 180), latitude clamped to
     * ±{@link WebMercator#MAX_LATITUDE}; a point on a tile edge belongs to the tile east or south of it.
     *
     * @param latitude degrees north
     * @param longitude degrees east
     * @param z zoom, 0 to {@link #MAX_ZOOM}
     * @return the tile
     */
    public static WebMercatorTile containing(double latitude, double longitude, int z) {
        if (!Double.isFinite(latitude) || !Double.isFinite(longitude)) {
            throw new IllegalArgumentException("latitude and longitude must be finite, got " + latitude + ", "
                    + longitude);
        }
        double lon = longitude - 360 * Math.floor((longitude + 180) / 360);
        int n = 1 << checkZoom(z);
        int x = clamp((int) Math.floor(column(lon, z)), n);
        int y = clamp((int) Math.floor(row(latitude, z)), n);
        return new WebMercatorTile(z, x, y);
    }

    /** Fractional tile column of {@code longitude} at zoom z: (λ + 180)/360 · 2^z. */
    static double column(double longitude, int z) {
        return (longitude + 180) / 360 * (1 << z);
    }

    /** Fractional tile row of {@code latitude} (clamped to the world) at zoom z: (1 − ln(tan φ + sec φ)/π)/2 · 2^z. */
    static double row(double latitude, int z) {
        return (WebMercator.HALF_WORLD - WebMercator.y(latitude)) / (2 * WebMercator.HALF_WORLD) * (1 << z);
    }

    /**
     * {@return the size in Web Mercator metres of one pixel at zoom z (156 543.03… m at zoom 0)}
     *
     * @param z zoom
     */
    public static double pixelSize(int z) {
        return 2 * WebMercator.HALF_WORLD / ((double) SIZE * (1L << checkZoom(z)));
    }

    /** {@return Web Mercator x of the west edge, metres} */
    public double westX() {
        return edgeX(x);
    }

    /** {@return Web Mercator x of the east edge, metres} */
    public double eastX() {
        return edgeX(x + 1);
    }

    /** {@return Web Mercator y of the north edge, metres} */
    public double northY() {
        return edgeY(y);
    }

    /** {@return Web Mercator y of the south edge, metres} */
    public double southY() {
        return edgeY(y + 1);
    }

    /** {@return the tile's edges in latitude and longitude, degrees} */
    public LatLonBox latLonBounds() {
        return new LatLonBox(WebMercator.latitude(southY()), WebMercator.latitude(northY()),
                WebMercator.longitude(westX()), WebMercator.longitude(eastX()));
    }

    /** {@return the row in the TMS scheme (counted from the south), as MBTiles stores it} */
    public int tmsY() {
        return (1 << z) - 1 - y;
    }

    /** {@return the tile one zoom out that contains this one (itself at zoom 0)} */
    public WebMercatorTile parent() {
        return z == 0 ? this : new WebMercatorTile(z - 1, x >> 1, y >> 1);
    }

    /** @return "z/x/y" */
    @Override
    public String toString() {
        return z + "/" + x + "/" + y;
    }

    private double edgeX(int col) {
        return -WebMercator.HALF_WORLD + 2 * WebMercator.HALF_WORLD * col / (1 << z);
    }

    private double edgeY(int row) {
        return WebMercator.HALF_WORLD - 2 * WebMercator.HALF_WORLD * row / (1 << z);
    }

    private static int checkZoom(int z) {
        if (z < 0 || z > MAX_ZOOM) {
            throw new IllegalArgumentException("zoom must be 0 to " + MAX_ZOOM + ", got " + z);
        }
        return z;
    }

    private static int clamp(int v, int n) {
        return Math.max(0, Math.min(n - 1, v));
    }
}
