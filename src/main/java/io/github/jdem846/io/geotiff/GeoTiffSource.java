package io.github.jdem846.io.geotiff;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.internal.GeoKeys;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.MemoryGuard;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.io.source.SampleDecoder;
import io.github.jdem846.io.source.ValueScale;
import io.github.jdem846.raster.GridGeometry;
import java.awt.Rectangle;
import java.awt.image.DataBuffer;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageReadParam;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;

/**
 * GeoTIFF: pixels decoded by TwelveMonkeys imageio-tiff (its reader SPI is instantiated directly, not looked up in
 * the global ImageIO registry), georeferencing from ModelPixelScale + ModelTiepoint or ModelTransformation, CRS from
 * the GeoKeys ({@link GeoTiffCrs}), no-data from GDAL_NODATA. Rotated or sheared grids are refused.
 *
 * <p>Windows: TwelveMonkeys 3.15.0 decodes every strip and tile above the last row of a source region (and fails on
 * regions narrower than a tiled image, haraldk/TwelveMonkeys#746). So for the usual compressions (none, LZW,
 * Deflate, PackBits) each read hands TwelveMonkeys a synthetic image directory that lists only the strips or tiles
 * covering the rows and columns asked for ({@link TiffSubset}); only those are decoded. Other compressions (JPEG)
 * are read through full-width source regions in large bands.
 *
 * <p>Longer than the other classes: it is the one place that maps a read request onto TIFF
 * strips or tiles (TiffSubset, TiffBlocks, PredictorUndo and DecodeTarget do the decoding); the direct path for
 * uncompressed blocks sits beside the decoded one so that both share the block walk.
 */
public final class GeoTiffSource implements RasterSource {

    /** The largest SamplesPerPixel, a SHORT field (TIFF 6.0). */
    private static final int MAX_SAMPLES_PER_PIXEL = 0xFFFF;

    private final Path file;
    private final ImageInputStream stream;
    private final ImageReader reader;
    private final DemInfo info;
    private final int rowBlock;
    private final boolean tiled;
    private final TiffSubset.Layout layout; // null: no subsetting, use source regions
    private final FileChannel channel;
    private final ValueScale valueScale;
    private final long blockBytes;
    private final SampleDecoder decoder = new SampleDecoder();
    private ByteBuffer direct = ByteBuffer.allocateDirect(0);
    private float[] decoded = new float[0];

    private GeoTiffSource(Path file, ImageInputStream stream, ImageReader reader, DemInfo info, int rowBlock,
                          boolean tiled, TiffSubset.Layout layout, FileChannel channel, ValueScale valueScale,
                          long blockBytes) {
        this.file = file;
        this.stream = stream;
        this.reader = reader;
        this.info = info;
        this.rowBlock = rowBlock;
        this.tiled = tiled;
        this.layout = layout;
        this.channel = channel;
        this.valueScale = valueScale;
        this.blockBytes = blockBytes;
    }

