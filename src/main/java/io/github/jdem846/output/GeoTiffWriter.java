package io.github.jdem846.output;

import io.github.jdem846.internal.SpareArrays;
import io.github.jdem846.output.TiffDirectory.Field;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.function.LongConsumer;

/**
 * A small baseline TIFF 6.0 writer for the one case the renderer needs, band of rows after band of rows
 * ({@link BandEncoder}): a single image, little-endian, strips of about 64 KiB, Deflate compression, chunky samples
 * and the GeoTIFF tags of {@link GeoTiffTags}. Sample layouts: 8-bit gray (BlackIsZero), 8-bit RGBA (RGB with
 * unassociated alpha) and float32 gray. 8-bit data use the horizontal differencing predictor (2), which makes relief
 * images markedly smaller; float32 is stored without predictor.
 *
 * <p>Why hand-written: TwelveMonkeys' TIFF writer (3.15.0) passes GeoTIFF tags through but cannot write float32
 * ("Not implemented for data type: 4"), and the JDK's own TIFF writer (17.0.15) truncates Deflate strips that do
 * not compress (noisy content), which GDAL and TwelveMonkeys then fail to decode. See docs/output.md.
 *
 * <p>File layout: header, strips in order (written as the bands complete them, those of one band compressed in
 * parallel when asked), then the IFD and its out-of-line values (word-aligned), then the header is rewritten to
 * point at the IFD. The file is the same for the whole picture given at once or in bands of any size.
 *
 * <p><b>BigTIFF.</b> Classic TIFF addresses at most 4 GiB. Whether the file is a classic TIFF or a BigTIFF (version
 * 43, 8-byte offsets, LONG8 StripOffsets and StripByteCounts) is decided before the first strip is written, from a
 * worst-case bound of the file size: every strip's raw bytes grown by zlib's worst case (incompressible data in
 * stored blocks) plus the header and IFD. Deciding later would move every strip, since the first strip follows an
 * 8-byte classic header but a 16-byte BigTIFF one. The bound makes the choice depend only on the image size and
 * sample layout, never on the content, so a picture always gets the same format, streamed or not; the price is
 * that a picture whose raw samples pass about 4 GiB is a BigTIFF even when it would compress below 4 GiB (a cautious
 * choice like GDAL's {@code BIGTIFF=IF_SAFER}).
 */
final class GeoTiffWriter implements BandEncoder {

    private static final int STRIP_TARGET_BYTES = 1 << 16;
    /** Strips compressed at once, per processor: a bound on the compressed data held before it is written. */
    private static final int STRIPS_PER_BATCH_AND_PROCESSOR = 8;

    private final FileChannel channel;
    private final TiffDirectory directory;
    private final RowChunks strips;
    private final int samplesPerPixel;
    private final boolean predictor;
    private final boolean parallel;
    private final boolean big;
    private final long[] offsets;
    private final long[] counts;
    private final TiffBlocks blocks = new TiffBlocks();
    private final SpareArrays<byte[]> spareRows = SpareArrays.bytes();
    private long position;
    private boolean finished;
    private LongConsumer encoded = rows -> { };

