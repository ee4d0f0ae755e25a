package io.github.jdem846.tiles;

import io.github.jdem846.geo.GeoLocator;
import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.raster.GridGeometry;

/**
 * Where Web Mercator positions fall in the DEM's grid: Web Mercator metres to longitude/latitude by the closed
 * formulas, then to the DEM's CRS by Apache SIS ({@link GeoLocator#fromLonLat}); the identity from longitude/latitude
 * for a geographic DEM, whose columns then depend on x only and rows on y only ({@link #isSeparable()}).
 */
final class SourceProjection {

    private final GridGeometry grid;
    private final GeoLocator locator;
    private final LatLonBox extent;

    private SourceProjection(GridGeometry grid, GeoLocator locator, LatLonBox extent) {
        this.grid = grid;
        this.locator = locator;
        this.extent = extent;
    }

    /**
     * The projection of the DEM whose full-resolution grid is {@code grid}.
     *
     * @param source the DEM's name, for the message
     * @throws IllegalArgumentException when its CRS is unknown or cannot be turned into latitude/longitude
     */
    static SourceProjection of(GridGeometry grid, String source) {
        GeoLocator locator = grid.geoLocator().orElseThrow(() -> new IllegalArgumentException(source
                + ": its coordinate reference system " + (grid.crs().name() != null ? "(" + grid.crs().name() + ") "
                : "") + "cannot be turned into latitude/longitude, which map tiles need: give the file a known CRS "
                + "(a .prj, GeoKeys with an EPSG code)"));
        LatLonBox e = grid.latLonExtent().orElseThrow();
        LatLonBox clamped = new LatLonBox(Math.max(-WebMercator.MAX_LATITUDE, e.south()),
                Math.min(WebMercator.MAX_LATITUDE, e.north()), e.west(), e.east());
        if (!(clamped.south() < clamped.north()) || !(clamped.west() < clamped.east())) {
            throw new IllegalArgumentException(source + ": its extent " + e + " has no area inside the Web Mercator "
                    + "world (latitudes ±" + WebMercator.MAX_LATITUDE + "°)");
        }
        return new SourceProjection(grid, locator, clamped);
    }

    /** @return the DEM's full-resolution grid */
    GridGeometry grid() {
        return grid;
    }

    /** @return the DEM's latitude/longitude box, clamped to the Web Mercator world */
    LatLonBox extent() {
        return extent;
    }

    /** @return true when the DEM is in longitude/latitude: its x is a function of longitude alone */
    boolean isSeparable() {
        return grid.crs().isGeographic();
    }

    /**
     * DEM-CRS positions of Web Mercator points, in place: {@code points} holds x0, y0, x1, y1, … in Web Mercator
     * metres and receives the DEM's x, y (NaN where the DEM's projection cannot take the point).
     */
    void toSource(double[] points, int count) {
        for (int i = 0; i < 2 * count; i += 2) {
            points[i] = WebMercator.longitude(points[i]);
            points[i + 1] = WebMercator.latitude(points[i + 1]);
        }
        locator.fromLonLat(points, count);
    }
}
