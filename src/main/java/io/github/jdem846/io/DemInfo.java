package io.github.jdem846.io;

import io.github.jdem846.raster.GridGeometry;
import java.util.List;
import java.util.Objects;

/**
 * What a DEM file declares, read from its header without decoding the elevations.
 *
 * @param source         the file (or the bundled sample's name)
 * @param format         the file format
 * @param dataType       how elevations are stored
 * @param bands          number of bands in the file (band 1 is read)
 * @param geometry       grid size, georeferencing (outer-corner form) and CRS
 * @param declaredNoData the no-data value the file declares; {@code null} when it declares none, NaN when it
 *                       declares NaN
 * @param notices        things a person should know (assumptions, ignored bands, unresolved CRS codes)
 */
public record DemInfo(String source, DemFormat format, SampleType dataType, int bands, GridGeometry geometry,
                      Double declaredNoData, List<String> notices) {

    public DemInfo {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(format, "format");
        Objects.requireNonNull(dataType, "dataType");
        Objects.requireNonNull(geometry, "geometry");
        notices = List.copyOf(notices);
    }

    /** @return columns */
    public int width() {
        return geometry.width();
    }

    /** @return rows */
    public int height() {
        return geometry.height();
    }

    /**
     * This header with {@link GridGeometry#withDefaultEllipsoid(io.github.jdem846.geo.Ellipsoid)} applied.
     *
     * @param body the ellipsoid for a grid whose file names none
     * @return this header, or a copy on {@code body}
     */
    public DemInfo withDefaultEllipsoid(io.github.jdem846.geo.Ellipsoid body) {
        GridGeometry g = geometry.withDefaultEllipsoid(body);
        return g == geometry ? this : new DemInfo(source, format, dataType, bands, g, declaredNoData, notices);
    }

    /** @return the declared no-data value as {@link io.github.jdem846.raster.Dem} takes it: NaN when none */
    public double noDataOrNaN() {
        return declaredNoData != null ? declaredNoData : Double.NaN;
    }
}
