package io.github.jdem846.tiles;

import io.github.jdem846.geo.LatLonBox;
import java.util.ArrayList;
import java.util.List;

/**
 * The tiles of one zoom level in a rectangle of columns {@code minX..maxX} and rows {@code minY..maxY} (inclusive).
 *
 * @param z    zoom
 * @param minX first column
 * @param minY first row (north)
 * @param maxX last column
 * @param maxY last row (south)
 */
public record TileRange(int z, int minX, int minY, int maxX, int maxY) {

    /**
     * Checks that the range is not empty and its tiles exist at zoom {@code z}.
     *
     * @param z zoom
     * @param minX first column
     * @param minY first row (north)
     * @param maxX last column
     * @param maxY last row (south)
     */
    public TileRange {
        int n = 1 << z;
        if (minX < 0 || minY < 0 || maxX >= n || maxY >= n || minX > maxX || minY > maxY) {
            throw new IllegalArgumentException("tile range " + minX + ".." + maxX + " × " + minY + ".." + maxY
                    + " does not fit zoom " + z);
        }
    }

    /**
     * The tiles whose area overlaps {@code box} by more than an edge: a box edge that lies exactly on a tile edge
     * does not bring in the tile beyond it. Latitudes beyond ±{@link io.github.jdem846.geo.WebMercator#MAX_LATITUDE}
     * are clamped; longitudes are taken as they are (a box must not cross the antimeridian).
     *
     * @param box the area, degrees
     * @param z zoom
     * @return the range of tiles
     * @throws IllegalArgumentException when the box is empty or not finite
     */
    public static TileRange covering(LatLonBox box, int z) {
        if (!(box.west() < box.east()) || !(box.south() < box.north()) || !Double.isFinite(box.west())
                || !Double.isFinite(box.east()) || !Double.isFinite(box.south()) || !Double.isFinite(box.north())) {
            throw new IllegalArgumentException("the box " + box + " is empty or not finite");
        }
        int n = 1 << z;
        double west = Math.max(-180, box.west());
        double east = Math.min(180, box.east());
        int minX = clamp((int) Math.floor(WebMercatorTile.column(west, z)), n);
        int maxX = clamp((int) Math.ceil(WebMercatorTile.column(east, z)) - 1, n);
        int minY = clamp((int) Math.floor(WebMercatorTile.row(box.north(), z)), n);
        int maxY = clamp((int) Math.ceil(WebMercatorTile.row(box.south(), z)) - 1, n);
        return new TileRange(z, minX, minY, Math.max(minX, maxX), Math.max(minY, maxY));
    }

    /** {@return columns × rows} */
    public long count() {
        return (long) (maxX - minX + 1) * (maxY - minY + 1);
    }

    /**
     * {@return whether the tile is in this range}
     *
     * @param t a tile of any zoom
     */
    public boolean contains(WebMercatorTile t) {
        return t.z() == z && t.x() >= minX && t.x() <= maxX && t.y() >= minY && t.y() <= maxY;
    }

    /** {@return every tile, row by row from the north-west} */
    public List<WebMercatorTile> tiles() {
        List<WebMercatorTile> out = new ArrayList<>((int) Math.min(Integer.MAX_VALUE - 8, count()));
        for (int y = minY; y <= maxY; y++) {
            for (int x = minX; x <= maxX; x++) {
                out.add(new WebMercatorTile(z, x, y));
            }
        }
        return out;
    }

    private static int clamp(int v, int n) {
        return Math.max(0, Math.min(n - 1, v));
    }
}
