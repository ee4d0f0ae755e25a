package io.github.jdem846.overlay;

import java.util.List;
import java.util.Objects;
import org.locationtech.jts.geom.Geometry;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * Vector features to draw onto a picture: their geometries, the CRS of their coordinates and the style.
 *
 * @param name       what the features are called in messages (usually the file name)
 * @param geometries the geometries (points, lines, polygons and collections of them); x is easting or longitude
 * @param crs        the CRS of the coordinates with x east (longitude) first, or {@code null} when unknown: the
 *                   coordinates are then taken to be in the picture's CRS
 * @param style      how to draw them
 */
public record Overlay(String name, List<Geometry> geometries, CoordinateReferenceSystem crs, OverlayStyle style) {

    /**
     * Checks the name and style and copies the geometries.
     *
     * @param name       what the features are called in messages (usually the file name)
     * @param geometries the geometries (points, lines, polygons and collections of them); x is easting or longitude
     * @param crs        the CRS of the coordinates with x east (longitude) first, or {@code null} when unknown: the
     *                   coordinates are then taken to be in the picture's CRS
     * @param style      how to draw them
     */
    public Overlay {
        Objects.requireNonNull(name, "name");
        geometries = List.copyOf(geometries);
        Objects.requireNonNull(style, "style");
    }

    /**
     * @param value the new style
     * @return this overlay drawn with {@code value}
     */
    public Overlay withStyle(OverlayStyle value) {
        return new Overlay(name, geometries, crs, value);
    }
}
