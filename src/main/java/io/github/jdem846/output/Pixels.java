package io.github.jdem846.output;

import java.awt.image.BufferedImage;

/** A product's pixels as handed to {@link ImageOutput}: row-major arrays of one of three sample layouts. */
sealed interface Pixels {

    int width();

    int height();

    /** Samples per pixel: 4 for RGBA, 1 otherwise. */
    int samplesPerPixel();

    /** Bits per sample: 8, or 32 for float. */
    int bitsPerSample();

    /** @return bytes of one row as stored in a little-endian TIFF: samples interleaved (R, G, B, A for RGBA) */
    default int rowBytes() {
        return width() * samplesPerPixel() * bitsPerSample() / 8;
    }

    /** Copies row {@code y} into {@code dst} in the layout of {@link #rowBytes()}. */
    void row(int y, byte[] dst);

    /** The pixels as a {@link BufferedImage} sharing the array (not available for float). */
    BufferedImage image();

    /** Non-premultiplied ARGB, alpha 0 = no-data. */
    record Argb(int[] argb, int width, int height) implements Pixels {
        public Argb {
            Rasters.checkLength(argb.length, width, height);
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
        public void row(int y, byte[] dst) {
            int base = y * width;
            for (int x = 0, j = 0; x < width; x++) {
                int p = argb[base + x];
                dst[j++] = (byte) (p >>> 16);
                dst[j++] = (byte) (p >>> 8);
                dst[j++] = (byte) p;
                dst[j++] = (byte) (p >>> 24);
            }
        }

        @Override
        public BufferedImage image() {
            return Rasters.argbImage(argb, width, height);
        }
    }

    /** 8-bit unsigned samples. */
    record Gray(byte[] gray, int width, int height) implements Pixels {
        public Gray {
            Rasters.checkLength(gray.length, width, height);
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
        public void row(int y, byte[] dst) {
            System.arraycopy(gray, y * width, dst, 0, width);
        }

        @Override
        public BufferedImage image() {
            return Rasters.grayImage(gray, width, height);
        }
    }

    /** IEEE float32 samples. */
    record Float32(float[] values, int width, int height) implements Pixels {
        public Float32 {
            Rasters.checkLength(values.length, width, height);
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
        public void row(int y, byte[] dst) {
            int base = y * width;
            for (int x = 0, j = 0; x < width; x++) {
                int bits = Float.floatToRawIntBits(values[base + x]);
                dst[j++] = (byte) bits;
                dst[j++] = (byte) (bits >>> 8);
                dst[j++] = (byte) (bits >>> 16);
                dst[j++] = (byte) (bits >>> 24);
            }
        }

        @Override
        public BufferedImage image() {
            return Rasters.floatImage(values, width, height);
        }
    }
}
