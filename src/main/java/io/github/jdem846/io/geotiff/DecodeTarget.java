package io.github.jdem846.io.geotiff;

import java.awt.image.BufferedImage;
import java.awt.image.ComponentSampleModel;
import java.awt.image.Raster;
import java.awt.image.SampleModel;
import javax.imageio.ImageTypeSpecifier;

/**
 * The destination image a TIFF decoder writes one-band samples into: a {@link RowCopyRaster} of the decoder's own
 * raw image type, so that its rows are copied whole and nothing is converted. {@link #getData()} returns that
 * raster itself instead of a copy: TwelveMonkeys' {@code readRaster} is {@code read(…).getData()}, whose full copy
 * goes cell by cell for short, int and float data; this image belongs to one read, so nothing else sees the raster.
 */
final class DecodeTarget extends BufferedImage {

    private DecodeTarget(ImageTypeSpecifier rawType, RowCopyRaster raster) {
        super(rawType.getColorModel(), raster, rawType.getColorModel().isAlphaPremultiplied(), null);
    }

    /**
     * A {@code width × height} target for images of {@code rawType}, or null when that type is not one band with
     * one array element per cell (several bands, packed bits, palettes: left to the decoder's own destination).
     */
    static DecodeTarget forRawType(ImageTypeSpecifier rawType, int width, int height) {
        SampleModel sm = rawType.getSampleModel();
        if (!(sm instanceof ComponentSampleModel c) || c.getNumBands() != 1 || c.getPixelStride() != 1
                || rawType.getColorModel().getNumComponents() != 1 || (long) width * height > Integer.MAX_VALUE) {
            return null;
        }
        RowCopyRaster raster;
        try {
            raster = RowCopyRaster.create(sm.getDataType(), width, height);
        } catch (IllegalArgumentException e) {
            return null; // a data type without a standard buffer
        }
        if (!rawType.getColorModel().isCompatibleRaster(raster)) {
            return null;
        }
        return new DecodeTarget(rawType, raster);
    }

    /** The cells, row after row (see {@link RowCopyRaster#array()}). */
    Object array() {
        return ((RowCopyRaster) getRaster()).array();
    }

    /** The raster itself, not a copy (see the class comment). */
    @Override
    public Raster getData() {
        return getRaster();
    }
}
