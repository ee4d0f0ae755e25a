package io.github.jdem846.output;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.stream.IntStream;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * Encodes 8-bit RGBA ({@code TYPE_INT_ARGB}; any other type through {@code getRGB}) and 8-bit gray
 * ({@code TYPE_BYTE_GRAY}) images as PNG: per-row PNG filters chosen as PngEncoder's "predictor encoding" chooses
 * them (the filter with the smallest sum of absolute values), and one zlib stream made of independently compressed
 * segments of whole rows, about {@link #SEGMENT_BYTES} each, compressed in parallel when asked. The segments, and so
 * the file's bytes, depend only on the image and the compression level: the file is the same on one thread or
 * many, on any machine with the same zlib. Measured against PngEncoder and ImageIO in docs/performance.md ("PNG
 * encoding").
 *
 * <p>A segment ends with a sync flush (the empty stored block that byte-aligns the stream) and the next starts
 * from a fresh deflate state, so segments concatenate into one valid stream (as pigz and PngEncoder do); the
 * stream's Adler-32 is combined from the segments'. IDAT chunks carry {@link #IDAT_BYTES} each. No colour profile
 * is written: the samples are display values, as gdaldem writes them (the JDK's {@code TYPE_BYTE_GRAY} colour space
 * is linear gray, and tagging a hillshade with it made colour-managed viewers show it much lighter).
 */
final class PngWriter {

    /** Target filtered bytes per deflate segment (whole rows, at least one). */
    static final int SEGMENT_BYTES = 1 << 20;
    /** Payload of every IDAT chunk but the last. */
    static final int IDAT_BYTES = 1 << 18;
    /**
     * Segments compressed at once per processor, and at most: a bound on the compressed data held before it is
     * written (the batches change no byte of the file).
     */
    private static final int SEGMENTS_PER_BATCH_AND_PROCESSOR = 4;
    private static final int MAX_SEGMENTS_PER_BATCH = 64;
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    private PngWriter() {
    }

    /**
     * Writes {@code image} to {@code file} (created or truncated).
     *
     * @param compressionLevel deflate level 0..9
     * @param parallel         compress the segments on all processors (common ForkJoinPool); same bytes
     */
    static void write(BufferedImage image, Path file, int compressionLevel, boolean parallel) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16)) {
            write(image, out, compressionLevel, parallel);
        }
    }

    static void write(BufferedImage image, OutputStream stream, int compressionLevel, boolean parallel)
            throws IOException {
        if (compressionLevel < 0 || compressionLevel > 9) {
            throw new IllegalArgumentException("PNG compression level must be 0..9, got " + compressionLevel);
        }
        Scanlines lines = Scanlines.of(image);
        DataOutputStream out = new DataOutputStream(stream);
        out.write(SIGNATURE);
        ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
        DataOutputStream h = new DataOutputStream(ihdr);
        h.writeInt(lines.width);
        h.writeInt(lines.height);
        h.writeByte(8);                                   // bit depth
        h.writeByte(lines.bytesPerPixel == 4 ? 6 : 0);    // colour type: RGBA or gray
        h.writeByte(0);                                   // deflate
        h.writeByte(0);                                   // adaptive filtering
        h.writeByte(0);                                   // not interlaced
        chunk(out, "IHDR", ihdr.toByteArray(), ihdr.size());
        writeImageData(out, lines, compressionLevel, parallel);
        chunk(out, "IEND", new byte[0], 0);
        out.flush();
    }

    /** The zlib stream of the filtered rows, segment by segment, in IDAT chunks. */
    private static void writeImageData(DataOutputStream out, Scanlines lines, int level, boolean parallel)
            throws IOException {
        int rowsPerSegment = Math.max(1, SEGMENT_BYTES / lines.rowBytes);
        int segments = (lines.height + rowsPerSegment - 1) / rowsPerSegment;
        IdatChunks idat = new IdatChunks(out);
        idat.write(new byte[] {0x78, zlibFlags(level)}, 2);
        long adler = 1;
        int batch = parallel ? Math.min(MAX_SEGMENTS_PER_BATCH,
                SEGMENTS_PER_BATCH_AND_PROCESSOR * Runtime.getRuntime().availableProcessors()) : 1;
        for (int s0 = 0; s0 < segments; s0 += batch) {
            int first = s0;
            int end = Math.min(segments, s0 + batch);
            Segment[] done = new Segment[end - first];
            IntStream range = IntStream.range(first, end);
            (parallel ? range.parallel() : range).forEach(s -> done[s - first] = compress(lines, s * rowsPerSegment,
                    Math.min(lines.height, (s + 1) * rowsPerSegment), level, s == segments - 1));
            for (Segment s : done) {
                idat.write(s.deflated, s.length);
                adler = combineAdler32(adler, s.adler32, s.inputLength);
            }
        }
        idat.write(new byte[] {(byte) (adler >>> 24), (byte) (adler >>> 16), (byte) (adler >>> 8), (byte) adler}, 4);
        idat.flush();
    }

    /** One segment's raw deflate data and the Adler-32 and length of its filtered rows. */
    private record Segment(byte[] deflated, int length, long adler32, int inputLength) {
    }

    /** Rows [y0, y1) filtered and deflated on their own: a sync flush at the end, or the final block if last. */
    private static Segment compress(Scanlines lines, int y0, int y1, int level, boolean last) {
        int n = (y1 - y0) * lines.rowBytes;
        byte[] filtered = new byte[n];
        new RowFilter(lines).filter(y0, y1, filtered);
        Adler32 adler = new Adler32();
        adler.update(filtered, 0, n);
        Deflater deflater = new Deflater(level, true);
        try {
            deflater.setInput(filtered, 0, n);
            if (last) {
                deflater.finish();
            }
            byte[] out = new byte[n + (n >> 3) + 64];
            int length = 0;
            while (true) {
                int room = out.length - length;
                int k = deflater.deflate(out, length, room, last ? Deflater.NO_FLUSH : Deflater.SYNC_FLUSH);
                length += k;
                if (last ? deflater.finished() : k < room) {
                    break;
                }
                if (length == out.length) {
                    out = Arrays.copyOf(out, out.length * 2);
                }
            }
            return new Segment(Arrays.copyOf(out, length), length, adler.getValue(), n);
        } finally {
            deflater.end();
        }
    }

    /** The zlib FLG byte after CMF 0x78 (deflate, 32 KiB window): FLEVEL of {@code level} and the FCHECK bits. */
    static byte zlibFlags(int level) {
        int flevel = level <= 1 ? 0 : level <= 5 ? 1 : level == 6 ? 2 : 3;
        int flg = flevel << 6;
        flg += (31 - (0x78 * 256 + flg) % 31) % 31;
        return (byte) flg;
    }

    /**
     * The Adler-32 of the concatenation of a block with checksum {@code a1} and one of {@code len2} bytes with
     * checksum {@code a2} (zlib's adler32_combine: s1 adds up, s2 adds s2 of both plus len2 times the first s1 − 1).
     */
    static long combineAdler32(long a1, long a2, long len2) {
        final long base = 65521;
        long rem = len2 % base;
        long s1 = ((a1 & 0xFFFF) + (a2 & 0xFFFF) + base - 1) % base;
        long s2 = (rem * (a1 & 0xFFFF) % base + (a1 >>> 16 & 0xFFFF) + (a2 >>> 16 & 0xFFFF) + base - rem) % base;
        return s1 | s2 << 16;
    }

    private static void chunk(DataOutputStream out, String type, byte[] data, int length) throws IOException {
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data, 0, length);
        out.writeInt(length);
        out.write(t);
        out.write(data, 0, length);
        out.writeInt((int) crc.getValue());
    }

    /** Cuts the zlib stream into IDAT chunks of {@link #IDAT_BYTES}. */
    private static final class IdatChunks {
        private final DataOutputStream out;
        private final byte[] buffer = new byte[IDAT_BYTES];
        private int count;

        IdatChunks(DataOutputStream out) {
            this.out = out;
        }

        void write(byte[] data, int length) throws IOException {
            for (int off = 0; off < length; ) {
                int n = Math.min(length - off, buffer.length - count);
                System.arraycopy(data, off, buffer, count, n);
                count += n;
                off += n;
                if (count == buffer.length) {
                    flush();
                }
            }
        }

        void flush() throws IOException {
            if (count > 0) {
                chunk(out, "IDAT", buffer, count);
                count = 0;
            }
        }
    }

    /** The image's rows as PNG samples: R, G, B, A or gray, 8 bits each. */
    private static final class Scanlines {
        final BufferedImage image;
        final int width;
        final int height;
        final int bytesPerPixel;
        /** Bytes of one filtered row: the filter type and the samples. */
        final int rowBytes;

        private Scanlines(BufferedImage image, int bytesPerPixel) {
            this.image = image;
            this.width = image.getWidth();
            this.height = image.getHeight();
            this.bytesPerPixel = bytesPerPixel;
            this.rowBytes = 1 + bytesPerPixel * width;
        }

        static Scanlines of(BufferedImage image) {
            return new Scanlines(image, image.getType() == BufferedImage.TYPE_BYTE_GRAY ? 1 : 4);
        }

        /** True when the image is written as RGBA through {@code getRGB} (sRGB): any type but ARGB and gray. */
        static boolean isRgbaFallback(BufferedImage image) {
            int t = image.getType();
            return t != BufferedImage.TYPE_INT_ARGB && t != BufferedImage.TYPE_BYTE_GRAY;
        }

        /** Scratch for {@link #row}: a row of ints (RGBA) or bytes (gray). */
        Object scratch() {
            return bytesPerPixel == 1 ? new byte[width] : new int[width];
        }

        /** Row {@code y}'s samples into {@code dst[1 …]}, through {@code scratch} (from {@link #scratch()}). */
        void row(int y, byte[] dst, Object scratch) {
            Raster raster = image.getRaster();
            if (bytesPerPixel == 1) {
                raster.getDataElements(0, y, width, 1, scratch);
                System.arraycopy((byte[]) scratch, 0, dst, 1, width);
                return;
            }
            int[] pixels = (int[]) scratch;
            if (image.getType() == BufferedImage.TYPE_INT_ARGB) {
                raster.getDataElements(0, y, width, 1, pixels);
            } else {
                image.getRGB(0, y, width, 1, pixels, 0, width);
            }
            for (int x = 0, j = 1; x < width; x++) {
                int p = pixels[x];
                dst[j++] = (byte) (p >>> 16);
                dst[j++] = (byte) (p >>> 8);
                dst[j++] = (byte) p;
                dst[j++] = (byte) (p >>> 24);
            }
        }
    }

    /**
     * PNG filtering of rows (PNG spec 9): each row takes the filter (none, sub, up, average, Paeth) whose output has
     * the smallest sum of absolute values, the first on ties; none sums the unsigned samples, the others their
     * signed bytes (PngEncoder's rule, so that its files and ours compress alike).
     */
    private static final class RowFilter {
        private final Scanlines lines;
        private final int bpp;
        private byte[] prev;
        private byte[] cur;
        private final byte[] sub;
        private final byte[] up;
        private final byte[] avg;
        private final byte[] paeth;
        private final Object scratch;

        RowFilter(Scanlines lines) {
            this.lines = lines;
            int n = lines.rowBytes;
            bpp = lines.bytesPerPixel;
            prev = new byte[n];
            cur = new byte[n];
            sub = new byte[n];
            up = new byte[n];
            avg = new byte[n];
            paeth = new byte[n];
            sub[0] = 1;
            up[0] = 2;
            avg[0] = 3;
            paeth[0] = 4;
            scratch = lines.scratch();
        }

        /** Filters rows [y0, y1) into {@code out}, one after another; row y0 − 1 (zeros above row 0) is read again. */
        void filter(int y0, int y1, byte[] out) {
            if (y0 > 0) {
                lines.row(y0 - 1, prev, scratch);
            }
            int n = lines.rowBytes;
            for (int y = y0; y < y1; y++) {
                lines.row(y, cur, scratch);
                System.arraycopy(choose(), 0, out, (y - y0) * n, n);
                byte[] t = prev;
                prev = cur;
                cur = t;
            }
        }

        private byte[] choose() {
            byte[] c = cur;
            byte[] p = prev;
            long sumNone = 0;
            long sumSub = 1;
            long sumUp = 2;
            long sumAvg = 3;
            long sumPaeth = 4;
            int n = c.length;
            for (int i = 1; i < n; i++) {
                int x = c[i] & 0xFF;
                int b = p[i] & 0xFF;
                int a = 0;
                int d = 0;
                if (i > bpp) {
                    a = c[i - bpp] & 0xFF;
                    d = p[i - bpp] & 0xFF;
                }
                byte s = (byte) (x - a);
                byte u = (byte) (x - b);
                byte v = (byte) (x - ((a + b) >> 1));
                int q = a + b - d;
                int pa = Math.abs(q - a);
                int pb = Math.abs(q - b);
                int pc = Math.abs(q - d);
                byte t = (byte) (x - (pa <= pb && pa <= pc ? a : pb <= pc ? b : d));
                sub[i] = s;
                up[i] = u;
                avg[i] = v;
                paeth[i] = t;
                sumNone += x;
                sumSub += Math.abs(s);
                sumUp += Math.abs(u);
                sumAvg += Math.abs(v);
                sumPaeth += Math.abs(t);
            }
            byte[] best = c;
            long min = sumNone;
            if (min > sumSub) {
                best = sub;
                min = sumSub;
            }
            if (min > sumUp) {
                best = up;
                min = sumUp;
            }
            if (min > sumAvg) {
                best = avg;
                min = sumAvg;
            }
            if (min > sumPaeth) {
                best = paeth;
            }
            return best;
        }
    }
}
