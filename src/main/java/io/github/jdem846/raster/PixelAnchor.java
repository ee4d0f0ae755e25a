package io.github.jdem846.raster;

/**
 * Where a file's georeferencing put its grid coordinates: on the outer corner of the cell (GeoTIFF PixelIsArea,
 * GridFloat {@code xllcorner}) or on its centre (GeoTIFF PixelIsPoint, GridFloat {@code xllcenter}, SRTM HGT).
 * {@link GridGeometry} always stores the outer corner; this records what the file declared.
 */
public enum PixelAnchor {
    /** Coordinates name the outer corner of a cell. */
    CORNER,
    /** Coordinates name the centre of a cell. */
    CENTER
}