    public static RasterSource open(Path tif) throws IOException {
        ImageInputStream stream = new FileImageInputStream(tif.toFile());
        ImageReader reader = null;
        try {
            reader = new TIFFImageReaderSpi().createReaderInstance();
            reader.setInput(stream, true, false);
            if (reader.getNumImages(true) < 1) {
                throw new DemFormatException(tif, "the TIFF holds no image (its first image directory is missing;"
                        + " truncated or corrupt?)");
            }
            int width = reader.getWidth(0);
            int height = reader.getHeight(0);
            IIOMetadata metadata = reader.getImageMetadata(0);
            TiffFields fields = TiffFields.of(metadata);
            List<String> notices = new ArrayList<>();
            SampleType type = GeoTiffTags.sampleType(tif, fields);
            int bands = fields.intValue(TiffFields.SAMPLES_PER_PIXEL, 1);
            if (bands < 1 || bands > MAX_SAMPLES_PER_PIXEL) {
                // the decoder sizes arrays by it: 2³¹ − 1 from a corrupt field type ran it out of memory
                throw new DemFormatException(tif, "SamplesPerPixel (tag 277) is " + bands + "; it must be 1 to "
                        + MAX_SAMPLES_PER_PIXEL + " (a SHORT; corrupt TIFF?)");
            }
            if (bands > 1) {
                notices.add("the file has " + bands + " bands; band 1 is read");
            }
            GeoTiffTags.checkCompression(tif, fields);
            TiffBlocks blocks = TiffBlocks.of(tif, fields, width, height, Files.size(tif));
            GridGeometry geometry = GeoTiffTags.geometry(tif, fields, width, height, notices);
            Double noData = GeoTiffTags.noData(fields, notices);
            ValueScale valueScale = ValueScale.fromGdalMetadata(fields.ascii(TiffFields.GDAL_METADATA), notices);
            boolean tiled = blocks.tiled();
            int rowBlock = blocks.blockHeight();
            DemInfo info = new DemInfo(tif.toString(), DemFormat.GEOTIFF, type, bands, geometry, noData, notices);
            FileChannel channel = FileChannel.open(tif, StandardOpenOption.READ);
            TiffSubset.Layout layout = layoutOf(fields, blocks, width, height, byteOrder(channel));
            return new GeoTiffSource(tif, stream, reader, info, rowBlock, tiled, layout, channel, valueScale,
                    blockBytes(fields, blocks, width));
        } catch (DemFormatException e) {
            closeQuietly(reader, stream);
            throw e;
        } catch (IOException | RuntimeException e) {
            closeQuietly(reader, stream);
            throw new DemFormatException(tif, "not a readable TIFF (truncated or corrupt?): " + describeDirectory(e),
                    e);
        }
    }

    @Override
    public DemInfo info() {
        return info;
    }

    /** One strip or tile, all its samples, twice: as stored (at most as large, uncompressed) and decoded. */
    @Override
    public long blockBytes() {
        return blockBytes;
    }

    private static long blockBytes(TiffFields fields, TiffBlocks blocks, int width) {
        long across = blocks.tiled() ? blocks.blockWidth() : width;
        long bitsPerPixel = 0;
        long[] bits = fields.has(TiffFields.BITS_PER_SAMPLE) ? fields.longs(TiffFields.BITS_PER_SAMPLE)
                : new long[] {1};
        for (long b : bits) {
            bitsPerPixel += Math.max(0, Math.min(b, 64));
        }
        if (bits.length == 1) {
            bitsPerPixel *= Math.max(1, Math.min(fields.intValue(TiffFields.SAMPLES_PER_PIXEL, 1), 1 << 16));
        }
        return MemoryGuard.saturatedMultiply(2 * across * blocks.blockHeight(), (bitsPerPixel + 7) / 8);
    }

    @Override
    public ValueScale valueScale() {
        return valueScale;
    }

    @Override
    public int naturalRowBlock() {
        return rowBlock;
    }

    /**
     * About 4 M cells per read with subsetting. Without it, large bands: TwelveMonkeys decodes every strip or
     * tile from the top of the image on each read, so each call costs time in proportion to the rows above it; up
     * to 32 M cells per call (less on small heaps: 1/64 of the maximum heap, at least 4 M cells).
     */
    @Override
    public long bandCells() {
        if (layout != null) {
            return 1L << 22;
        }
        return Math.max(1L << 22, Math.min(1L << 25, Runtime.getRuntime().maxMemory() / 64));
    }

