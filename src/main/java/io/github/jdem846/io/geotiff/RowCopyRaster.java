package io.github.jdem846.io.geotiff;

import java.awt.Point;
import java.awt.image.ComponentSampleModel;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferDouble;
import java.awt.image.DataBufferFloat;
import java.awt.image.DataBufferInt;
import java.awt.image.DataBufferShort;
import java.awt.image.DataBufferUShort;
import java.awt.image.PixelInterleavedSampleModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;

/**
 * A one-band raster, one array element per cell, row after row, whose {@link #setDataElements(int, int, Raster)}
 * copies whole rows with {@link System#arraycopy} when the source is a one-band raster of the same data type with
 * one element per cell. For short, int, float and double data the JDK's own rasters copy such rows cell by cell
 * through the sample model, and that copy is where a TIFF decoder writing row by row spends most of its time.
 * Any other source takes the JDK's general path, so the result is always the same as that of a standard raster.
 */
final class RowCopyRaster extends WritableRaster {

    private final Object array;

    private RowCopyRaster(DataBuffer buffer, int width, int height) {
        super(new PixelInterleavedSampleModel(buffer.getDataType(), width, height, 1, width, new int[] {0}), buffer,
                new Point(0, 0));
        this.array = arrayOf(buffer);
    }

    /**
     * A raster of {@code width × height} cells of a DataBuffer type (byte, ushort, short, int, float or double).
     *
     * @throws IllegalArgumentException for another data type or when the grid has more than 2^31 − 1 cells
     */
    static RowCopyRaster create(int dataType, int width, int height) {
        long cells = (long) width * height;
        if (width <= 0 || height <= 0 || cells > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("cannot hold " + width + " × " + height + " cells in one array");
        }
        int n = (int) cells;
        DataBuffer buffer = switch (dataType) {
            case DataBuffer.TYPE_BYTE -> new DataBufferByte(n);
            case DataBuffer.TYPE_USHORT -> new DataBufferUShort(n);
            case DataBuffer.TYPE_SHORT -> new DataBufferShort(n);
            case DataBuffer.TYPE_INT -> new DataBufferInt(n);
            case DataBuffer.TYPE_FLOAT -> new DataBufferFloat(n);
            case DataBuffer.TYPE_DOUBLE -> new DataBufferDouble(n);
            default -> throw new IllegalArgumentException("unsupported DataBuffer type " + dataType);
        };
        return new RowCopyRaster(buffer, width, height);
    }

    /** The cells, row after row: a byte[], short[], int[], float[] or double[] by the data type. */
    Object array() {
        return array;
    }

    /** Sets the cells from {@code (x + in.minX, y + in.minY)} on to those of {@code in}, like the JDK. */
    @Override
    public void setDataElements(int x, int y, Raster in) {
        int dstX = x + in.getMinX();
        int dstY = y + in.getMinY();
        int w = in.getWidth();
        int h = in.getHeight();
        Object source = rowSource(in);
        if (source == null || dstX < 0 || dstY < 0 || dstX + w > getWidth() || dstY + h > getHeight()) {
            super.setDataElements(x, y, in); // the JDK's own copy, and its own errors
            return;
        }
        ComponentSampleModel sm = (ComponentSampleModel) in.getSampleModel();
        DataBuffer db = in.getDataBuffer();
        int bank = sm.getBankIndices()[0];
        int from = db.getOffsets()[bank] + sm.getOffset(in.getMinX() - in.getSampleModelTranslateX(),
                in.getMinY() - in.getSampleModelTranslateY(), 0);
        int stride = sm.getScanlineStride();
        int to = dstY * getWidth() + dstX;
        for (int r = 0; r < h; r++) {
            System.arraycopy(source, from + r * stride, array, to + r * getWidth(), w);
        }
    }

    /** The array of {@code in} when rows of it can be copied element for element into this raster, else null. */
    private Object rowSource(Raster in) {
        DataBuffer db = in.getDataBuffer();
        if (!(in.getSampleModel() instanceof ComponentSampleModel sm) || sm.getNumBands() != 1
                || sm.getPixelStride() != 1 || db.getDataType() != getDataBuffer().getDataType()
                || in.getTransferType() != getTransferType()) {
            return null;
        }
        return arrayOf(db, sm.getBankIndices()[0]);
    }

    private static Object arrayOf(DataBuffer db) {
        return arrayOf(db, 0);
    }

    private static Object arrayOf(DataBuffer db, int bank) {
        if (db instanceof DataBufferByte b) {
            return b.getData(bank);
        }
        if (db instanceof DataBufferUShort b) {
            return b.getData(bank);
        }
        if (db instanceof DataBufferShort b) {
            return b.getData(bank);
        }
        if (db instanceof DataBufferInt b) {
            return b.getData(bank);
        }
        if (db instanceof DataBufferFloat b) {
            return b.getData(bank);
        }
        if (db instanceof DataBufferDouble b) {
            return b.getData(bank);
        }
        return null;
    }
}
