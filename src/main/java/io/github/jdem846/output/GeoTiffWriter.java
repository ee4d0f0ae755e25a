package io.github.jdem846.output;

import io.github.jdem846.internal.GeoKeys;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.IntStream;
import java.util.zip.Deflater;

/**
 * A small baseline TIFF 6.0 writer for the one case the renderer needs: a single image, little-endian, strips of
 * about 64 KiB, Deflate compression (code 8, the zlib stream GDAL calls DEFLATE), chunky samples, and the GeoTIFF
 * tags ModelPixelScale (33550), ModelTiepoint (33922), GeoKeyDirectory (34735–34737) plus GDAL_NODATA (42113).
 * Sample layouts: 8-bit gray (BlackIsZero), 8-bit RGBA (RGB with unassociated alpha) and float32 gray. 8-bit data
 * use the horizontal differencing predictor (2), which makes relief images markedly smaller; float32 is stored
 * without predictor.
 *
 * <p>Why hand-written: TwelveMonkeys' TIFF writer (3.15.0) passes GeoTIFF tags through but cannot write float32
 * ("Not implemented for data type: 4"), and the JDK's own TIFF writer (17.0.15) truncates Deflate strips that do
 * not compress (noisy content), which GDAL and TwelveMonkeys then fail to decode. See docs/output.md.
 *
 * <p>File layout: header, strips in order, then the IFD and its out-of-line values (word-aligned). Classic TIFF
 * addresses at most 4 GiB; a larger file is refused with an IOException (BigTIFF is not written).
 */
final class GeoTiffWriter {

    static final int TAG_GDAL_NODATA = 42113;
    private static final int STRIP_TARGET_BYTES = 1 << 16;

    private static final short SHORT = 3;
    private static final short LONG = 4;
    private static final short ASCII = 2;
    private static final short DOUBLE = 12;

    private GeoTiffWriter() {
    }

