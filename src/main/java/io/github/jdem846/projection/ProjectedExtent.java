package io.github.jdem846.projection;

import io.github.jdem846.raster.GridGeometry;

/**
 * The rectangle a projected picture covers, in the projection's units (x east, y north, outer pixel edges).
 *
 * @param west  x of the west edge
 * @param south y of the south edge
 * @param east  x of the east edge, greater than {@code west}
 * @param north y of the north edge, greater than {@code south}
 */
public record ProjectedExtent(double west, double south, double east, double north) {

    /** Points per edge of the grid sampled for its outline. */
    static final int EDGE_SAMPLES = 2048;

    /** Points per side of the grid sampled inside (the extreme of a projection may lie inside the outline). */
    static final int INSIDE_SAMPLES = 64;

    /**
     * Checks that the edges are finite with east &gt; west and north &gt; south.
     *
     * @param west x of the west edge
     * @param south y of the south edge
     * @param east x of the east edge, greater than {@code west}
     * @param north y of the north edge, greater than {@code south}
     */
    public ProjectedExtent {
        if (!(Double.isFinite(west) && Double.isFinite(south) && Double.isFinite(east) && Double.isFinite(north))
                || !(east > west) || !(north > south)) {
            throw new IllegalArgumentException("a projected extent needs finite edges with east > west and north > "
                    + "south, got " + west + ", " + south + ", " + east + ", " + north);
        }
    }

    /**
     * The projected bounding box of a grid's area: its outer edge sampled every 1/{@value #EDGE_SAMPLES} of a side
     * and {@value #INSIDE_SAMPLES}² points inside, each projected (and where a longitude/latitude grid crosses the
     * meridian opposite the central one, that meridian on both sides of the map); points off the projection's map
     * are left out, latitudes beyond its limit cut (Mercator).
     *
     * @param grid       the grid (its CRS must be known)
     * @param projection the projection
     * @return the box
     * @throws IllegalArgumentException when no point of the grid lies on the projection's map
     */
    public static ProjectedExtent of(GridGeometry grid, MapProjection projection) {
        return of(grid, GridMapping.of(grid, projection), projection);
    }

    static ProjectedExtent of(GridGeometry grid, GridMapping mapping, MapProjection projection) {
        int n = EDGE_SAMPLES;
        int m = INSIDE_SAMPLES;
        double[] seams = seamsInside(grid, projection);
        double[] xy = new double[2 * (4 * (n + 1) + m * m + 2 * seams.length * (n + 1))];
        int k = 0;
        double w = grid.originX();
        double e = grid.eastX();
        double north = grid.originY();
        double south = grid.southY();
        for (int i = 0; i <= n; i++) {
            double f = (double) i / n;
            double x = w + f * (e - w);
            double y = south + f * (north - south);
            k = put(xy, k, x, north);
            k = put(xy, k, x, south);
            k = put(xy, k, w, y);
            k = put(xy, k, e, y);
        }
        for (int i = 0; i < m; i++) {
            for (int j = 0; j < m; j++) {
                k = put(xy, k, w + (i + 0.5) / m * (e - w), south + (j + 0.5) / m * (north - south));
            }
        }
        for (double seam : seams) {
            // the meridian opposite the central one, inside the grid: both of the map's side edges
            for (int i = 0; i <= n; i++) {
                double y = south + (double) i / n * (north - south);
                k = put(xy, k, projection.centralMeridian() - 180, y);
                k = put(xy, k, projection.centralMeridian() + 180, y);
            }
        }
        mapping.toTarget(xy, k);
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < k; i++) {
            double x = xy[2 * i];
            double y = xy[2 * i + 1];
            if (Double.isFinite(x) && Double.isFinite(y)) {
                minX = Math.min(minX, x);
                maxX = Math.max(maxX, x);
                minY = Math.min(minY, y);
                maxY = Math.max(maxY, y);
            }
        }
        if (!(maxX > minX) || !(maxY > minY)) {
            throw new IllegalArgumentException("the DEM does not lie on the map of " + projection.label());
        }
        return new ProjectedExtent(minX, minY, maxX, maxY);
    }

    /** The longitudes λ₀ ± 180° + 360° k strictly inside a longitude/latitude grid (none for other grids). */
    private static double[] seamsInside(GridGeometry grid, MapProjection projection) {
        if (!grid.crs().isGeographic()) {
            return new double[0];
        }
        double first = projection.centralMeridian() + 180;
        first -= 360 * Math.ceil((first - grid.originX()) / 360);
        java.util.List<Double> seams = new java.util.ArrayList<>();
        for (double s = first; s < grid.eastX(); s += 360) {
            if (s > grid.originX()) {
                seams.add(s);
            }
        }
        return seams.stream().mapToDouble(Double::doubleValue).toArray();
    }

    private static int put(double[] xy, int k, double x, double y) {
        xy[2 * k] = x;
        xy[2 * k + 1] = y;
        return k + 1;
    }

    /** {@return east − west} */
    public double width() {
        return east - west;
    }

    /** {@return north − south} */
    public double height() {
        return north - south;
    }

    /**
     * A picture size with square pixels: {@code width} across (height from the aspect ratio), {@code height} down,
     * or with both given the largest that fits in both.
     *
     * @param width  pixels across, or 0
     * @param height pixels down, or 0
     * @return {width, height}, each at least 1
     * @throws IllegalArgumentException when both are 0
     */
    public int[] pixels(int width, int height) {
        if (width <= 0 && height <= 0) {
            throw new IllegalArgumentException("a projected picture needs a width or a height");
        }
        double aspect = width() / height();
        int w;
        int h;
        if (width > 0 && (height <= 0 || width / aspect <= height)) {
            w = width;
            h = (int) Math.max(1, Math.round(width / aspect));
        } else {
            h = height;
            w = (int) Math.max(1, Math.round(height * aspect));
        }
        return new int[] {w, h};
    }
}
