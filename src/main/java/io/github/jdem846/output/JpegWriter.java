package io.github.jdem846.output;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.function.LongConsumer;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.event.IIOWriteProgressListener;
import javax.imageio.stream.ImageOutputStream;

/**
 * Encodes a JPEG with the JDK's baseline encoder (javax.imageio), 4:2:0 YCbCr for colour, gray for gray pictures.
 * JPEG has no transparency: RGBA rows are laid on an opaque background as they come. The encoder needs the whole
 * picture, so the rows are kept in memory (3 bytes a pixel, 1 for gray) until {@link #finish()}; the size is
 * checked against JPEG's limit (65 535 pixels a side) and one Java array before any row.
 */
final class JpegWriter implements BandEncoder {

    /** JPEG's largest width or height. */
    static final int MAX_SIDE = 65_535;

    private final Path file;
    private final int width;
    private final int height;
    private final int samplesPerPixel;
    private final float quality;
    private final int background;
    private final BufferedImage image;
    private final byte[] pixels;
    private LongConsumer encoded = rows -> { };
    private int rows;

    /**
     * @param background opaque 0xRRGGBB under transparent pixels (RGBA only)
     * @throws IllegalArgumentException when the picture exceeds JPEG's size or one array
     */
    JpegWriter(Path file, int width, int height, int samplesPerPixel, int quality, int background) {
        checkSize(file, width, height, samplesPerPixel);
        this.file = file;
        this.width = width;
        this.height = height;
        this.samplesPerPixel = samplesPerPixel;
        this.quality = quality / 100f;
        this.background = background;
        this.image = new BufferedImage(width, height,
                samplesPerPixel == 1 ? BufferedImage.TYPE_BYTE_GRAY : BufferedImage.TYPE_3BYTE_BGR);
        this.pixels = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
    }

    /**
     * Refuses a picture JPEG or memory cannot hold, before anything is written.
     *
     * @throws IllegalArgumentException naming the file, the size and what to do
     */
    static void checkSize(Path file, int width, int height, int samplesPerPixel) {
        if (width > MAX_SIDE || height > MAX_SIDE) {
            throw new IllegalArgumentException("a JPEG is at most " + MAX_SIDE + " pixels a side, '" + file
                    + "' would be " + width + "×" + height + "; write a .png or .tif instead");
        }
        long bytes = (long) width * height * (samplesPerPixel == 1 ? 1 : 3);
        if (bytes > Integer.MAX_VALUE - 16) {
            throw new IllegalArgumentException("a JPEG is encoded in memory, at most " + (Integer.MAX_VALUE - 16)
                    + " bytes of pixels; '" + file + "' (" + width + "×" + height + ") needs " + bytes
                    + "; write a .png or .tif, which are streamed, instead");
        }
    }

    @Override
    public void append(Pixels band) throws IOException {
        if (band.samplesPerPixel() != samplesPerPixel || band.bitsPerSample() != 8) {
            throw new IllegalArgumentException("a JPEG holds 8-bit " + (samplesPerPixel == 1 ? "gray" : "RGB")
                    + " pixels");
        }
        if (rows + band.height() > height) {
            throw new IllegalStateException(band.height() + " rows after " + rows + " pass the bottom of a "
                    + height + "-row image");
        }
        byte[] row = new byte[width * samplesPerPixel];
        int br = background >>> 16 & 0xff;
        int bg = background >>> 8 & 0xff;
        int bb = background & 0xff;
        for (int y = 0; y < band.height(); y++) {
            band.row(y, row, 0);
            int out = (rows + y) * width * (samplesPerPixel == 1 ? 1 : 3);
            if (samplesPerPixel == 1) {
                System.arraycopy(row, 0, pixels, out, width);
                continue;
            }
            for (int x = 0, i = 0; x < width; x++, i += 4) {
                int a = row[i + 3] & 0xff;
                // BGR order of TYPE_3BYTE_BGR; straight alpha over the opaque background, rounded.
                pixels[out++] = (byte) over(row[i + 2] & 0xff, bb, a);
                pixels[out++] = (byte) over(row[i + 1] & 0xff, bg, a);
                pixels[out++] = (byte) over(row[i] & 0xff, br, a);
            }
        }
        rows += band.height();
    }

    /** {@code c} with alpha {@code a} over the opaque {@code under}, 0..255, rounded to nearest. */
    static int over(int c, int under, int a) {
        return (c * a + under * (255 - a) + 127) / 255;
    }

    @Override
    public void finish() throws IOException {
        if (rows != height) {
            throw new IllegalStateException("only " + rows + " of " + height + " rows were appended");
        }
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("jpeg");
        if (!writers.hasNext()) {
            throw new IOException("this Java runtime has no JPEG encoder (javax.imageio)");
        }
        ImageWriter writer = writers.next();
        try (ImageOutputStream out = ImageIO.createImageOutputStream(Files.newOutputStream(file))) {
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(quality);
            writer.setOutput(out);
            writer.addIIOWriteProgressListener(new RowsEncoded());
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    @Override
    public long rowsToEncode() {
        return height;
    }

    @Override
    public void onEncoded(LongConsumer rowsEncoded) {
        this.encoded = rowsEncoded;
    }

    @Override
    public void close() {
        // Nothing is open between finish() calls; an unfinished file is the staged temporary, deleted by the sink.
    }

    /** The encoder's percentage done as rows, in increasing steps, ending at the height. */
    private final class RowsEncoded implements IIOWriteProgressListener {
        private long reported;

        private void reportUpTo(long done) {
            if (done > reported) {
                encoded.accept(done - reported);
                reported = done;
            }
        }

        @Override
        public void imageProgress(ImageWriter source, float percentageDone) {
            reportUpTo(Math.min(height, (long) Math.floor(percentageDone / 100.0 * height)));
        }

        @Override
        public void imageComplete(ImageWriter source) {
            reportUpTo(height);
        }

        @Override
        public void imageStarted(ImageWriter source, int imageIndex) {
        }

        @Override
        public void thumbnailStarted(ImageWriter source, int imageIndex, int thumbnailIndex) {
        }

        @Override
        public void thumbnailProgress(ImageWriter source, float percentageDone) {
        }

        @Override
        public void thumbnailComplete(ImageWriter source) {
        }

        @Override
        public void writeAborted(ImageWriter source) {
        }
    }
}
