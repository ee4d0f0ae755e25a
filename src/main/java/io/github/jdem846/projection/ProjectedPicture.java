package io.github.jdem846.projection;

import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * A picture in a map projection ({@link ProjectedRender}).
 *
 * @param projection the projection
 * @param extent     the area it covers, in the projection's units
 * @param width      pixels across
 * @param height     pixels down
 * @param argb       non-premultiplied 0xAARRGGBB pixels, row 0 north, transparent off the map and outside the DEM.
 *                   Owned by this record: do not modify
 */
public record ProjectedPicture(MapProjection projection, ProjectedExtent extent, int width, int height,
                               int[] argb) {

    /**
     * Checks that projection and extent are given and that there are {@code width × height} pixels.
     *
     * @param projection the projection
     * @param extent the area it covers, in the projection's units
     * @param width pixels across
     * @param height pixels down
     * @param argb non-premultiplied 0xAARRGGBB pixels, row 0 north, transparent off the map and outside the DEM. Owned
     *     by this record: do not modify
     */
    public ProjectedPicture {
        Objects.requireNonNull(projection, "projection");
        Objects.requireNonNull(extent, "extent");
        if (argb.length != (long) width * height) {
            throw new IllegalArgumentException(argb.length + " pixels for a " + width + " × " + height
                    + " picture");
        }
    }

    /** {@return where the picture lies, in the projection's CRS (EPSG code when it has one, else its WKT)} */
    public GeoReference geoReference() {
        return new GeoReference(extent.west(), extent.north(), extent.east(), extent.south(),
                projection.crsInfo());
    }

    /** {@return a {@code TYPE_INT_ARGB} image backed by the pixels (no copy)} */
    public BufferedImage toBufferedImage() {
        return ImageOutput.toBufferedImage(argb, width, height);
    }

    /**
     * Writes the picture, all or nothing: PNG or GeoTIFF by the extension, georeferenced in the projection (a
     * GeoTIFF's GeoKeys name an EPSG code when the CRS has one; the {@code .prj} of a PNG holds its WKT).
     *
     * @param file    the image file
     * @param options how to write it
     * @return the files written
     * @throws IOException when the file cannot be written
     */
    public WriteResult write(Path file, WriteOptions options) throws IOException {
        return ImageOutput.writeRgba(file, argb, width, height, geoReference(), options);
    }
}
