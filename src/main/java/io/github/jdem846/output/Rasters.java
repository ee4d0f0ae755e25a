package io.github.jdem846.output;

import java.awt.Point;
import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.SinglePixelPackedSampleModel;
import java.awt.image.WritableRaster;

/**
 * Wraps the renderer's pixel arrays as {@link BufferedImage}s without copying them. The images share the arrays:
 * a change to one shows in the other.
 */
final class Rasters {

    private Rasters() {
    }

    /** A {@code TYPE_INT_ARGB} image over non-premultiplied ARGB pixels, row-major. */
    static BufferedImage argbImage(int[] argb, int width, int height) {
        checkLength(argb.length, width, height);
        DirectColorModel cm = (DirectColorModel) ColorModel.getRGBdefault();
        SinglePixelPackedSampleModel sm = new SinglePixelPackedSampleModel(DataBuffer.TYPE_INT, width, height,
                cm.getMasks());
        WritableRaster raster = Raster.createWritableRaster(sm, new DataBufferInt(argb, argb.length), new Point());
        return new BufferedImage(cm, raster, false, null);
    }

    /** A {@code TYPE_BYTE_GRAY} image over 8-bit samples, row-major. */
    static BufferedImage grayImage(byte[] gray, int width, int height) {
        checkLength(gray.length, width, height);
        ComponentColorModel cm = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_GRAY),
                new int[]{8}, false, true, Transparency.OPAQUE, DataBuffer.TYPE_BYTE);
        WritableRaster raster = Raster.createInterleavedRaster(new DataBufferByte(gray, gray.length), width, height,
                width, 1, new int[]{0}, null);
        return new BufferedImage(cm, raster, false, null);
    }

    /** Checks the image size and that the array holds exactly {@code width × height} pixels. */
    static void checkLength(int length, int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1×1, got " + width + "×" + height);
        }
        if ((long) width * height != length) {
            throw new IllegalArgumentException("pixel array has " + length + " elements but a " + width + "×"
                    + height + " image needs " + (long) width * height);
        }
    }
}
