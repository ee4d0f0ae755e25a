package io.github.jdem846.tiles;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

/**
 * Tiles of one zoom that are rendered together from one read of the DEM: a block of up to {@value TilePlan#GROUP}
 * × {@value TilePlan#GROUP} tiles of a {@link TilePlan}, the unit of work handed to a thread or to a cluster's task.
 * Serializable, so that it can be shipped to another process.
 *
 * @param z    zoom
 * @param minX first column
 * @param minY first row (north)
 * @param maxX last column (inclusive)
 * @param maxY last row (inclusive)
 * @serial exclude
 */
public record TileGroup(int z, int minX, int minY, int maxX, int maxY) implements Serializable {

    private static final long serialVersionUID = 1L;

    /**
     * Checks that the tiles exist at zoom {@code z}.
     *
     * @param z zoom
     * @param minX first column
     * @param minY first row (north)
     * @param maxX last column (inclusive)
     * @param maxY last row (inclusive)
     */
    public TileGroup {
        new TileRange(z, minX, minY, maxX, maxY); // checks the bounds
    }

    /** {@return its tiles, row by row from the north-west} */
    public List<WebMercatorTile> tiles() {
        return new TileRange(z, minX, minY, maxX, maxY).tiles();
    }

    /** {@return how many tiles it holds} */
    public int size() {
        return (maxX - minX + 1) * (maxY - minY + 1);
    }

    /** @return the groups of {@code range}: blocks of {@code side} tiles aligned on multiples of {@code side} */
    static List<TileGroup> covering(TileRange range, int side) {
        List<TileGroup> out = new ArrayList<>();
        for (int gy = range.minY() / side; gy <= range.maxY() / side; gy++) {
            for (int gx = range.minX() / side; gx <= range.maxX() / side; gx++) {
                out.add(new TileGroup(range.z(), Math.max(range.minX(), gx * side), Math.max(range.minY(), gy * side),
                        Math.min(range.maxX(), gx * side + side - 1), Math.min(range.maxY(), gy * side + side - 1)));
            }
        }
        return out;
    }

    @Override
    public String toString() {
        return z + "/" + minX + "-" + maxX + "/" + minY + "-" + maxY;
    }
}
