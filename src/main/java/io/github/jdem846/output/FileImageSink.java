package io.github.jdem846.output;

import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.StageProgress;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * The {@link ImageSink} of {@link ImageOutput}, and the way every file of it is written (the whole picture is one
 * band): rows go to the format's {@link BandEncoder} as they come, into a temporary file next to the target
 * ({@link StagedFiles}); {@link #commit()} finishes the file, stages the sidecars ({@link SidecarPlan}) and moves
 * them all into place; {@link #close()} without a commit deletes them. Memory is bounded by a band and the
 * encoder's buffers, not by the picture.
 */
final class FileImageSink implements ImageSink {

    private final Path file;
    private final int width;
    private final int height;
    private final int samplesPerPixel;
    private final SidecarPlan plan;
    private final StagedFiles staged;
    private final BandEncoder encoder;
    private final StageProgress progress;
    private final Integer background;
    private int rows;
    private boolean failed;
    private boolean committed;
    private boolean closed;

    private FileImageSink(Path file, int width, int height, int samplesPerPixel, SidecarPlan plan,
                          StagedFiles staged, BandEncoder encoder, StageProgress progress, Integer background) {
        this.file = file;
        this.width = width;
        this.height = height;
        this.samplesPerPixel = samplesPerPixel;
        this.plan = plan;
        this.staged = staged;
        this.encoder = encoder;
        this.progress = progress;
        this.background = background;
    }

    /**
     * Checks everything that can be checked before any pixel, then creates the temporary file.
     *
     * @param samplesPerPixel 4 (RGBA, 8 bits) or 1 (gray, 8 or 32 bits)
     * @param noData          the GDAL_NODATA value, or {@code null}
     * @param classicLimit    the largest GeoTIFF written as a classic TIFF ({@link TiffDirectory#CLASSIC_LIMIT})
     * @throws IllegalArgumentException for an unsupported extension, size, layout or no-data value
     * @throws IOException              naming the file when it or a sidecar cannot be written
     */
    static FileImageSink open(Path file, int width, int height, int samplesPerPixel, int bitsPerSample,
                              GeoReference geo, WriteOptions options, Double noData, long classicLimit)
            throws IOException {
        return open(file, width, height, samplesPerPixel, bitsPerSample, geo, options, noData, classicLimit,
                RenderProgress.NONE);
    }

    /**
     * As {@link #open(Path, int, int, int, int, GeoReference, WriteOptions, Double, long)}, telling {@code progress}
     * the rows written (stage {@value RenderProgress#WRITE}: {@link BandEncoder#rowsToEncode()} in all, reported as
     * the encoder writes its chunks and ended at the commit).
     */
    static FileImageSink open(Path file, int width, int height, int samplesPerPixel, int bitsPerSample,
                              GeoReference geo, WriteOptions options, Double noData, long classicLimit,
                              RenderProgress progress) throws IOException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(progress, "progress");
        Objects.requireNonNull(options, "options");
        ImageFormat format = ImageFormat.of(file);
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1×1, got " + width + "×" + height);
        }
        checkLayout(file, format, options);
        boolean cog = format == ImageFormat.GEOTIFF && options.tiffLayout() == WriteOptions.TiffLayout.COG;
        if (bitsPerSample == 32 && format != ImageFormat.GEOTIFF) {
            throw new IllegalArgumentException("float32 images can only be written as GeoTIFF (.tif, .tiff), not '"
                    + file + "'");
        }
        if (bitsPerSample == 32 && cog) {
            throw new IllegalArgumentException("a Cloud-Optimized GeoTIFF is written of 8-bit gray and RGBA "
                    + "pictures only; write the float32 '" + file + "' with the strip layout");
        }
        if (bitsPerSample == 8 && noData != null && !(noData >= 0 && noData <= 255 && noData == Math.rint(noData))) {
            throw new IllegalArgumentException("no-data of an 8-bit image must be an integer 0..255, got " + noData);
        }
        Pixels.rowBytes(width, samplesPerPixel, bitsPerSample);
        if (format == ImageFormat.JPEG) {
            JpegWriter.checkSize(file, width, height, samplesPerPixel);
        }
        SidecarPlan plan = SidecarPlan.checked(file, format, geo, width, height, options);
        StagedFiles staged = new StagedFiles();
        try {
            Path temp = staged.open(file);
            BandEncoder encoder = switch (format) {
                case JPEG -> new JpegWriter(temp, width, height, samplesPerPixel, options.jpegQuality(),
                        options.background() != null ? options.background() : WriteOptions.DEFAULT_JPEG_BACKGROUND);
                case PNG -> PngWriter.toFile(temp, width, height, samplesPerPixel, options.pngCompressionLevel(),
                        options.parallelCompression());
                case GEOTIFF -> cog
                        ? new CogWriter(temp, purpose -> staged.scratch(file, purpose), width, height, samplesPerPixel,
                                geo, noData, options.cogTileSize(), options.parallelCompression(), classicLimit)
                        : new GeoTiffWriter(temp, width, height, samplesPerPixel, bitsPerSample, geo, noData,
                                options.parallelCompression(), classicLimit);
            };
            StageProgress rows = new StageProgress(progress, RenderProgress.WRITE, encoder.rowsToEncode()).start();
            encoder.onEncoded(rows::add);
            return new FileImageSink(file, width, height, samplesPerPixel, plan, staged, encoder, rows,
                    options.background());
        } catch (IOException e) {
            staged.close();
            throw StagedFiles.withTarget(e, file);
        } catch (RuntimeException | Error e) {
            staged.close();
            throw e;
        }
    }

    /**
     * Refuses a layout the format does not have: the COG layout is a GeoTIFF's.
     *
     * @throws IllegalArgumentException naming the file
     */
    static void checkLayout(Path file, ImageFormat format, WriteOptions options) {
        if (options.tiffLayout() == WriteOptions.TiffLayout.COG && format != ImageFormat.GEOTIFF) {
            throw new IllegalArgumentException("a Cloud-Optimized GeoTIFF must be written to a .tif or .tiff file, "
                    + "not '" + file + "'");
        }
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public int rowsWritten() {
        return rows;
    }

    @Override
    public void appendRgba(int[] argb, int count) throws IOException {
        Objects.requireNonNull(argb, "argb");
        if (samplesPerPixel != 4) {
            throw new IllegalStateException("this sink holds gray pixels");
        }
        if (checkRows(argb.length, count)) {
            append(new Pixels.Argb(argb, width, count));
        }
    }

    @Override
    public void appendGray(byte[] gray, int count) throws IOException {
        Objects.requireNonNull(gray, "gray");
        if (samplesPerPixel != 1) {
            throw new IllegalStateException("this sink holds RGBA pixels");
        }
        if (checkRows(gray.length, count)) {
            append(new Pixels.Gray(gray, width, count));
        }
    }

    /** Appends the next rows in any layout the sink was opened for (the whole picture, float32 included). */
    void append(Pixels band) throws IOException {
        if (committed || closed || failed) {
            throw new IllegalStateException("the sink of " + file + " is " + (failed ? "broken by an earlier failure"
                    : committed ? "committed" : "closed"));
        }
        try {
            encoder.append(background != null && band instanceof Pixels.Argb rgba
                    ? new Pixels.Argb(Background.under(rgba.argb(), rgba.width() * rgba.height(), background),
                            rgba.width(), rgba.height())
                    : band);
        } catch (IOException e) {
            failed = true;
            throw StagedFiles.withTarget(e, file);
        } catch (RuntimeException | Error e) {
            failed = true;
            throw e;
        }
        rows += band.height();
    }

    /** @return whether there are rows to append: {@code count > 0} and they fit */
    private boolean checkRows(int length, int count) {
        if (count < 0 || (long) rows + count > height) {
            throw new IllegalStateException(count + " rows after " + rows + " pass the bottom of a " + height
                    + "-row image");
        }
        if ((long) count * width > length) {
            throw new IllegalArgumentException(count + " rows of " + width + " need " + (long) count * width
                    + " samples, got " + length);
        }
        return count > 0;
    }

    @Override
    public WriteResult commit() throws IOException {
        if (committed || closed || failed) {
            throw new IllegalStateException("the sink of " + file + " is " + (failed ? "broken by an earlier failure"
                    : committed ? "committed" : "closed"));
        }
        if (rows != height) {
            throw new IllegalStateException("only " + rows + " of " + height + " rows were appended");
        }
        List<Path> sidecars;
        try {
            encoder.finish();
            encoder.close();
            progress.finish();
            sidecars = plan.stage(staged);
            staged.commit();
        } catch (IOException e) {
            failed = true;
            throw StagedFiles.withTarget(e, file);
        } catch (RuntimeException | Error e) {
            failed = true;
            throw e;
        }
        committed = true;
        staged.close();
        return new WriteResult(file, sidecars, plan.removeStale());
    }

    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            encoder.close();
        } finally {
            staged.close();
        }
    }
}
