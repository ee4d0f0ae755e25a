package io.github.jdem846.job;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.sun.SunPosition;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * The picture a {@link ReliefJob} made: RGBA pixels ({@link Product#RELIEF}, {@link Product#TINT}) or 8-bit gray
 * ({@link Product#HILLSHADE}, {@link Product#SHADOWS}), row 0 = north, with the geometry of the cells they cover.
 *
 * @param job      the job that made it
 * @param source   the header of the DEM read, or {@code null} for a grid rendered from memory
 * @param geometry the grid the pixels cover (for world files and GeoTIFF tags)
 * @param argb     non-premultiplied 0xAARRGGBB pixels, no-data transparent; {@code null} for a gray product. Owned
 *                 by this record: do not modify
 * @param gray     0..255 samples (hillshade: 0 = no-data); {@code null} for an RGBA product. Owned by this
 *                 record: do not modify
 * @param sun      the sun by date and time at the centre of the picture, or {@code null} for a fixed light
 */
public record ReliefResult(ReliefJob job, DemInfo source, GridGeometry geometry, int[] argb, byte[] gray,
                           SunPosition sun) {

    /**
     * Checks that the job and geometry are given and that the result holds either RGBA or gray pixels.
     *
     * @param job the job that made it
     * @param source the header of the DEM read, or {@code null} for a grid rendered from memory
     * @param geometry the grid the pixels cover (for world files and GeoTIFF tags)
     * @param argb non-premultiplied 0xAARRGGBB pixels, no-data transparent; {@code null} for a gray product. Owned by
     *     this record: do not modify
     * @param gray 0..255 samples (hillshade: 0 = no-data); {@code null} for an RGBA product. Owned by this record: do
     *     not modify
     * @param sun the sun by date and time at the centre of the picture, or {@code null} for a fixed light
     */
    public ReliefResult {
        Objects.requireNonNull(job, "job");
        Objects.requireNonNull(geometry, "geometry");
        if ((argb == null) == (gray == null)) {
            throw new IllegalArgumentException("a result holds either RGBA or gray pixels");
        }
    }

    static ReliefResult rgba(ReliefJob job, DemInfo source, GridGeometry geometry, int[] argb, SunPosition sun) {
        return new ReliefResult(job, source, geometry, Objects.requireNonNull(argb, "argb"), null, sun);
    }

    static ReliefResult gray(ReliefJob job, DemInfo source, GridGeometry geometry, byte[] gray, SunPosition sun) {
        return new ReliefResult(job, source, geometry, null, Objects.requireNonNull(gray, "gray"), sun);
    }

    /** {@return pixels across} */
    public int width() {
        return geometry.width();
    }

    /** {@return pixels down} */
    public int height() {
        return geometry.height();
    }

    /**
     * The pixels as an image.
     *
     * @return a {@link BufferedImage} backed by the pixels (no copy): {@code TYPE_INT_ARGB} or {@code TYPE_BYTE_GRAY}
     */
    public BufferedImage toBufferedImage() {
        return argb != null ? ImageOutput.toBufferedImage(argb, width(), height())
                : ImageOutput.toBufferedImage(gray, width(), height());
    }

    /**
     * Writes the picture, all or nothing ({@link ImageOutput}): PNG or GeoTIFF by the extension, georeferenced.
     * A hillshade's GeoTIFF marks 0 as no-data unless {@code options} names another value; a shadow mask has no
     * no-data. An output that would replace or delete a file of the input is refused ({@link
     * ReliefJob#checkOutput}).
     *
     * @param file    the image file (its extension chooses the format)
     * @param options how to write it
     * @return the files written
     * @throws IOException when the file cannot be written, or is a file of the input
     */
    public WriteResult write(Path file, WriteOptions options) throws IOException {
        return write(file, options, RenderProgress.NONE);
    }

    /**
     * {@link #write(Path, WriteOptions)}, telling {@code progress} the rows written (stage {@value
     * RenderProgress#WRITE}, {@link ImageOutput#writeRgba(Path, int[], int, int, GeoReference, WriteOptions,
     * RenderProgress)}); the bytes written do not depend on it.
     *
     * @param file     the image file (its extension chooses the format)
     * @param options  how to write it
     * @param progress told of the rows written, on the calling thread
     * @return the files written
     * @throws IOException when the file cannot be written, or is a file of the input
     */
    public WriteResult write(Path file, WriteOptions options, RenderProgress progress) throws IOException {
        Objects.requireNonNull(progress, "progress");
        job.checkOutput(file, options);
        GeoReference geo = GeoReference.of(geometry);
        if (argb != null) {
            return ImageOutput.writeRgba(file, argb, width(), height(), geo, options, progress);
        }
        WriteOptions o = (job.product() == Product.HILLSHADE || job.product() == Product.SKY_VIEW)
                && options.noData() == null ? options.withNoData(0)
                : options;
        return ImageOutput.writeGray(file, gray, width(), height(), geo, o, progress);
    }
}
