package io.github.jdem846.output;

import io.github.jdem846.render.RenderProgress;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * Writes the renderer's products as image files, the format chosen from the file extension ({@link ImageFormat}):
 * PNG ({@code .png}) or GeoTIFF ({@code .tif}, {@code .tiff}; in strips or as a Cloud-Optimized GeoTIFF,
 * {@link WriteOptions#tiffLayout()}), the whole picture at once or band of rows by band of rows ({@link ImageSink}).
 *
 * <p>Writing is all or nothing: the image and its sidecars are written to temporary files in the target directory
 * and renamed into place only when all are complete, the image first; on any failure the temporary files are
 * deleted and an existing file of the same name is left unchanged. A missing or unwritable directory or a read-only
 * existing file is reported before any encoding, as an {@link IOException} naming the file.
 *
 * <p>Georeferencing ({@link GeoReference}, may be {@code null}) goes into GeoTIFF tags, and into a world file
 * ({@code .pgw}/{@code .tfw}/{@code .wld}), an ESRI {@code .prj} and a GDAL {@code .aux.xml} (the CRS; GDAL does
 * not read a {@code .prj} next to a PNG) as {@link WriteOptions#sidecars()} says. When
 * sidecars are due, a sidecar of an earlier run that would now be wrong (no georeferencing, or no known CRS for the
 * {@code .prj}) is deleted and a notice says so.
 *
 * <p>All methods are thread-safe; the pixel arrays are only read.
 */
public final class ImageOutput {

    private ImageOutput() {
    }

    /**
     * Writes an 8-bit RGBA image: PNG colour type 6, or a 4-band GeoTIFF with unassociated alpha.
     *
     * @param file    the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param argb    non-premultiplied ARGB pixels, row-major, {@code width × height}; no-data pixels have alpha 0
     *                ({@link WriteOptions#noData()} is not used: alpha is the mask)
     * @param width   pixels across
     * @param height  pixels down
     * @param geo     where the image lies on the ground, or {@code null}
     * @param options how to write
     * @return the files written and notices for the user
     * @throws IllegalArgumentException for an unsupported extension or an array that does not match the size
     * @throws IOException              naming the file when it cannot be written
     */
    public static WriteResult writeRgba(Path file, int[] argb, int width, int height, GeoReference geo,
                                        WriteOptions options) throws IOException {
        Objects.requireNonNull(argb, "argb");
        Rasters.checkLength(argb.length, width, height);
        return writeRgba(file, argb, width, height, geo, options, RenderProgress.NONE);
    }

    /**
     * {@link #writeRgba(Path, int[], int, int, GeoReference, WriteOptions)}, telling {@code progress} the rows
     * written (stage {@value RenderProgress#WRITE}: rows of every PNG segment, TIFF strip or COG tile row as it is
     * written, for a COG every level's rows; it ends at its total once the file is complete). The bytes written do
     * not depend on it.
     *
     * @param file     the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param argb     non-premultiplied ARGB pixels, row-major, {@code width × height}
     * @param width    pixels across
     * @param height   pixels down
     * @param geo      where the image lies on the ground, or {@code null}
     * @param options  how to write
     * @param progress told of the rows written, on the calling thread
     * @return the files written and notices for the user
     * @throws IOException naming the file when it cannot be written
     */
    public static WriteResult writeRgba(Path file, int[] argb, int width, int height, GeoReference geo,
                                        WriteOptions options, RenderProgress progress) throws IOException {
        Objects.requireNonNull(argb, "argb");
        Rasters.checkLength(argb.length, width, height);
        return write(file, new Pixels.Argb(argb, width, height), geo, options, null, progress);
    }

    /**
     * Writes an 8-bit single-band image (a hillshade, a shadow mask): PNG colour type 0 or a gray GeoTIFF, whose
     * GDAL_NODATA tag is {@link WriteOptions#noData()} when given (an integer 0..255; hillshades use 0).
     *
     * @param file    the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param gray    samples 0..255 as unsigned bytes, row-major, {@code width × height}
     * @param width   pixels across
     * @param height  pixels down
     * @param geo     where the image lies on the ground, or {@code null}
     * @param options how to write
     * @return the files written and notices for the user
     * @throws IllegalArgumentException for an unsupported extension, a size that does not match or a no-data value
     *                                  outside 0..255
     * @throws IOException              naming the file when it cannot be written
     */
    public static WriteResult writeGray(Path file, byte[] gray, int width, int height, GeoReference geo,
                                        WriteOptions options) throws IOException {
        Objects.requireNonNull(gray, "gray");
        Rasters.checkLength(gray.length, width, height);
        return writeGray(file, gray, width, height, geo, options, RenderProgress.NONE);
    }

    /**
     * {@link #writeGray(Path, byte[], int, int, GeoReference, WriteOptions)}, telling {@code progress} the rows
     * written, as {@link #writeRgba(Path, int[], int, int, GeoReference, WriteOptions, RenderProgress)} does.
     *
     * @param file     the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param gray     samples 0..255 as unsigned bytes, row-major, {@code width × height}
     * @param width    pixels across
     * @param height   pixels down
     * @param geo      where the image lies on the ground, or {@code null}
     * @param options  how to write
     * @param progress told of the rows written, on the calling thread
     * @return the files written and notices for the user
     * @throws IOException naming the file when it cannot be written
     */
    public static WriteResult writeGray(Path file, byte[] gray, int width, int height, GeoReference geo,
                                        WriteOptions options, RenderProgress progress) throws IOException {
        Objects.requireNonNull(gray, "gray");
        Rasters.checkLength(gray.length, width, height);
        return write(file, new Pixels.Gray(gray, width, height), geo, options, options.noData(), progress);
    }

    /**
     * Writes a float32 single-band GeoTIFF (numeric products such as a shadow depth or a sky-view factor), with
     * GDAL_NODATA = {@link WriteOptions#noData()} when given (NaN allowed).
     *
     * @param file    the target, {@code .tif} or {@code .tiff}
     * @param values  samples, row-major, {@code width × height}
     * @param width   pixels across
     * @param height  pixels down
     * @param geo     where the image lies on the ground, or {@code null}
     * @param options how to write
     * @return the files written and notices for the user
     * @throws IllegalArgumentException for another extension or an array that does not match the size
     * @throws IOException              naming the file when it cannot be written
     */
    public static WriteResult writeFloat(Path file, float[] values, int width, int height, GeoReference geo,
                                         WriteOptions options) throws IOException {
        Objects.requireNonNull(values, "values");
        if (ImageFormat.of(file) != ImageFormat.GEOTIFF) {
            throw new IllegalArgumentException("float32 images can only be written as GeoTIFF (.tif, .tiff), not '"
                    + file + "'");
        }
        Rasters.checkLength(values.length, width, height);
        return write(file, new Pixels.Float32(values, width, height), geo, options, options.noData(),
                RenderProgress.NONE);
    }

    /**
     * Opens an RGBA image to be written band of rows by band of rows ({@link ImageSink}); the file is the one
     * {@link #writeRgba} writes for the same pixels, byte for byte, however the rows are cut into bands. The rows
     * are encoded as they come into a temporary file next to the target: memory is bounded by a band and the
     * encoder's buffers, not by the picture (see docs/output.md, "Streaming writes").
     *
     * @param file    the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param width   pixels across
     * @param height  pixels down
     * @param geo     where the image lies on the ground, or {@code null}
     * @param options how to write
     * @return the sink; close it (try-with-resources) whether or not it was committed
     * @throws IllegalArgumentException for an unsupported extension, size or layout
     * @throws IOException              naming the file when it or a sidecar cannot be written (checked before any
     *                                  pixel)
     */
    public static ImageSink openRgba(Path file, int width, int height, GeoReference geo, WriteOptions options)
            throws IOException {
        return openRgba(file, width, height, geo, options, RenderProgress.NONE);
    }

    /**
     * {@link #openRgba(Path, int, int, GeoReference, WriteOptions)}, telling {@code progress} the rows written (stage
     * {@value RenderProgress#WRITE}, as {@link #writeRgba(Path, int[], int, int, GeoReference, WriteOptions,
     * RenderProgress)} does; it ends at the commit).
     *
     * @param file     the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param width    pixels across
     * @param height   pixels down
     * @param geo      where the image lies on the ground, or {@code null}
     * @param options  how to write
     * @param progress told of the rows written, on the thread that appends
     * @return the sink; close it (try-with-resources) whether or not it was committed
     * @throws IOException naming the file when it or a sidecar cannot be written (checked before any pixel)
     */
    public static ImageSink openRgba(Path file, int width, int height, GeoReference geo, WriteOptions options,
                                     RenderProgress progress) throws IOException {
        return FileImageSink.open(file, width, height, 4, 8, geo, options, null, TiffDirectory.CLASSIC_LIMIT,
                progress);
    }

    /**
     * Opens an 8-bit single-band image to be written band of rows by band of rows ({@link ImageSink}); the file is
     * the one {@link #writeGray} writes for the same samples.
     *
     * @param file    the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param width   pixels across
     * @param height  pixels down
     * @param geo     where the image lies on the ground, or {@code null}
     * @param options how to write (its no-data value as for {@link #writeGray})
     * @return the sink; close it (try-with-resources) whether or not it was committed
     * @throws IllegalArgumentException for an unsupported extension, size, layout or no-data value
     * @throws IOException              naming the file when it or a sidecar cannot be written (checked before any
     *                                  pixel)
     */
    public static ImageSink openGray(Path file, int width, int height, GeoReference geo, WriteOptions options)
            throws IOException {
        return openGray(file, width, height, geo, options, RenderProgress.NONE);
    }

    /**
     * {@link #openGray(Path, int, int, GeoReference, WriteOptions)}, telling {@code progress} the rows written, as
     * {@link #openRgba(Path, int, int, GeoReference, WriteOptions, RenderProgress)} does.
     *
     * @param file     the target; {@code .png}, {@code .tif} or {@code .tiff}
     * @param width    pixels across
     * @param height   pixels down
     * @param geo      where the image lies on the ground, or {@code null}
     * @param options  how to write
     * @param progress told of the rows written, on the thread that appends
     * @return the sink; close it (try-with-resources) whether or not it was committed
     * @throws IOException naming the file when it or a sidecar cannot be written (checked before any pixel)
     */
    public static ImageSink openGray(Path file, int width, int height, GeoReference geo, WriteOptions options,
                                     RenderProgress progress) throws IOException {
        Objects.requireNonNull(options, "options");
        return FileImageSink.open(file, width, height, 1, 8, geo, options, options.noData(),
                TiffDirectory.CLASSIC_LIMIT, progress);
    }

    /**
     * A {@code TYPE_INT_ARGB} image backed by {@code argb} (no copy: changes to one show in the other).
     *
     * @param argb   non-premultiplied ARGB pixels, row-major, {@code width × height}
     * @param width  pixels across
     * @param height pixels down
     * @return the image
     */
    public static BufferedImage toBufferedImage(int[] argb, int width, int height) {
        return Rasters.argbImage(Objects.requireNonNull(argb, "argb"), width, height);
    }

    /**
     * A {@code TYPE_BYTE_GRAY} image backed by {@code gray} (no copy). Its raster samples are the bytes; note that
     * Java treats this type as linear gray, so {@code getRGB} returns gamma-converted colours, not (v, v, v).
     *
     * @param gray   samples 0..255 as unsigned bytes, row-major, {@code width × height}
     * @param width  pixels across
     * @param height pixels down
     * @return the image
     */
    public static BufferedImage toBufferedImage(byte[] gray, int width, int height) {
        return Rasters.grayImage(Objects.requireNonNull(gray, "gray"), width, height);
    }

    /**
     * The world-file path for an image.
     *
     * @param image  the image file
     * @param naming the format's own extension or the generic one
     * @return {@code out.pgw}, {@code out.tfw} or {@code out.wld}
     */
    public static Path worldFilePath(Path image, WriteOptions.WorldFileNaming naming) {
        String ext = naming == WriteOptions.WorldFileNaming.WLD ? "wld" : ImageFormat.of(image).worldFileExtension();
        return sibling(image, ext);
    }

    /**
     * The {@code .prj} path for an image.
     *
     * @param image the image file
     * @return {@code out.prj}
     */
    public static Path prjPath(Path image) {
        ImageFormat.of(image);
        return sibling(image, "prj");
    }

    /**
     * The GDAL sidecar path for an image.
     *
     * @param image the image file
     * @return {@code out.png.aux.xml}
     */
    public static Path auxXmlPath(Path image) {
        ImageFormat.of(image);
        return image.resolveSibling(image.getFileName() + ".aux.xml");
    }

    /**
     * Every file a write of {@code file} with {@code options} may create, replace or delete: the image, then the
     * world file, {@code .prj} and {@code .aux.xml} when sidecars are due (they are also deleted as stale when the
     * image has no georeferencing or no known CRS). {@link InputProtection} checks them against the input's files
     * before any work.
     *
     * @param file    the image file
     * @param options how it will be written
     * @return the image, then the sidecars that the write may touch
     * @throws IllegalArgumentException for an unsupported extension, or the COG layout for a PNG
     */
    public static List<Path> filesWritten(Path file, WriteOptions options) {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(options, "options");
        ImageFormat format = ImageFormat.of(file);
        FileImageSink.checkLayout(file, format, options);
        if (!SidecarPlan.isDue(format, options)) {
            return List.of(file);
        }
        return List.of(file, worldFilePath(file, options.worldFileNaming()), prjPath(file), auxXmlPath(file));
    }

    /** The whole picture as one band. */
    private static WriteResult write(Path file, Pixels image, GeoReference geo, WriteOptions options,
                                     Double noData, RenderProgress progress) throws IOException {
        try (FileImageSink sink = FileImageSink.open(file, image.width(), image.height(), image.samplesPerPixel(),
                image.bitsPerSample(), geo, options, noData, TiffDirectory.CLASSIC_LIMIT, progress)) {
            sink.append(image);
            return sink.commit();
        }
    }

    private static Path sibling(Path image, String extension) {
        String name = image.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return image.resolveSibling(name.substring(0, dot) + "." + extension);
    }
}
