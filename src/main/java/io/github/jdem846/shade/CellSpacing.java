package io.github.jdem846.shade;

import io.github.jdem846.raster.GridGeometry;

/**
 * Horizontal distances between neighbouring cell centres, in metres, per row: the DEM's metric cell size, or the
 * cell size in CRS units times a gdaldem-style scale ({@link HillshadeOptions#horizontalScale()}).
 */
final class CellSpacing {

    private final GridGeometry geometry;
    private final double scale;

    /** Largest accepted spacing, 10⁹ m: far beyond any planet, far below overflow in the normals. */
    static final double MAX_SPACING_METERS = 1e9;

    CellSpacing(GridGeometry geometry, HillshadeOptions options) {
        this.geometry = geometry;
        this.scale = options.horizontalScale();
        if (!Double.isNaN(scale)) {
            double largest = Math.max(geometry.cellWidth(), geometry.cellHeight()) * scale;
            if (!(largest <= MAX_SPACING_METERS)) {
                throw new IllegalArgumentException("horizontal scale " + scale + " makes cells " + largest
                        + " m wide; the scale should turn the grid's cell size (" + geometry.cellWidth() + " × "
                        + geometry.cellHeight() + " CRS units) into metres, e.g. 111120 for degrees");
            }
        }
    }

    /** East–west distance between centres of neighbouring cells of {@code row} (≥ 0; 0 only at a pole). */
    double eastWest(int row) {
        double w = Double.isNaN(scale) ? geometry.cellWidthMeters(row) : geometry.cellWidth() * scale;
        return sanitize(w);
    }

    /** North–south distance between centres of neighbouring rows around {@code row} (> 0 for a sane grid). */
    double northSouth(int row) {
        double h = Double.isNaN(scale) ? geometry.cellHeightMeters(row) : geometry.cellHeight() * scale;
        return sanitize(h);
    }

    /** A size that is not a finite non-negative number (it cannot be, but be safe) becomes 0: no extent. */
    private static double sanitize(double v) {
        return v >= 0 && v < Double.POSITIVE_INFINITY ? v : 0.0;
    }
}
