package io.github.jdem846.output;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * An {@link ImageSink} that gathers the rows in one array and writes the picture at {@link #commit()} through
 * {@link ImageOutput}: the whole picture is held in memory (one Java array).
 */
final class BufferedImageSink implements ImageSink {

    private final Path file;
    private final int width;
    private final int height;
    private final GeoReference geo;
    private final WriteOptions options;
    private final int[] argb;
    private final byte[] gray;
    private int rows;

    BufferedImageSink(Path file, int width, int height, boolean rgba, GeoReference geo, WriteOptions options) {
        this.file = Objects.requireNonNull(file, "file");
        this.options = Objects.requireNonNull(options, "options");
        ImageFormat.of(file);
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1×1, got " + width + "×" + height);
        }
        if ((long) width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a " + width + "×" + height + " image is more than one Java array"
                    + " can hold");
        }
        this.width = width;
        this.height = height;
        this.geo = geo;
        this.argb = rgba ? new int[Math.multiplyExact(width, height)] : null;
        this.gray = rgba ? null : new byte[Math.multiplyExact(width, height)];
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
    public void appendRgba(int[] pixels, int count) {
        if (argb == null) {
            throw new IllegalStateException("this sink holds gray pixels");
        }
        checkRows(pixels.length, count);
        System.arraycopy(pixels, 0, argb, rows * width, count * width);
        rows += count;
    }

    @Override
    public void appendGray(byte[] samples, int count) {
        if (gray == null) {
            throw new IllegalStateException("this sink holds RGBA pixels");
        }
        checkRows(samples.length, count);
        System.arraycopy(samples, 0, gray, rows * width, count * width);
        rows += count;
    }

    private void checkRows(int length, int count) {
        if (count < 0 || rows + count > height) {
            throw new IllegalStateException(count + " rows after " + rows + " pass the bottom of a " + height
                    + "-row image");
        }
        if ((long) count * width > length) {
            throw new IllegalArgumentException(count + " rows of " + width + " need " + (long) count * width
                    + " samples, got " + length);
        }
    }

    @Override
    public WriteResult commit() throws IOException {
        if (rows != height) {
            throw new IllegalStateException("only " + rows + " of " + height + " rows were appended");
        }
        WriteResult result = argb != null ? ImageOutput.writeRgba(file, argb, width, height, geo, options)
                : ImageOutput.writeGray(file, gray, width, height, geo, options);
        return result;
    }

    @Override
    public void close() {
        // nothing is staged before commit: the pixels are only in memory
    }
}
