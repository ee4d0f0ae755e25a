package io.github.jdem846.projection;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.ImageIO;
import javax.imageio.ImageReadParam;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

/**
 * Rows of a TIFF picture written by jdem846 (8-bit RGBA or gray, in strips), read a window of rows at a time with
 * the JDK's TIFF reader ({@code javax.imageio}), which decodes only the strips the window touches.
 */
final class TiffRows implements PictureWarp.RowReader, AutoCloseable {

    private final ImageInputStream stream;
    private final ImageReader reader;
    private final int width;
    private final boolean rgba;

    private TiffRows(ImageInputStream stream, ImageReader reader, boolean rgba) throws IOException {
        this.stream = stream;
        this.reader = reader;
        this.width = reader.getWidth(0);
        this.rgba = rgba;
    }

    /**
     * Opens a TIFF file.
     *
     * @param file the file
     * @param rgba whether it holds RGBA pixels (else 8-bit gray)
     * @return the reader
     * @throws IOException when the file cannot be opened as a TIFF
     */
    static TiffRows open(Path file, boolean rgba) throws IOException {
        ImageReader reader = null;
        for (Iterator<ImageReader> readers = ImageIO.getImageReadersByFormatName("tiff"); readers.hasNext(); ) {
            ImageReader r = readers.next();
            // the JDK's own reader: others on the class path may refuse a highly compressed strip (a flat area)
            if (reader == null || r.getClass().getName().startsWith("com.sun.imageio.")) {
                reader = r;
            }
        }
        ImageInputStream stream = ImageIO.createImageInputStream(file.toFile());
        if (stream == null || reader == null) {
            if (stream != null) {
                stream.close();
            }
            throw new IOException("no TIFF reader for " + file);
        }
        reader.setInput(stream, true, true);
        return new TiffRows(stream, reader, rgba);
    }

    @Override
    public boolean rgba() {
        return rgba;
    }

    private BufferedImage read(int first, int count) throws IOException {
        ImageReadParam param = reader.getDefaultReadParam();
        param.setSourceRegion(new Rectangle(0, first, width, count));
        try {
            return reader.read(0, param);
        } catch (IOException | RuntimeException e) {
            throw new IOException("the temporary rendered picture cannot be read back (rows " + first + " to "
                    + (first + count - 1) + "): " + e.getMessage(), e);
        }
    }

    @Override
    public int[] rgbaRows(int first, int count) throws IOException {
        BufferedImage image = read(first, count);
        Raster raster = image.getRaster();
        int[] argb = new int[width * count];
        int[] sample = new int[4];
        for (int row = 0; row < count; row++) {
            for (int col = 0; col < width; col++) {
                raster.getPixel(col, row, sample);
                argb[row * width + col] = sample[3] << 24 | sample[0] << 16 | sample[1] << 8 | sample[2];
            }
        }
        return argb;
    }

    @Override
    public byte[] grayRows(int first, int count) throws IOException {
        Raster raster = read(first, count).getRaster();
        byte[] gray = new byte[width * count];
        int[] row = new int[width];
        for (int r = 0; r < count; r++) {
            raster.getSamples(0, r, width, 1, 0, row);
            for (int c = 0; c < width; c++) {
                gray[r * width + c] = (byte) row[c];
            }
        }
        return gray;
    }

    @Override
    public void close() throws IOException {
        reader.dispose();
        stream.close();
    }
}
