package io.github.jdem846.io.source;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.nio.file.Path;

/**
 * The grid geometry a reader builds from a file's georeferencing, refused with the file's name and the keys or
 * tags at fault when it gives no usable grid: cell sizes positive and finite, all four edges finite (a cell size
 * of 1e308 times the rows overflows), and cells wide enough to tell apart at their coordinates (cells of 1e-300
 * at x = 500000 would all have the same x). Whatever else {@link GridGeometry} refuses becomes a
 * {@link DemFormatException} too.
 */
public final class ReaderGeometry {

    private ReaderGeometry() {
    }

    /** {@link #checkEdges} of a {@code width × height} grid whose north-west corner is the origin. */
    public static void check(Path file, String source, int width, int height, double originX, double originY,
                      double cellWidth, double cellHeight) throws DemFormatException {
        checkEdges(file, source, source, originX, originX + width * cellWidth, originY - height * cellHeight,
                originY, cellWidth, cellHeight);
    }

    /**
     * Checks georeferencing by its edges, each computed from what the file gives (so that a message shows the
     * value the file holds next to the one that overflowed).
     *
     * @param file    the file that holds the georeferencing (named in the message)
     * @param xSource what gives the x extent, e.g. "header keys 'xllcorner', 'ncols' and 'cellsize'"
     * @param ySource what gives the y extent
     */
    public static void checkEdges(Path file, String xSource, String ySource, double west, double east, double south,
                           double north, double cellWidth, double cellHeight) throws DemFormatException {
        checkAxis(file, xSource, "x", "wide", west, east, cellWidth);
        checkAxis(file, ySource, "y", "high", south, north, cellHeight);
    }

    /** {@link #check} and then the geometry, with what GridGeometry refuses as a DemFormatException. */
    public static GridGeometry of(Path file, String source, int width, int height, double originX, double originY,
                           double cellWidth, double cellHeight, CrsInfo crs, PixelAnchor anchor)
            throws DemFormatException {
        check(file, source, width, height, originX, originY, cellWidth, cellHeight);
        try {
            return new GridGeometry(width, height, originX, originY, cellWidth, cellHeight, crs, anchor);
        } catch (IllegalArgumentException e) {
            throw new DemFormatException(file, source + ": no usable grid: " + e.getMessage(), e);
        }
    }

    private static void checkAxis(Path file, String source, String axis, String extent, double low, double high,
                                  double cell) throws DemFormatException {
        if (!(cell > 0) || !Double.isFinite(cell)) {
            throw new DemFormatException(file, source + ": cells are " + cell + " " + extent
                    + "; the cell size must be a positive finite number");
        }
        if (!Double.isFinite(low) || !Double.isFinite(high)) {
            throw new DemFormatException(file, source + ": the grid runs from " + axis + " = " + low + " to "
                    + high + "; its edges must be finite numbers");
        }
        double at = Math.max(Math.abs(low), Math.abs(high));
        if (!(cell >= Math.ulp(at))) {
            throw new DemFormatException(file, source + ": cells are " + cell + " " + extent + " at " + axis + " = "
                    + at + ", too small to tell neighbouring cells apart there (coordinates are doubles)");
        }
    }
}
