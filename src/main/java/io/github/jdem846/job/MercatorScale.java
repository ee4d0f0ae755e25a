package io.github.jdem846.job;

import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.raster.GridGeometry;

/**
 * How a job measures the cells of a Web Mercator (EPSG:3857) DEM for slopes and cast-shadow lengths. Web Mercator's
 * metres are longer than ground metres by 1/cos φ (1.52 at 49° N); other grids are measured as their CRS says
 * whatever is chosen here.
 */
public enum MercatorScale {

    /**
     * The default: the true size of the cells on the ground, row by row at each row's latitude, as for a
     * latitude/longitude grid and for map tiles ({@link GridGeometry#withGroundCellSizes()}).
     */
    GROUND,

    /** The projection's nominal metres, the same for every row, as gdaldem uses them. */
    MAP;

    /**
     * The geometry a job measures {@code g}'s cells by.
     *
     * @param g a grid's geometry
     * @return {@code g} with ground cell sizes when this is {@link #GROUND} and {@code g} is Web Mercator, else
     * {@code g}
     */
    public GridGeometry apply(GridGeometry g) {
        return this == GROUND && !g.hasGroundCellSizes() && WebMercator.isWebMercator(g.crs())
                ? g.withGroundCellSizes() : g;
    }
}
