package io.github.jdem846.projection;

import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * An 8-bit gray product (hillshade, shadow mask, sky view) in a map projection ({@link ProjectedRender#warpGray}).
 *
 * @param projection the projection
 * @param extent     the area it covers, in the projection's units
 * @param width      pixels across
 * @param height     pixels down
 * @param gray       0..255 samples, row 0 north; owned by this record: do not modify
 * @param noData     the value of pixels off the map, outside the DEM or without data, or null when the product has
 *                   none (a shadow mask: those pixels are 0)
 */
public record ProjectedGray(MapProjection projection, ProjectedExtent extent, int width, int height, byte[] gray,
                            Integer noData) {

    /**
     * Checks that projection and extent are given and that there are {@code width × height} samples.
     *
     * @param projection the projection
     * @param extent the area it covers, in the projection's units
     * @param width pixels across
     * @param height pixels down
     * @param gray 0..255 samples, row 0 north; owned by this record: do not modify
     * @param noData the value of pixels off the map, outside the DEM or without data, or null when the product has none
     */
    public ProjectedGray {
        Objects.requireNonNull(projection, "projection");
        Objects.requireNonNull(extent, "extent");
        if (gray.length != (long) width * height) {
            throw new IllegalArgumentException(gray.length + " samples for a " + width + " × " + height
                    + " picture");
        }
    }

    /** {@return where the picture lies, in the projection's CRS} */
    public GeoReference geoReference() {
        return new GeoReference(extent.west(), extent.north(), extent.east(), extent.south(),
                projection.crsInfo());
    }

    /**
     * Writes the picture, all or nothing: PNG or GeoTIFF by the extension, georeferenced in the projection; a
     * GeoTIFF marks {@link #noData()} as no-data unless {@code options} name another value.
     *
     * @param file    the image file
     * @param options how to write it
     * @return the files written
     * @throws IOException when the file cannot be written
     */
    public WriteResult write(Path file, WriteOptions options) throws IOException {
        WriteOptions o = noData != null && options.noData() == null ? options.withNoData(noData) : options;
        return ImageOutput.writeGray(file, gray, width, height, geoReference(), o);
    }
}
