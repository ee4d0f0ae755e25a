package io.github.jdem846.output;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.GridGeometry;
import java.util.Objects;

/**
 * Where an output image lies on the ground: the outer edges of the area it covers, in CRS units, and the CRS. The
 * image fills this area whatever its pixel size, so a picture smaller (or larger) than the DEM keeps the DEM's
 * extent and gets pixels of {@code extent / image size} ({@link #pixelWidth(int)}, {@link #pixelHeight(int)}).
 * North up; x grows east, y grows north.
 *
 * @param westX  x of the west edge of the first column
 * @param northY y of the north edge of the first row
 * @param eastX  x of the east edge of the last column; greater than {@code westX}
 * @param southY y of the south edge of the last row; less than {@code northY}
 * @param crs    the CRS ({@link CrsInfo#UNKNOWN} when unknown)
 */
public record GeoReference(double westX, double northY, double eastX, double southY, CrsInfo crs) {

    /**
     * Checks that the CRS is given and that the edges are finite with east &gt; west and north &gt; south.
     *
     * @param westX x of the west edge of the first column
     * @param northY y of the north edge of the first row
     * @param eastX x of the east edge of the last column; greater than {@code westX}
     * @param southY y of the south edge of the last row; less than {@code northY}
     * @param crs the CRS ({@link CrsInfo#UNKNOWN} when unknown)
     */
    public GeoReference {
        Objects.requireNonNull(crs, "crs");
        if (!Double.isFinite(westX) || !Double.isFinite(northY) || !Double.isFinite(eastX)
                || !Double.isFinite(southY)) {
            throw new IllegalArgumentException("georeferencing edges must be finite, got west " + westX + ", north "
                    + northY + ", east " + eastX + ", south " + southY);
        }
        if (!(eastX > westX) || !(northY > southY)) {
            throw new IllegalArgumentException("georeferencing needs east > west and north > south, got west "
                    + westX + ", north " + northY + ", east " + eastX + ", south " + southY);
        }
    }

    /**
     * The area covered by {@code grid}, outer cell edges, with its CRS.
     *
     * @param grid the grid
     * @return its outer edges and CRS
     */
    public static GeoReference of(GridGeometry grid) {
        return new GeoReference(grid.originX(), grid.originY(), grid.eastX(), grid.southY(), grid.crs());
    }

    /**
     * Width in CRS units of one pixel of an image {@code imageWidth} pixels wide.
     *
     * @param imageWidth the image's width in pixels
     * @return the pixel width, {@code (east − west) / imageWidth}
     */
    public double pixelWidth(int imageWidth) {
        checkSize(imageWidth);
        return (eastX - westX) / imageWidth;
    }

    /**
     * Height in CRS units (positive) of one pixel of an image {@code imageHeight} pixels high.
     *
     * @param imageHeight the image's height in pixels
     * @return the pixel height, {@code (north − south) / imageHeight}
     */
    public double pixelHeight(int imageHeight) {
        checkSize(imageHeight);
        return (northY - southY) / imageHeight;
    }

    private static void checkSize(int pixels) {
        if (pixels < 1) {
            throw new IllegalArgumentException("image size must be at least 1 pixel, got " + pixels);
        }
    }
}
