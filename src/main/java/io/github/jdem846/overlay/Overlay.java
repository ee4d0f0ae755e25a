package io.github.jdem846.overlay;

import java.util.List;
import java.util.Objects;
import org.locationtech.jts.geom.Geometry;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * Vector features to draw onto a picture: their geometries, the CRS of their coordinates, the file's style and the
 * style each feature gives itself.
 *
 * @param name          what the features are called in messages (usually the file name)
 * @param geometries    the geometries (points, lines, polygons and collections of them); x is easting or longitude
 * @param crs           the CRS of the coordinates with x east (longitude) first, or {@code null} when unknown: the
 *                      coordinates are then taken to be in the picture's CRS
 * @param style         how to draw them
 * @param featureStyles for each geometry, the style properties of its feature put over {@code style}; empty when
 *                      no feature has any
 */
public record Overlay(String name, List<Geometry> geometries, CoordinateReferenceSystem crs, OverlayStyle style,
                      List<FeatureStyle> featureStyles) {

    /**
     * Checks the name and style and copies the lists.
     *
     * @param name          what the features are called in messages (usually the file name)
     * @param geometries    the geometries (points, lines, polygons and collections of them); x is easting or
     *                      longitude
     * @param crs           the CRS of the coordinates with x east (longitude) first, or {@code null} when unknown:
     *                      the coordinates are then taken to be in the picture's CRS
     * @param style         how to draw them
     * @param featureStyles for each geometry, the style properties of its feature put over {@code style}; empty
     *                      when no feature has any
     * @throws IllegalArgumentException when {@code featureStyles} is neither empty nor one per geometry
     */
    public Overlay {
        Objects.requireNonNull(name, "name");
        geometries = List.copyOf(geometries);
        Objects.requireNonNull(style, "style");
        featureStyles = featureStyles.stream().allMatch(FeatureStyle.NONE::equals) ? List.of()
                : List.copyOf(featureStyles);
        if (!featureStyles.isEmpty() && featureStyles.size() != geometries.size()) {
            throw new IllegalArgumentException(featureStyles.size() + " feature styles for " + geometries.size()
                    + " geometries");
        }
    }

    /**
     * Features that all get the file's style.
     *
     * @param name       what the features are called in messages (usually the file name)
     * @param geometries the geometries (points, lines, polygons and collections of them); x is easting or longitude
     * @param crs        the CRS of the coordinates with x east (longitude) first, or {@code null} when unknown: the
     *                   coordinates are then taken to be in the picture's CRS
     * @param style      how to draw them
     */
    public Overlay(String name, List<Geometry> geometries, CoordinateReferenceSystem crs, OverlayStyle style) {
        this(name, geometries, crs, style, List.of());
    }

    /**
     * @param value the new style
     * @return this overlay drawn with {@code value} (the features' own style properties still put over it)
     */
    public Overlay withStyle(OverlayStyle value) {
        return new Overlay(name, geometries, crs, value, featureStyles);
    }

    /**
     * @param index a geometry's index
     * @return the style that geometry is drawn with
     */
    public OverlayStyle styleOf(int index) {
        return featureStyles.isEmpty() ? style : featureStyles.get(index).over(style);
    }
}
