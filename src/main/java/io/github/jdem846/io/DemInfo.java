package io.github.jdem846.io;

import io.github.jdem846.raster.GridGeometry;
import java.util.List;
import java.util.Objects;

/**
 * What a DEM file declares, read from its header without decoding the elevations; for a mosaic of several
 * files ({@link DemFormat#MOSAIC}, {@link DemFormat#VRT}), what the files declare together.
 *
 * @param source         the file (or the bundled sample's name; for a mosaic, the {@code .vrt} or a short list of
 *                       the files)
 * @param format         the file format
 * @param dataType       how elevations are stored
 * @param bands          number of bands in the file (band 1 is read)
 * @param geometry       grid size, georeferencing (outer-corner form) and CRS
 * @param declaredNoData the no-data value the file declares; {@code null} when it declares none, NaN when it
 *                       declares NaN
 * @param notices        things a person should know (assumptions, ignored bands, unresolved CRS codes)
 * @param members        the files of a mosaic, in the order they are read (the data file of each); empty for one
 *                       file
 */
public record DemInfo(String source, DemFormat format, SampleType dataType, int bands, GridGeometry geometry,
                      Double declaredNoData, List<String> notices, List<java.nio.file.Path> members) {

    /**
     * Checks that source, format, data type and geometry are given, and copies the lists.
     *
     * @param source the file (or the bundled sample's name; for a mosaic, the {@code .vrt} or a short list of the
     *     files)
     * @param format the file format
     * @param dataType how elevations are stored
     * @param bands number of bands in the file (band 1 is read)
     * @param geometry grid size, georeferencing (outer-corner form) and CRS
     * @param declaredNoData the no-data value the file declares; {@code null} when it declares none, NaN when it
     *     declares NaN
     * @param notices things a person should know (assumptions, ignored bands, unresolved CRS codes)
     * @param members the files of a mosaic, in the order they are read (the data file of each); empty for one file
     */
    public DemInfo {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(format, "format");
        Objects.requireNonNull(dataType, "dataType");
        Objects.requireNonNull(geometry, "geometry");
        notices = List.copyOf(notices);
        members = List.copyOf(members);
    }

    /**
     * The header of one file (no members).
     *
     * @param source the file (or the bundled sample's name; for a mosaic, the {@code .vrt} or a short list of the
     *     files)
     * @param format the file format
     * @param dataType how elevations are stored
     * @param bands number of bands in the file (band 1 is read)
     * @param geometry grid size, georeferencing (outer-corner form) and CRS
     * @param declaredNoData the no-data value the file declares; {@code null} when it declares none, NaN when it
     *     declares NaN
     * @param notices things a person should know (assumptions, ignored bands, unresolved CRS codes)
     */
    public DemInfo(String source, DemFormat format, SampleType dataType, int bands, GridGeometry geometry,
                   Double declaredNoData, List<String> notices) {
        this(source, format, dataType, bands, geometry, declaredNoData, notices, List.of());
    }

    /** {@return true when this describes several files read as one grid} */
    public boolean isMosaic() {
        return !members.isEmpty();
    }

    /**
     * A copy with other notices (e.g. with those learned while reading).
     *
     * @param newNotices the notices
     * @return the copy
     */
    public DemInfo withNotices(List<String> newNotices) {
        return new DemInfo(source, format, dataType, bands, geometry, declaredNoData, newNotices, members);
    }

    /**
     * A copy with another geometry (e.g. with the CRS completed by Apache SIS).
     *
     * @param newGeometry the geometry
     * @return the copy
     */
    public DemInfo withGeometry(GridGeometry newGeometry) {
        return new DemInfo(source, format, dataType, bands, newGeometry, declaredNoData, notices, members);
    }

    /** {@return columns} */
    public int width() {
        return geometry.width();
    }

    /** {@return rows} */
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
        return g == geometry ? this : withGeometry(g);
    }

    /** {@return the declared no-data value as {@link io.github.jdem846.raster.Dem} takes it: NaN when none} */
    public double noDataOrNaN() {
        return declaredNoData != null ? declaredNoData : Double.NaN;
    }
}