    /** With subsetting each read decodes only its own strips or tiles. */
    @Override
    public boolean readsRowsIndependently() {
        return layout != null;
    }

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        readRows(col, row, width, rows, dst, 0);
    }

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        if (layout != null) {
            try {
                readSubset(col, row, width, rows, dst, at);
            } catch (IndexOutOfBoundsException | NegativeArraySizeException | IllegalArgumentException
                     | ArithmeticException | java.nio.BufferUnderflowException e) {
                // what the checks at open did not foresee in a corrupt file: still the file's own error
                throw new DemFormatException(file, "cannot decode rows " + row + "–" + (row + rows - 1)
                        + " (truncated or corrupt TIFF?): " + describe(e), e);
            }
            return;
        }
        ImageReadParam param = reader.getDefaultReadParam();
        // TwelveMonkeys 3.15.0 fails on tiled images when the source region is narrower than the image
        // (haraldk/TwelveMonkeys#746), so tiled files are read in full-width row bands and cropped here.
        int readCol = tiled ? 0 : col;
        int readWidth = tiled ? info.width() : width;
        param.setSourceRegion(new Rectangle(readCol, row, readWidth, rows));
        Raster raster;
        try {
            raster = reader.readRaster(0, param);
        } catch (IOException | RuntimeException e) {
            throw new DemFormatException(file, "cannot decode rows " + row + "–" + (row + rows - 1)
                    + " (truncated or corrupt TIFF?): " + describe(e), e);
        }
        if (raster.getWidth() < readWidth || raster.getHeight() < rows) {
            throw new DemFormatException(file, "the TIFF decoder returned " + raster.getWidth() + "×"
                    + raster.getHeight() + " cells for a " + readWidth + "×" + rows + " region");
        }
        copyBand0(raster, col - readCol, 0, width, rows, dst, at);
    }

    /**
     * Decodes only the strips or tiles covering the cells, through a synthetic directory. Where some of them are
     * sparse (never written), block by block: sparse ones read as the declared no-data, or 0 without one, as GDAL
     * reads them.
     */
    private void readSubset(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        if (!layout.coversSparse(col, row, width, rows)) {
            decodeSubset(col, row, width, rows, dst, at);
            return;
        }
        float fill = info.declaredNoData() != null ? info.declaredNoData().floatValue() : 0f;
        int bw = layout.blockWidth();
        int bh = layout.blockHeight();
        for (int by = row / bh * bh; by < row + rows; by += bh) {
            int y0 = Math.max(by, row);
            int h = Math.min(by + bh, row + rows) - y0;
            for (int bx = col / bw * bw; bx < col + width; bx += bw) {
                int x0 = Math.max(bx, col);
                int w = Math.min(bx + bw, col + width) - x0;
                float[] part = new float[w * h];
                if (layout.isSparse(by / bh * layout.blocksAcross() + bx / bw)) {
                    java.util.Arrays.fill(part, fill);
                } else {
                    decodeSubset(x0, y0, w, h, part, 0);
                }
                for (int r = 0; r < h; r++) {
                    System.arraycopy(part, r * w, dst, at + (y0 - row + r) * width + (x0 - col), w);
                }
            }
        }
    }

    /** Decodes the strips or tiles covering the cells, none of them sparse, through a synthetic directory. */
    private void decodeSubset(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        if (layout.decodedHere() && decodeHere(col, row, width, rows, dst, at)) {
            return;
        }
        if (layout.predictorUndoneHere()) {
            decodeUndoingPredictor(col, row, width, rows, dst, at);
            return;
        }
        TiffSubset.Subset subset = TiffSubset.of(layout, col, row, width, rows);
        Raster raster;
        DecodeTarget target;
        ImageReader r = new TIFFImageReaderSpi().createReaderInstance();
        try (ImageInputStream in = new SplicedImageInputStream(subset.head(), subset.shift(), channel)) {
            r.setInput(in, true, true);
            target = DecodeTarget.forRawType(r.getRawImageType(0), subset.width(), subset.height());
            ImageReadParam param = r.getDefaultReadParam();
            param.setDestination(target); // null: the decoder's own image
            raster = r.readRaster(0, param);
        } catch (IOException | RuntimeException e) {
            throw new DemFormatException(file, "cannot decode rows " + row + "–" + (row + rows - 1)
                    + " (truncated or corrupt TIFF?): " + describe(e), e);
        } finally {
            r.dispose();
        }
        if (raster.getWidth() < subset.width() || raster.getHeight() < subset.height()) {
            throw new DemFormatException(file, "the TIFF decoder returned " + raster.getWidth() + "×"
                    + raster.getHeight() + " cells for " + subset.width() + "×" + subset.height());
        }
        if (target != null && raster == target.getRaster()) {
            copyCells(target.array(), raster.getDataBuffer().getDataType(), subset.width(), col - subset.x0(),
                    row - subset.y0(), width, rows, dst, at);
        } else {
            copyBand0(raster, col - subset.x0(), row - subset.y0(), width, rows, dst, at);
        }
    }

    /**
     * Like {@link #decodeSubset} for uncompressed, LZW and Deflate blocks: read here with one positional read each,
     * LZW decompressed by {@link TiffLzw}, Deflate by {@link TiffDeflate} (which also checks that each stream is
     * whole), turned into samples by {@link PredictorUndo}. TwelveMonkeys reads uncompressed samples through stream
     * calls and LZW bytes one synchronized call at a time (docs/performance.md), and reads a Deflate block only
     * until its rows are full, never reaching the checksum.
     *
     * @return false, with nothing decided, when a block is in the old, bit-reversed LZW (left to TwelveMonkeys)
     */
    private boolean decodeHere(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        boolean lzw = layout.compression() == 5;
        boolean deflate = layout.compression() == 8 || layout.compression() == 32946;
        int bw = layout.blockWidth();
        int bh = layout.blockHeight();
        int bytes = layout.bytesPerSample();
        int segment = layout.tiled() ? bw : layout.width();
        for (int by = row / bh * bh; by < row + rows; by += bh) {
            int blockRows = layout.tiled() ? bh : Math.min(bh, layout.height() - by);
            long blockBytes = (long) segment * blockRows * bytes;
            if (blockBytes > MemoryGuard.MAX_ARRAY) {
                throw new DemFormatException(file, "its " + (layout.tiled() ? "tiles" : "strips") + " hold "
                        + MemoryGuard.human(blockBytes) + " each, more than one Java array can hold; re-tile it,"
                        + " e.g. gdal_translate -co TILED=YES in.tif out.tif");
            }
            int expected = (int) blockBytes;
            // LZW's or Deflate's output; uncompressed data stay as read
            byte[] block = lzw || deflate ? new byte[expected] : null;
            for (int bx = col / bw * bw; bx < col + width; bx += bw) {
                int index = by / bh * layout.blocksAcross() + bx / bw;
                int x0 = Math.max(bx, col);
                int x1 = Math.min(Math.min(bx + bw, layout.width()), col + width);
                if (!lzw && !deflate && layout.predictor() == 1) {
                    if (layout.byteCounts()[index] < expected) {
                        throw new DemFormatException(file, "the data of " + (layout.tiled() ? "tile " : "strip ")
                                + index + " end after " + layout.byteCounts()[index] + " of " + expected
                                + " bytes (truncated or corrupt TIFF?)");
                    }
                    int y0 = Math.max(by, row);
                    int y1 = Math.min(by + blockRows, row + rows);
                    readUncompressed(layout.offsets()[index], segment * bytes, y0 - by, y1 - y0, x0 - bx, x1 - x0,
                            dst, at + (y0 - row) * width + x0 - col, width);
                    continue;
                }
                byte[] stored = readBlock(layout.offsets()[index], layout.byteCounts()[index]);
                if (lzw && !TiffLzw.isNewStyle(stored, stored.length)) {
                    return false;
                }
                int got;
                if (lzw) {
                    try {
                        got = TiffLzw.decode(stored, stored.length, block);
                    } catch (IOException e) {
                        throw new DemFormatException(file, "cannot decode rows " + row + "–" + (row + rows - 1)
                                + " (truncated or corrupt TIFF?): " + e.getMessage(), e);
                    }
                } else if (deflate) {
                    try {
                        TiffDeflate.decode(stored, stored.length, block);
                    } catch (IOException e) {
                        throw new DemFormatException(file, "cannot decode " + (layout.tiled() ? "tile " : "strip ")
                                + index + " (rows " + by + "–" + (by + blockRows - 1) + "; corrupt TIFF?): "
                                + e.getMessage(), e);
                    }
                    got = expected;
                } else {
                    got = Math.min(stored.length, expected);
                }
                byte[] samples = lzw || deflate ? block : stored;
                if (got < expected) {
                    throw new DemFormatException(file, "the data of " + (layout.tiled() ? "tile " : "strip ")
                            + index + " end after " + got + " of " + expected + " bytes (truncated or corrupt"
                            + " TIFF?)");
                }
                for (int y = Math.max(by, row); y < Math.min(by + blockRows, row + rows); y++) {
                    PredictorUndo.row(samples, (y - by) * segment * bytes, segment, layout.predictor(),
                            info.dataType(), layout.order(), x0 - bx, x1 - x0, dst, at + (y - row) * width + x0 - col,
                            decoder);
                }
            }
        }
        return true;
    }

    /** Bytes of an uncompressed block read at once into {@link #direct}. */
    private static final int CHUNK = 1 << 20;

    /**
     * Rows {@code [firstRow, firstRow + rows)} of an uncompressed strip or tile at {@code offset}, of
     * {@code rowBytes} each, columns {@code [firstCol, firstCol + cols)}: read into a direct buffer, several rows
     * (at most {@link #CHUNK} bytes) per read, and converted from there in bulk ({@link SampleDecoder}) to
     * {@code dst[at…]}, {@code stride} cells per row: straight into place when the rows are whole and adjacent
     * there, else all of them at once into {@link #decoded} and copied row by row (one conversion per read, not per
     * row: a 128² tile has short rows).
     */
    private void readUncompressed(long offset, int rowBytes, int firstRow, int rows, int firstCol, int cols,
                                  float[] dst, int at, int stride) throws IOException {
        int bytes = layout.bytesPerSample();
        SampleType type = info.dataType();
        if (rowBytes > CHUNK) {
            // a row longer than a chunk: its columns in pieces
            int pieceCells = CHUNK / bytes;
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < cols; c += pieceCells) {
                    int n = Math.min(pieceCells, cols - c);
                    readDirect(offset + (long) (firstRow + r) * rowBytes + (long) (firstCol + c) * bytes,
                            n * bytes);
                    decoder.decode(direct, type, dst, at + r * stride + c, n);
                }
            }
            return;
        }
        int perRead = Math.max(1, CHUNK / rowBytes);
        int segment = rowBytes / bytes;
        boolean inPlace = cols == segment && stride == cols;
        for (int r0 = 0; r0 < rows; r0 += perRead) {
            int n = Math.min(perRead, rows - r0);
            readDirect(offset + (long) (firstRow + r0) * rowBytes, n * rowBytes);
            if (inPlace) {
                decoder.decode(direct, type, dst, at + r0 * stride, n * cols);
                continue;
            }
            if (decoded.length < n * segment) {
                decoded = new float[Math.max(n * segment, Math.min(CHUNK, 2 * decoded.length))];
            }
            decoder.decode(direct, type, decoded, 0, n * segment);
            for (int r = 0; r < n; r++) {
                System.arraycopy(decoded, r * segment + firstCol, dst, at + (r0 + r) * stride, cols);
            }
        }
    }

    /** Reads {@code length} bytes at {@code position} into {@link #direct}, in the file's byte order. */
    private void readDirect(long position, int length) throws IOException {
        if (direct.capacity() < length) {
            direct = ByteBuffer.allocateDirect(Math.max(length, Math.min(CHUNK, 2 * direct.capacity())));
        }
        direct.clear().limit(length);
        long at = position;
        while (direct.hasRemaining()) {
            int n = channel.read(direct, at);
            if (n < 0) {
                throw new DemFormatException(file, "the file ends inside a strip or tile (truncated?)");
            }
            at += n;
        }
        direct.flip().order(layout.order());
    }

    /** The stored bytes of one strip or tile. */
    private byte[] readBlock(long offset, long count) throws IOException {
        if (count > Integer.MAX_VALUE - 8) {
            throw new DemFormatException(file, "a strip or tile of " + count + " bytes is too large to read");
        }
        if (offset < 0 || count < 0) { // refused at open (TiffBlocks); kept off FileChannel.read all the same
            throw new DemFormatException(file, "a strip or tile at offset " + offset + " of " + count
                    + " bytes lies outside the file");
        }
        byte[] b = new byte[(int) count];
        ByteBuffer buffer = ByteBuffer.wrap(b);
        long at = offset;
        while (buffer.hasRemaining()) {
            int n = channel.read(buffer, at);
            if (n < 0) {
                throw new DemFormatException(file, "the file ends inside a strip or tile (truncated?)");
            }
            at += n;
        }
        return b;
    }

    /**
     * Like {@link #decodeSubset}, with TwelveMonkeys only decompressing the blocks ({@link TiffSubset#ofBytes})
     * and the predictor undone here, row by row of each block ({@link PredictorUndo}).
     */
    private void decodeUndoingPredictor(int col, int row, int width, int rows, float[] dst, int at)
            throws IOException {
        TiffSubset.Subset subset = TiffSubset.ofBytes(layout, col, row, width, rows);
        int bytes = layout.bytesPerSample();
        int rowBytes = subset.width() * bytes;
        byte[] raw;
        ImageReader r = new TIFFImageReaderSpi().createReaderInstance();
        try (ImageInputStream in = new SplicedImageInputStream(subset.head(), subset.shift(), channel)) {
            r.setInput(in, true, true);
            DecodeTarget target = DecodeTarget.forRawType(r.getRawImageType(0), rowBytes, subset.height());
            if (target == null || !(target.array() instanceof byte[] array)) {
                throw new IOException("the decoder gave no byte raster for the decompressed blocks");
            }
            ImageReadParam param = r.getDefaultReadParam();
            param.setDestination(target);
            Raster raster = r.readRaster(0, param);
            if (raster != target.getRaster() || raster.getWidth() < rowBytes
                    || raster.getHeight() < subset.height()) {
                throw new IOException("the decoder did not fill the " + rowBytes + "×" + subset.height()
                        + " byte raster of the decompressed blocks");
            }
            raw = array;
        } catch (IOException | RuntimeException e) {
            throw new DemFormatException(file, "cannot decode rows " + row + "–" + (row + rows - 1)
                    + " (truncated or corrupt TIFF?): " + describe(e), e);
        } finally {
            r.dispose();
        }
        // the predictor runs along each row of each block: a tile's width, or a strip's (the image's)
        int segment = layout.tiled() ? layout.blockWidth() : layout.width();
        int first = col - subset.x0();
        int end = first + width;
        for (int y = 0; y < rows; y++) {
            int base = (row - subset.y0() + y) * rowBytes;
            for (int s0 = first / segment * segment; s0 < end; s0 += segment) {
                int from = Math.max(first, s0);
                int to = Math.min(end, s0 + segment);
                PredictorUndo.row(raw, base + s0 * bytes, segment, layout.predictor(), info.dataType(),
                        layout.order(), from - s0, to - from, dst, at + y * width + from - first, decoder);
            }
        }
    }

    /**
     * The layout for {@link TiffSubset}, or null when the compression needs more than the strip or tile bytes
     * (JPEG tables) and subsetting is not attempted.
     */
    private static TiffSubset.Layout layoutOf(TiffFields f, TiffBlocks b, int width, int height, ByteOrder order) {
        int compression = f.intValue(TiffFields.COMPRESSION, 1);
        if (compression != 1 && compression != 5 && compression != 8 && compression != 32946
                && compression != 32773) {
            return null;
        }
        int spp = f.intValue(TiffFields.SAMPLES_PER_PIXEL, 1);
        long[] bits = f.has(TiffFields.BITS_PER_SAMPLE) ? f.longs(TiffFields.BITS_PER_SAMPLE) : new long[] {1};
        long[] formats = f.has(TiffFields.SAMPLE_FORMAT) ? f.longs(TiffFields.SAMPLE_FORMAT) : new long[] {1};
        int planar = f.intValue(TiffFields.PLANAR_CONFIGURATION, 1);
        if (spp > 1 && planar != 2 && (bits.length < spp || formats.length < spp)) {
            return null; // a per-sample array is short: leave the file to the decoder's own rules
        }
        int blockWidth = b.blockWidth();
        int rowBlock = b.blockHeight();
        long[] offsets = b.offsets();
        long[] counts = b.byteCounts();
        long blocks = ((width + (long) blockWidth - 1) / blockWidth) * ((height + (long) rowBlock - 1) / rowBlock);
        if (offsets.length < blocks || counts.length < blocks) {
            return null; // no byte counts: left to the decoder
        }
        return new TiffSubset.Layout(order, width, height, bits, compression,
                f.intValue(TiffFields.PHOTOMETRIC, 1), spp, planar, f.intValue(TiffFields.PREDICTOR, 1), formats,
                f.has(TiffFields.EXTRA_SAMPLES) ? f.longs(TiffFields.EXTRA_SAMPLES) : new long[0], b.tiled(),
                blockWidth, rowBlock, offsets, counts);
    }

    /** The byte order of the TIFF header ("II" little-endian, "MM" big-endian). */
    private static ByteOrder byteOrder(FileChannel channel) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(2);
        channel.read(b, 0);
        return b.get(0) == 'M' ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN;
    }

    /**
     * Columns {@code [skipX, skipX+width)} of rows {@code [skipY, skipY+rows)} of band 0 of the raster as float32,
     * undoing Java's lack of signed bytes and unsigned ints.
     */
    private void copyBand0(Raster raster, int skipX, int skipY, int width, int rows, float[] dst, int at) {
        int x0 = raster.getMinX() + skipX;
        int y0 = raster.getMinY() + skipY;
        SampleType type = info.dataType();
        int dataType = raster.getDataBuffer().getDataType();
        if (dataType == DataBuffer.TYPE_INT || dataType == DataBuffer.TYPE_BYTE) {
            int[] row = new int[width];
            for (int r = 0; r < rows; r++) {
                raster.getSamples(x0, y0 + r, width, 1, 0, row);
                for (int c = 0; c < width; c++) {
                    int v = row[c];
                    dst[at + r * width + c] = switch (type) {
                        case INT8 -> (byte) v;
                        case UINT32 -> v & 0xFFFFFFFFL;
                        default -> v;
                    };
                }
            }
        } else {
            float[] row = new float[width];
            for (int r = 0; r < rows; r++) {
                raster.getSamples(x0, y0 + r, width, 1, 0, row);
                System.arraycopy(row, 0, dst, at + r * width, width);
            }
        }
    }

    /**
     * Like {@link #copyBand0}, from the cells of a {@link DecodeTarget} ({@code stride} per row, of a DataBuffer
     * type) with the same conversions as the JDK's sample getters there: bytes and unsigned shorts unsigned,
     * shorts signed, then the sample type's reinterpretation of ints and bytes.
     */
    private void copyCells(Object cells, int dataType, int stride, int skipX, int skipY, int width, int rows,
                           float[] dst, int at) {
        SampleType type = info.dataType();
        for (int r = 0; r < rows; r++) {
            int from = (skipY + r) * stride + skipX;
            int to = at + r * width;
            if (cells instanceof float[] a) {
                System.arraycopy(a, from, dst, to, width);
            } else if (cells instanceof short[] a) {
                boolean unsigned = dataType == DataBuffer.TYPE_USHORT;
                for (int c = 0; c < width; c++) {
                    dst[to + c] = unsigned ? a[from + c] & 0xFFFF : a[from + c];
                }
            } else if (cells instanceof int[] a) {
                boolean unsigned = type == SampleType.UINT32;
                for (int c = 0; c < width; c++) {
                    dst[to + c] = unsigned ? a[from + c] & 0xFFFFFFFFL : a[from + c];
                }
            } else if (cells instanceof byte[] a) {
                boolean signed = type == SampleType.INT8;
                for (int c = 0; c < width; c++) {
                    dst[to + c] = signed ? a[from + c] : a[from + c] & 0xFF;
                }
            } else {
                double[] a = (double[]) cells;
                for (int c = 0; c < width; c++) {
                    dst[to + c] = (float) a[from + c];
                }
            }
        }
    }

    @Override
    public void close() throws IOException {
        reader.dispose();
        try {
            stream.close();
        } finally {
            channel.close();
        }
    }

    /** The decoder's own message, or the kind of failure when it has none. */
    private static String describe(Throwable e) {
        String m = e.getMessage();
        if (m != null && !m.isBlank()) {
            return m;
        }
        return e instanceof java.io.EOFException ? "the file ends inside the data of a strip or tile"
                : "the decoder failed (" + e.getClass().getSimpleName() + ")";
    }

    /** {@link #describe}, for failures while the image directory is read. */
    private static String describeDirectory(Throwable e) {
        // TwelveMonkeys stores the EOFException of a field whose values lie outside the file as its value
        return e instanceof ClassCastException ? "a field of the image directory has values of the wrong type or"
                + " outside the file" : describe(e);
    }

    private static void closeQuietly(ImageReader reader, ImageInputStream stream) {
        if (reader != null) {
            reader.dispose();
        }
        try {
            stream.close();
        } catch (IOException ignored) {
            // already failing
        }
    }
}
