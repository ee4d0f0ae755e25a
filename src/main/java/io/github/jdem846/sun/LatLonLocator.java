package io.github.jdem846.sun;

import io.github.jdem846.raster.GridGeometry;
import java.util.Objects;
import java.util.function.BiFunction;

/**
 * Where a point of a grid is on the Earth: geodetic latitude and longitude in degrees for fractional cell
 * coordinates ({@code col}, {@code row}), where whole numbers are cell centres (as {@link GridGeometry#centerX}):
 * (0, 0) is the centre of the north-west cell and (−0.5, −0.5) its outer corner.
 */
@FunctionalInterface
interface LatLonLocator {

    /** {@code {latitude, longitude}} in degrees of the point at ({@code col}, {@code row}). */
    double[] latLon(double col, double row);

    /**
     * The locator of a grid whose CRS is geographic (x = longitude, y = latitude in degrees).
     *
     * @throws IllegalArgumentException when the grid is not geographic (projected grids need an inverse
     *                                  projection: pass one with {@link #of(BiFunction)})
     */
    static LatLonLocator geographic(GridGeometry grid) {
        Objects.requireNonNull(grid, "grid");
        if (!grid.crs().isGeographic()) {
            throw new IllegalArgumentException("the grid's coordinates are not longitude/latitude (" + grid.crs().kind()
                    + "); a sun per tile needs a locator that turns its cells into latitude and longitude");
        }
        return (col, row) -> new double[] {grid.centerY(row), grid.centerX(col)};
    }

    /**
     * The locator of any grid whose CRS can be turned into latitude/longitude ({@link GridGeometry#geoLocator()}:
     * geographic grids directly, projected ones through Apache SIS).
     *
     * @throws IllegalArgumentException when the CRS is unknown or cannot be inverted offline
     */
    static LatLonLocator forGrid(GridGeometry grid) {
        Objects.requireNonNull(grid, "grid");
        if (grid.crs().isGeographic()) {
            return geographic(grid);
        }
        io.github.jdem846.geo.GeoLocator geo = grid.geoLocator().orElseThrow(() -> new IllegalArgumentException(
                "the grid's CRS (" + (grid.crs().name() != null ? grid.crs().name() : "unknown")
                        + ") cannot be turned into latitude/longitude here; give the place with --sun-at LAT,LON"));
        return (col, row) -> {
            io.github.jdem846.geo.LatLon p = geo.toLatLon(grid.centerX(col), grid.centerY(row));
            return new double[] {p.latitude(), p.longitude()};
        };
    }

    /** Adapts a function {@code (col, row) → {lat, lon}} (e.g. a reader's inverse projection). */
    static LatLonLocator of(BiFunction<Double, Double, double[]> function) {
        Objects.requireNonNull(function, "function");
        return function::apply;
    }
}
