package io.github.jdem846.output;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;

/**
 * Rows of pixels handed to an encoder: a whole picture or one band of it, each row given in the sample layout of
 * the files (8-bit R, G, B, A interleaved for RGBA; one byte for gray; four little-endian bytes for float32), which
 * PNG and TIFF share. The arrays of a band may be longer than {@code width × height}: rows past the band are not
 * read.
 */
sealed interface Pixels {

    int width();

    /** @return rows held (of a band: the band's rows) */
    int height();

    /** Samples per pixel: 4 for RGBA, 1 otherwise. */
    int samplesPerPixel();

    /** Bits per sample: 8, or 32 for float. */
    int bitsPerSample();

    /** @return bytes of one row in the file's layout: samples interleaved (R, G, B, A for RGBA), little-endian */
    default int rowBytes() {
        return rowBytes(width(), samplesPerPixel(), bitsPerSample());
    }

    /** Copies row {@code y} into {@code dst} from index {@code offset}, in the layout of {@link #rowBytes()}. */
    default void row(int y, byte[] dst, int offset) {
        row(y, 0, width(), dst, offset);
    }

    /** Copies pixels {@code [x0, x0 + count)} of row {@code y} into {@code dst} from index {@code offset}. */
    void row(int y, int x0, int count, byte[] dst, int offset);

    /**
     * Bytes of one row of {@code width} pixels.
     *
     * @throws IllegalArgumentException when one row would not fit in a Java array
     */
    static int rowBytes(int width, int samplesPerPixel, int bitsPerSample) {
        long bytes = (long) width * samplesPerPixel * bitsPerSample / 8;
        if (bytes > Integer.MAX_VALUE - 16) {
            throw new IllegalArgumentException("a row of " + width + " pixels (" + bytes + " bytes) is more than "
                    + "one Java array can hold");
        }
        return (int) bytes;
    }

    /** Checks that an array of {@code length} elements holds {@code width × rows} pixels from index 0. */
    private static void checkHolds(int length, int width, int rows) {
        if (width < 1 || rows < 1) {
            throw new IllegalArgumentException("image size must be at least 1×1, got " + width + "×" + rows);
        }
        if ((long) width * rows > length) {
            throw new IllegalArgumentException(rows + " rows of " + width + " pixels need " + (long) width * rows
                    + " elements, the array has " + length);
        }
    }

    /** Non-premultiplied ARGB, alpha 0 = no-data. */
    record Argb(int[] argb, int width, int height) implements Pixels {
        public Argb {
            checkHolds(argb.length, width, height);
        }

        @Override
        public int samplesPerPixel() {
            return 4;
        }

        @Override
        public int bitsPerSample() {
            return 8;
        }

        @Override
        public void row(int y, int x0, int count, byte[] dst, int offset) {
            int base = y * width + x0;
            for (int x = 0, j = offset; x < count; x++) {
                int p = argb[base + x];
                dst[j++] = (byte) (p >>> 16);
                dst[j++] = (byte) (p >>> 8);
                dst[j++] = (byte) p;
                dst[j++] = (byte) (p >>> 24);
            }
        }
    }

    /** 8-bit unsigned samples. */
    record Gray(byte[] gray, int width, int height) implements Pixels {
        public Gray {
            checkHolds(gray.length, width, height);
        }

        @Override
        public int samplesPerPixel() {
            return 1;
        }

        @Override
        public int bitsPerSample() {
            return 8;
        }

        @Override
        public void row(int y, int x0, int count, byte[] dst, int offset) {
            System.arraycopy(gray, y * width + x0, dst, offset, count);
        }
    }

    /** IEEE float32 samples. */
    record Float32(float[] values, int width, int height) implements Pixels {
        public Float32 {
            checkHolds(values.length, width, height);
        }

        @Override
        public int samplesPerPixel() {
            return 1;
        }

        @Override
        public int bitsPerSample() {
            return 32;
        }

        @Override
        public void row(int y, int x0, int count, byte[] dst, int offset) {
            int base = y * width + x0;
            for (int x = 0, j = offset; x < count; x++) {
                int bits = Float.floatToRawIntBits(values[base + x]);
                dst[j++] = (byte) bits;
                dst[j++] = (byte) (bits >>> 8);
                dst[j++] = (byte) (bits >>> 16);
                dst[j++] = (byte) (bits >>> 24);
            }
        }
    }

    /** Rows already in the file's layout, one after another: the rows an encoder keeps between two bands. */
    record Encoded(byte[] bytes, int width, int height, int samplesPerPixel, int bitsPerSample) implements Pixels {
        public Encoded {
            checkHolds(bytes.length, Pixels.rowBytes(width, samplesPerPixel, bitsPerSample), height);
        }

        @Override
        public void row(int y, int x0, int count, byte[] dst, int offset) {
            int pixelBytes = samplesPerPixel * bitsPerSample / 8;
            System.arraycopy(bytes, y * rowBytes() + x0 * pixelBytes, dst, offset, count * pixelBytes);
        }
    }

    /**
     * Any {@link BufferedImage}: {@code TYPE_BYTE_GRAY} as gray samples, every other type as RGBA ({@code
     * TYPE_INT_ARGB} as stored, others through {@code getRGB}, i.e. converted to sRGB).
     */
    record Image(BufferedImage image) implements Pixels {

        @Override
        public int width() {
            return image.getWidth();
        }

        @Override
        public int height() {
            return image.getHeight();
        }

        @Override
        public int samplesPerPixel() {
            return image.getType() == BufferedImage.TYPE_BYTE_GRAY ? 1 : 4;
        }

        @Override
        public int bitsPerSample() {
            return 8;
        }

        @Override
        public void row(int y, int x0, int count, byte[] dst, int offset) {
            Raster raster = image.getRaster();
            if (samplesPerPixel() == 1) {
                byte[] gray = offset == 0 ? dst : new byte[count];
                raster.getDataElements(x0, y, count, 1, gray);
                if (gray != dst) {
                    System.arraycopy(gray, 0, dst, offset, count);
                }
                return;
            }
            int[] pixels = new int[count];
            if (image.getType() == BufferedImage.TYPE_INT_ARGB) {
                raster.getDataElements(x0, y, count, 1, pixels);
            } else {
                image.getRGB(x0, y, count, 1, pixels, 0, count);
            }
            new Argb(pixels, count, 1).row(0, dst, offset);
        }
    }
}