    /**
     * Writes {@code pixels} to {@code file} (created or truncated).
     *
     * @param geo      the georeferencing, or {@code null} for a plain TIFF
     * @param noData   the GDAL_NODATA value, or {@code null} for none
     * @param parallel compress the strips on all processors (the file is the same byte for byte)
     */
    static void write(Pixels pixels, Path file, GeoReference geo, Double noData, boolean parallel)
            throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.WRITE, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING)) {
            ch.position(8);
            int rowBytes = pixels.rowBytes();
            int rowsPerStrip = Math.max(1, Math.min(pixels.height(), STRIP_TARGET_BYTES / rowBytes));
            int strips = (pixels.height() + rowsPerStrip - 1) / rowsPerStrip;
            long[] offsets = new long[strips];
            long[] counts = new long[strips];
            boolean predictor = pixels.bitsPerSample() == 8;
            writeStrips(ch, pixels, rowsPerStrip, predictor, offsets, counts, parallel);

            Map<Integer, Field> fields = fields(pixels, geo, noData, rowsPerStrip, predictor, offsets, counts);
            long ifdOffset = align(ch.position());
            ByteBuffer ifd = layOutIfd(fields, ifdOffset);
            if (ifdOffset + ifd.capacity() > 0xFFFF_FFFFL) {
                throw new IOException("image too large for a classic TIFF (over 4 GiB compressed); BigTIFF is not "
                        + "supported, write a smaller image or a PNG");
            }
            ch.write(ifd, ifdOffset);
            ByteBuffer header = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN);
            header.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt((int) ifdOffset).flip();
            ch.write(header, 0);
        }
    }

    /** Strips compressed at once, per processor: a bound on the compressed data held before it is written. */
    private static final int STRIPS_PER_BATCH_AND_PROCESSOR = 8;

    private static void writeStrips(FileChannel ch, Pixels pixels, int rowsPerStrip, boolean predictor,
                                    long[] offsets, long[] counts, boolean parallel) throws IOException {
        int batch = parallel ? STRIPS_PER_BATCH_AND_PROCESSOR * Runtime.getRuntime().availableProcessors() : 1;
        for (int s0 = 0; s0 < offsets.length; s0 += batch) {
            int first = s0;
            int end = Math.min(offsets.length, s0 + batch);
            byte[][] compressed = new byte[end - first][];
            IntStream strips = IntStream.range(first, end);
            (parallel ? strips.parallel() : strips).forEach(s ->
                    compressed[s - first] = compressStrip(pixels, s, rowsPerStrip, predictor));
            for (int s = first; s < end; s++) {
                offsets[s] = ch.position();
                ByteBuffer data = ByteBuffer.wrap(compressed[s - first]);
                while (data.hasRemaining()) {
                    ch.write(data);
                }
                counts[s] = compressed[s - first].length;
            }
        }
    }

    /** Strip {@code s}: its rows, with the horizontal predictor when asked, as one zlib (Deflate) stream. */
    private static byte[] compressStrip(Pixels pixels, int s, int rowsPerStrip, boolean predictor) {
        int rowBytes = pixels.rowBytes();
        int spp = pixels.samplesPerPixel();
        int y0 = s * rowsPerStrip;
        int rows = Math.min(rowsPerStrip, pixels.height() - y0);
        byte[] raw = new byte[rowBytes * rows];
        byte[] row = new byte[rowBytes];
        for (int r = 0; r < rows; r++) {
            pixels.row(y0 + r, row);
            int base = r * rowBytes;
            if (predictor) {
                // TIFF 6.0 section 14: each sample minus the same sample of the pixel to its left, mod 256.
                for (int i = 0; i < spp && i < rowBytes; i++) {
                    raw[base + i] = row[i];
                }
                for (int i = spp; i < rowBytes; i++) {
                    raw[base + i] = (byte) (row[i] - row[i - spp]);
                }
            } else {
                System.arraycopy(row, 0, raw, base, rowBytes);
            }
        }
        Deflater deflater = new Deflater(Deflater.DEFAULT_COMPRESSION);
        try {
            deflater.setInput(raw);
            deflater.finish();
            ByteArrayOutputStream out = new ByteArrayOutputStream(raw.length / 4 + 64);
            byte[] buffer = new byte[1 << 16];
            while (!deflater.finished()) {
                out.write(buffer, 0, deflater.deflate(buffer));
            }
            return out.toByteArray();
        } finally {
            deflater.end();
        }
    }

    private static Map<Integer, Field> fields(Pixels pixels, GeoReference geo, Double noData, int rowsPerStrip,
                                              boolean predictor, long[] offsets, long[] counts) {
        Map<Integer, Field> f = new TreeMap<>();
        int spp = pixels.samplesPerPixel();
        boolean rgba = spp == 4;
        f.put(256, Field.longs(pixels.width()));                          // ImageWidth
        f.put(257, Field.longs(pixels.height()));                         // ImageLength
        int[] bits = new int[spp];
        Arrays.fill(bits, pixels.bitsPerSample());
        f.put(258, Field.shorts(bits));                                   // BitsPerSample
        f.put(259, Field.shorts(8));                                      // Compression: Deflate
        f.put(262, Field.shorts(rgba ? 2 : 1));                           // Photometric: RGB or BlackIsZero
        f.put(273, Field.longs(offsets));                                 // StripOffsets
        f.put(277, Field.shorts(spp));                                    // SamplesPerPixel
        f.put(278, Field.longs(rowsPerStrip));                            // RowsPerStrip
        f.put(279, Field.longs(counts));                                  // StripByteCounts
        f.put(284, Field.shorts(1));                                      // PlanarConfiguration: chunky
        f.put(305, Field.ascii("jdem846"));                               // Software
        if (predictor) {
            f.put(317, Field.shorts(2));                                  // Predictor: horizontal differencing
        }
        if (rgba) {
            f.put(338, Field.shorts(2));                                  // ExtraSamples: unassociated alpha
        }
        int[] format = new int[spp];
        Arrays.fill(format, pixels.bitsPerSample() == 32 ? 3 : 1);
        f.put(339, Field.shorts(format));                                 // SampleFormat: IEEE float or uint
        if (geo != null) {
            double sx = geo.pixelWidth(pixels.width());
            double sy = geo.pixelHeight(pixels.height());
            f.put(33550, Field.doubles(sx, sy, 0));                       // ModelPixelScale
            // PixelIsArea: raster point (0, 0) is the outer north-west corner of the first pixel.
            f.put(33922, Field.doubles(0, 0, 0, geo.westX(), geo.northY(), 0)); // ModelTiepoint
            GeoKeyWriter keys = GeoKeyWriter.of(geo.crs());
            int[] dir = new int[keys.directory().length];
            for (int i = 0; i < dir.length; i++) {
                dir[i] = keys.directory()[i];
            }
            f.put(GeoKeys.TAG_GEO_KEY_DIRECTORY, Field.shorts(dir));
            if (keys.doubleParams().length > 0) {
                f.put(GeoKeys.TAG_GEO_DOUBLE_PARAMS, Field.doubles(keys.doubleParams()));
            }
            if (!keys.asciiParams().isEmpty()) {
                f.put(GeoKeys.TAG_GEO_ASCII_PARAMS, Field.ascii(keys.asciiParams()));
            }
        }
        if (noData != null) {
            f.put(TAG_GDAL_NODATA, Field.ascii(noDataText(noData)));
        }
        return f;
    }

    /** The IFD (entries ascending by tag) followed by the values that do not fit in an entry's 4 bytes. */
    private static ByteBuffer layOutIfd(Map<Integer, Field> fields, long ifdOffset) {
        int entriesBytes = 2 + 12 * fields.size() + 4;
        int extraBytes = 0;
        for (Field field : fields.values()) {
            if (field.bytes().length > 4) {
                extraBytes += align(field.bytes().length);
            }
        }
        ByteBuffer buf = ByteBuffer.allocate(entriesBytes + extraBytes).order(ByteOrder.LITTLE_ENDIAN);
        long valueOffset = ifdOffset + entriesBytes;
        List<byte[]> extras = new ArrayList<>();
        buf.putShort((short) fields.size());
        for (Map.Entry<Integer, Field> e : fields.entrySet()) {
            Field field = e.getValue();
            buf.putShort((short) (int) e.getKey()).putShort(field.type()).putInt(field.count());
            if (field.bytes().length <= 4) {
                byte[] inline = new byte[4];
                System.arraycopy(field.bytes(), 0, inline, 0, field.bytes().length);
                buf.put(inline);
            } else {
                buf.putInt((int) valueOffset);
                valueOffset += align(field.bytes().length);
                extras.add(field.bytes());
            }
        }
        buf.putInt(0); // no next IFD
        for (byte[] extra : extras) {
            buf.put(extra);
            if (extra.length % 2 != 0) {
                buf.put((byte) 0);
            }
        }
        return buf.flip();
    }

    private static long align(long offset) {
        return offset + (offset & 1);
    }

    private static int align(int length) {
        return length + (length & 1);
    }

    /** GDAL_NODATA text: an integer without decimals, NaN as "nan", else the shortest float32 decimal. */
    static String noDataText(double value) {
        if (Double.isNaN(value)) {
            return "nan";
        }
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Float.toString((float) value);
    }

    /** One IFD entry's type, count and little-endian value bytes. */
    private record Field(short type, int count, byte[] bytes) {

        static Field shorts(int... values) {
            ByteBuffer b = ByteBuffer.allocate(2 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (int v : values) {
                b.putShort((short) v);
            }
            return new Field(SHORT, values.length, b.array());
        }

        static Field longs(long... values) {
            ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (long v : values) {
                b.putInt((int) v);
            }
            return new Field(LONG, values.length, b.array());
        }

        static Field doubles(double... values) {
            ByteBuffer b = ByteBuffer.allocate(8 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (double v : values) {
                b.putDouble(v);
            }
            return new Field(DOUBLE, values.length, b.array());
        }

        static Field ascii(String text) {
            byte[] s = (text + '\0').getBytes(StandardCharsets.US_ASCII);
            return new Field(ASCII, s.length, s);
        }
    }
}
