package io.github.jdem846.output;

import io.github.jdem846.internal.SpareArrays;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.LongConsumer;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * Encodes 8-bit RGBA and 8-bit gray images as PNG, band of rows after band of rows ({@link BandEncoder}): per-row
 * PNG filters chosen as PngEncoder's "predictor encoding" chooses them (the filter with the smallest sum of absolute
 * values; {@link PngRowFilter}), and one zlib stream made of independently compressed segments of whole rows, about
 * {@link #SEGMENT_BYTES} each, the segments of a band compressed in parallel when asked. The segments, and so the
 * file's bytes, depend only on the image and the compression level: the file is the same on one thread or many,
 * for the whole picture given at once or in bands of any size ({@link RowChunks}), on any machine with the same
 * zlib. Memory: the band, at most one segment of rows copied from a band that ends inside it, and one batch of
 * compressed segments. Measured against PngEncoder and ImageIO in docs/performance.md ("Writing PNG and GeoTIFF").
 *
 * <p>The filter rule is computed exactly, eight bytes at a time in a {@code long} ({@link PngRowFilter}): the
 * byte-wise loop it replaced, with a branching Paeth predictor, was the hottest Java method of {@code hillshade} on
 * the rough 4000² DEM of docs/performance.md and took about 3 times as long (Java 17 and 25), for the same choices
 * and bytes. Measured and left aside: a branch-free Paeth in the byte-wise loop (1.3 to 1.5 times faster only), and
 * scoring the filters on a quarter of each row, then writing only the chosen one (no faster on shading, whose
 * winner, Paeth, must then be computed over the whole row anyway; and it chose another filter for 298 of 643 rows of
 * Big Tujunga's shadow mask, so it changed files). The filter and the coding now take about the same time of a gray
 * segment, and in a one-shot command the filter runs uncompiled for its first rows: there the write phase gained
 * about 10 %.
 *
 * <p>Gray segments (hillshades, shadows) are coded with Huffman codes only, zlib's {@link Deflater#HUFFMAN_ONLY}
 * strategy, by {@link HuffmanBlocks} (about 3 times as fast as zlib in that mode, and as small): continuous-tone
 * rows hold few repeated strings after filtering, so string matching costs about 2.5 times the time for a larger
 * result (a rough 4000² hillshade: 12.8 MB Huffman-only, 13.2 MB with matching at level 1); see
 * {@link #HUFFMAN_ONLY_RATIO} for the exception. RGBA segments are deflated by zlib with string matching (repeated
 * colours and alpha). Both at the level asked for; level 0 stores the rows.
 *
 * <p>A segment ends with a sync flush (the empty stored block that byte-aligns the stream) and the next starts
 * from a fresh deflate state, so segments concatenate into one valid stream (as pigz and PngEncoder do); the
 * stream's Adler-32 is combined from the segments'. IDAT chunks carry {@link #IDAT_BYTES} each. No colour profile
 * is written: the samples are display values, as gdaldem writes them (the JDK's {@code TYPE_BYTE_GRAY} colour space
 * is linear gray, and tagging a hillshade with it made colour-managed viewers show it much lighter).
 */
final class PngWriter implements BandEncoder {

    /** Target filtered bytes per deflate segment (whole rows, at least one). */
    static final int SEGMENT_BYTES = 1 << 20;
    /**
     * A gray segment is deflated Huffman-only unless the entropy of its filtered bytes ({@link #entropyBits}) is
     * below 1/this of their bits, i.e. Huffman coding alone would compress it below 1/this: few distinct values,
     * mostly long runs (shadow masks, flat or no-data areas), which string matching compresses far better and
     * fast.
     */
    static final int HUFFMAN_ONLY_RATIO = 4;
    /** Payload of every IDAT chunk but the last. */
    static final int IDAT_BYTES = 1 << 18;
    /**
     * Segments compressed at once per processor, and at most: a bound on the compressed data held before it is
     * written (the batches change no byte of the file).
     */
    private static final int SEGMENTS_PER_BATCH_AND_PROCESSOR = 4;
    private static final int MAX_SEGMENTS_PER_BATCH = 64;
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    private final DataOutputStream out;
    private final IdatChunks idat;
    private final RowChunks segments;
    private final int segmentCount;
    private final int bytesPerPixel;
    private final int level;
    private final boolean parallel;
    private final int batch;
    /** Filtered rows and deflated bytes of segments done, and deflaters, for the next segments. */
    private final SpareArrays<byte[]> spareFiltered = SpareArrays.bytes();
    private final SpareArrays<byte[]> spareDeflated = SpareArrays.bytes();
    private final SpareDeflaters spareDeflaters;
    private final ConcurrentLinkedQueue<HuffmanBlocks> spareCoders = new ConcurrentLinkedQueue<>();
    private long adler = 1;
    private boolean finished;
    private LongConsumer encoded = rows -> { };

    /**
     * Starts a PNG on {@code stream}: writes the signature and the header at once, the rows as they are appended.
     *
     * @param bytesPerPixel    4 for RGBA (colour type 6), 1 for gray (colour type 0), 8 bits per sample
     * @param compressionLevel deflate level 0..9
     * @param parallel         compress the segments of a band on all processors; same bytes
     * @throws IllegalArgumentException for a size PNG cannot hold or a row longer than one Java array
     */
    PngWriter(OutputStream stream, int width, int height, int bytesPerPixel, int compressionLevel, boolean parallel)
            throws IOException {
        if (compressionLevel < 0 || compressionLevel > 9) {
            throw new IllegalArgumentException("PNG compression level must be 0..9, got " + compressionLevel);
        }
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1×1, got " + width + "×" + height);
        }
        int rowBytes = 1 + Pixels.rowBytes(width, bytesPerPixel, 8);
        this.bytesPerPixel = bytesPerPixel;
        this.level = compressionLevel;
        this.spareDeflaters = new SpareDeflaters(compressionLevel, true);
        this.parallel = parallel;
        this.batch = Batches.size(parallel, SEGMENTS_PER_BATCH_AND_PROCESSOR, MAX_SEGMENTS_PER_BATCH);
        int rowsPerSegment = Math.max(1, SEGMENT_BYTES / rowBytes);
        this.segmentCount = RowChunks.count(height, rowsPerSegment);
        this.segments = new RowChunks(width, height, bytesPerPixel, 8, rowsPerSegment, true, this::compress);
        this.out = new DataOutputStream(stream);
        out.write(SIGNATURE);
        ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
        DataOutputStream h = new DataOutputStream(ihdr);
        h.writeInt(width);
        h.writeInt(height);
        h.writeByte(8);                                   // bit depth
        h.writeByte(bytesPerPixel == 4 ? 6 : 0);          // colour type: RGBA or gray
        h.writeByte(0);                                   // deflate
        h.writeByte(0);                                   // adaptive filtering
        h.writeByte(0);                                   // not interlaced
        chunk(out, "IHDR", ihdr.toByteArray(), ihdr.size());
        this.idat = new IdatChunks(out);
        idat.write(new byte[] {0x78, zlibFlags(compressionLevel)}, 2);
    }

    /** A PNG written to {@code file} (created or truncated); {@link #close()} closes the file. */
    static PngWriter toFile(Path file, int width, int height, int bytesPerPixel, int compressionLevel,
                            boolean parallel) throws IOException {
        OutputStream stream = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16);
        try {
            return new PngWriter(stream, width, height, bytesPerPixel, compressionLevel, parallel);
        } catch (IOException | RuntimeException e) {
            stream.close();
            throw e;
        }
    }

    /**
     * Writes {@code image} to {@code file} (created or truncated): {@code TYPE_BYTE_GRAY} as gray, any other type
     * as RGBA.
     *
     * @param compressionLevel deflate level 0..9
     * @param parallel         compress the segments on all processors (common ForkJoinPool); same bytes
     */
    static void write(BufferedImage image, Path file, int compressionLevel, boolean parallel) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16)) {
            write(image, out, compressionLevel, parallel);
        }
    }

    /** Writes {@code image} to {@code stream}, which stays open. */
    static void write(BufferedImage image, OutputStream stream, int compressionLevel, boolean parallel)
            throws IOException {
        Pixels pixels = new Pixels.Image(image);
        PngWriter png = new PngWriter(stream, pixels.width(), pixels.height(), pixels.samplesPerPixel(),
                compressionLevel, parallel);
        png.append(pixels);
        png.finish();
    }

    @Override
    public void append(Pixels band) throws IOException {
        if (finished) {
            throw new IllegalStateException("the PNG is finished");
        }
        segments.append(band);
    }

    /** Writes the Adler-32 of the rows and the last chunks. */
    @Override
    public void finish() throws IOException {
        if (segments.rowsIn() != segments.height()) {
            throw new IllegalStateException("only " + segments.rowsIn() + " of " + segments.height()
                    + " rows were appended");
        }
        if (!finished) {
            finished = true;
            idat.write(new byte[] {(byte) (adler >>> 24), (byte) (adler >>> 16), (byte) (adler >>> 8),
                (byte) adler}, 4);
            idat.flush();
            chunk(out, "IEND", new byte[0], 0);
            out.flush();
            spareDeflaters.end();
        }
    }

    @Override
    public void close() throws IOException {
        spareDeflaters.end();
        out.close();
    }

    /** The segments a band completed: filtered and deflated, a batch at a time, and written in order. */
    private void compress(List<RowChunks.Chunk> ready) throws IOException {
        Batches.run(ready.size(), batch, parallel, i -> compress(ready.get(i)), s -> {
            idat.write(s.deflated, s.length);
            spareDeflated.give(s.deflated);
            adler = combineAdler32(adler, s.adler32, s.inputLength);
            encoded.accept(s.rows);
        });
    }

    @Override
    public long rowsToEncode() {
        return segments.height();
    }

    @Override
    public void onEncoded(LongConsumer rows) {
        encoded = java.util.Objects.requireNonNull(rows, "rows");
    }

    /** One segment's raw deflate data (the first {@code length} bytes) and the Adler-32 and length of its rows. */
    private record Segment(byte[] deflated, int length, long adler32, int inputLength, int rows) {
    }

    /** A segment's rows filtered and deflated on their own: a sync flush at the end, or the final block if last. */
    private Segment compress(RowChunks.Chunk segment) {
        boolean last = segment.index() == segmentCount - 1;
        int rowBytes = 1 + segments.rowBytes();
        int n = segment.rows() * rowBytes;
        byte[] filtered = spareFiltered.take(n);
        new PngRowFilter(segments.rowBytes(), bytesPerPixel).filter(segment, filtered);
        Adler32 adler = new Adler32();
        adler.update(filtered, 0, n);
        Deflated d;
        if (level == 0 || bytesPerPixel != 1) {
            d = deflate(filtered, n, last);
        } else {
            // the counts for the entropy are the Huffman coder's, made in the same pass
            HuffmanBlocks coder = spareCoders.poll();
            coder = coder != null ? coder : new HuffmanBlocks();
            if (entropyBits(coder.count(filtered, 0, n), n) * HUFFMAN_ONLY_RATIO < 8.0 * n) {
                d = deflate(filtered, n, last);
            } else {
                byte[] deflated = spareDeflated.take(HuffmanBlocks.bound(n));
                d = new Deflated(deflated, coder.deflate(filtered, 0, n, last, deflated));
            }
            spareCoders.offer(coder);
        }
        spareFiltered.give(filtered);
        return new Segment(d.bytes, d.length, adler.getValue(), n, segment.rows());
    }

    /**
     * The order-0 entropy of the first {@code n} bytes of {@code data}, in bits: about the size of their Huffman
     * coding. {@link StrictMath} so that the choice it makes, and so the file, is the same on every JVM.
     */
    static double entropyBits(byte[] data, int n) {
        int[] counts = new int[256];
        for (int i = 0; i < n; i++) {
            counts[data[i] & 0xFF]++;
        }
        return entropyBits(counts, n);
    }

    /** {@link #entropyBits(byte[], int)} of {@code n} bytes whose values {@code counts} counts. */
    static double entropyBits(int[] counts, int n) {
        double bits = 0;
        for (int c : counts) {
            if (c > 0) {
                bits += c * StrictMath.log((double) n / c);
            }
        }
        return bits / StrictMath.log(2);
    }

    /** Raw deflate data in the first {@code length} bytes of {@code bytes}. */
    private record Deflated(byte[] bytes, int length) {
    }

    /**
     * {@code n} filtered bytes deflated by zlib at this writer's level, with string matching: ending in a sync
     * flush, or the final block when {@code last}.
     */
    private Deflated deflate(byte[] filtered, int n, boolean last) {
        Deflater deflater = spareDeflaters.take();
        try {
            deflater.setInput(filtered, 0, n);
            if (last) {
                deflater.finish();
            }
            byte[] deflated = spareDeflated.take((int) Math.min(Integer.MAX_VALUE - 16, n + (n >> 3) + 64L));
            int length = 0;
            while (true) {
                int room = deflated.length - length;
                int k = deflater.deflate(deflated, length, room, last ? Deflater.NO_FLUSH : Deflater.SYNC_FLUSH);
                length += k;
                if (last ? deflater.finished() : k < room && deflater.needsInput()) {
                    break;
                }
                if (length == deflated.length) {
                    deflated = Arrays.copyOf(deflated, deflated.length * 2);
                }
            }
            return new Deflated(deflated, length);
        } finally {
            spareDeflaters.give(deflater);
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
}