    /**
     * Starts a GeoTIFF in {@code file} (created or truncated).
     *
     * @param geo          the georeferencing, or {@code null} for a plain TIFF
     * @param noData       the GDAL_NODATA value, or {@code null} for none
     * @param parallel     compress the strips of a band on all processors (the file is the same byte for byte)
     * @param classicLimit the largest file size, by the worst-case bound, written as a classic TIFF
     *                     ({@link TiffDirectory#CLASSIC_LIMIT}; smaller in tests)
     */
    GeoTiffWriter(Path file, int width, int height, int samplesPerPixel, int bitsPerSample, GeoReference geo,
                  Double noData, boolean parallel, long classicLimit) throws IOException {
        int rowBytes = Pixels.rowBytes(width, samplesPerPixel, bitsPerSample);
        int rowsPerStrip = Math.max(1, Math.min(height, STRIP_TARGET_BYTES / Math.max(1, rowBytes)));
        int count = RowChunks.count(height, rowsPerStrip);
        this.samplesPerPixel = samplesPerPixel;
        this.predictor = GeoTiffTags.predictor(bitsPerSample);
        this.parallel = parallel;
        this.offsets = new long[count];
        this.counts = new long[count];
        this.strips = new RowChunks(width, height, samplesPerPixel, bitsPerSample, rowsPerStrip, false,
                this::writeStrips);
        this.directory = GeoTiffTags.samples(width, height, samplesPerPixel, bitsPerSample, noData);
        GeoTiffTags.describe(directory, geo, width, height);
        directory.put(278, Field.longs(rowsPerStrip));                    // RowsPerStrip
        placeStrips(true);
        long bound = TiffDirectory.BIG_HEADER_BYTES + 1 + directory.size(true)
                + (count - 1) * TiffBlocks.deflateBound((long) rowsPerStrip * rowBytes)
                + TiffBlocks.deflateBound((long) (height - (count - 1) * rowsPerStrip) * rowBytes);
        this.big = bound > classicLimit;
        this.position = big ? TiffDirectory.BIG_HEADER_BYTES : TiffDirectory.CLASSIC_HEADER_BYTES;
        this.channel = FileChannel.open(file, StandardOpenOption.WRITE, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING);
    }

    @Override
    public void append(Pixels band) throws IOException {
        if (finished) {
            throw new IllegalStateException("the GeoTIFF is finished");
        }
        strips.append(band);
    }

    /** Writes the IFD after the strips and the header that points at it. */
    @Override
    public void finish() throws IOException {
        if (strips.rowsIn() != strips.height()) {
            throw new IllegalStateException("only " + strips.rowsIn() + " of " + strips.height()
                    + " rows were appended");
        }
        if (finished) {
            return;
        }
        placeStrips(big);
        long ifdOffset = TiffDirectory.align(position);
        ByteBuffer ifd = directory.layOut(ifdOffset, 0, big);
        if (!big && ifdOffset + ifd.remaining() > TiffDirectory.CLASSIC_LIMIT) {
            throw new IOException("the GeoTIFF passed the 4 GiB a classic TIFF can address");
        }
        FileChannels.writeFully(channel, ifd, ifdOffset);
        FileChannels.writeFully(channel, TiffDirectory.header(big, ifdOffset), 0);
        finished = true;
    }

    @Override
    public void close() throws IOException {
        blocks.end();
        channel.close();
    }

    private void placeStrips(boolean asBig) {
        directory.put(273, Field.offsets(offsets, asBig));                // StripOffsets
        directory.put(279, Field.offsets(counts, asBig));                 // StripByteCounts
    }

    /** The strips a band completed, compressed a batch at a time and written in order. */
    private void writeStrips(List<RowChunks.Chunk> ready) throws IOException {
        int batch = Batches.size(parallel, STRIPS_PER_BATCH_AND_PROCESSOR, Integer.MAX_VALUE);
        int[] next = {0};
        Batches.run(ready.size(), batch, parallel, i -> compress(ready.get(i)), data -> {
            int s = ready.get(next[0]++).index();
            offsets[s] = position;
            counts[s] = data.length;
            FileChannels.writeFully(channel, ByteBuffer.wrap(data), position);
            position += data.length;
            encoded.accept(ready.get(next[0] - 1).rows());
        });
    }

    @Override
    public long rowsToEncode() {
        return strips.height();
    }

    @Override
    public void onEncoded(LongConsumer rows) {
        encoded = java.util.Objects.requireNonNull(rows, "rows");
    }

    /** A strip's rows, with the predictor for 8-bit samples, as one zlib stream. */
    private byte[] compress(RowChunks.Chunk strip) {
        int rowBytes = strips.rowBytes();
        byte[] raw = spareRows.take(strip.rows() * rowBytes);
        for (int r = 0; r < strip.rows(); r++) {
            strip.row(r, raw, r * rowBytes);
        }
        byte[] data = blocks.deflate(raw, strip.rows(), rowBytes, samplesPerPixel, predictor);
        spareRows.give(raw);
        return data;
    }
}
