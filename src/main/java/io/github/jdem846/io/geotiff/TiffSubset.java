package io.github.jdem846.io.geotiff;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * A synthetic BigTIFF header and image directory describing a rectangle of whole strips or tiles of an existing
 * TIFF, whose data stay where they are in the file (shifted by the header's length, see
 * {@link SplicedImageInputStream}). Decoding the synthetic image decodes only those strips or tiles: TwelveMonkeys
 * 3.15.0 otherwise decodes every strip and tile above the last row of a source region.
 *
 * <p>Only band 1 of a planar (PlanarConfiguration 2) file is described. A one-sample image is declared
 * BlackIsZero, so that no decoder inverts WhiteIsZero or expands a palette: the raw samples come out.
 */
final class TiffSubset {

    private static final int SHORT = 3;
    private static final int LONG8 = 16;

    /** What is needed of the original directory. */
    record Layout(ByteOrder order, int width, int height, long[] bitsPerSample, int compression,
                  int photometric, int samplesPerPixel, int planar, int predictor, long[] sampleFormat,
                  long[] extraSamples, boolean tiled, int blockWidth, int blockHeight, long[] offsets,
                  long[] byteCounts) {

        int blocksAcross() {
            return (width + blockWidth - 1) / blockWidth;
        }

        int blocksDown() {
            return (height + blockHeight - 1) / blockHeight;
        }

        /**
         * Whether block {@code index} (row-major, plane 0) was never written: GDAL's {@code SPARSE_OK} leaves
         * blocks of only no-data (or only 0) out with offset and byte count 0, and readers fill them.
         */
        boolean isSparse(int index) {
            return offsets[index] == 0 || byteCounts[index] == 0;
        }

        /**
         * Whether the file's predictor is undone here rather than by the decoder ({@link #ofBytes}): predictor 2
         * on 8/16/32-bit integers or 3 on 32/64-bit floats, one sample per pixel (or band 1 of separate planes),
         * LZW or Deflate. TwelveMonkeys 3.15.0 undoes them through byte-by-byte streams, most of a Deflate read.
         */
        boolean predictorUndoneHere() {
            boolean compressed = compression == 5 || compression == 8 || compression == 32946;
            return oneSample() && compressed && predictor != 1 && samplesUndoable();
        }

        /**
         * Whether the blocks are read and decoded here rather than by TwelveMonkeys: uncompressed, LZW
         * ({@link TiffLzw}) or Deflate ({@link TiffDeflate}) blocks with predictor 1, 2 or 3 (as
         * {@link #predictorUndoneHere}), one sample per pixel or band 1 of separate planes, samples of 8, 16, 32 or
         * 64 bits.
         */
        boolean decodedHere() {
            boolean deflate = compression == 8 || compression == 32946;
            return (compression == 1 || compression == 5 || deflate) && oneSample() && samplesUndoable();
        }

        private boolean oneSample() {
            return samplesPerPixel == 1 || planar == 2;
        }

        /**
         * Whether {@link PredictorUndo} handles these samples and this predictor: none on 8/16/32-bit integers or
         * 32/64-bit floats, 2 on those integers, 3 on those floats.
         */
        private boolean samplesUndoable() {
            int bits = (int) bitsPerSample[0];
            int format = (int) sampleFormat[0];
            boolean integers = (format == 1 || format == 2) && (bits == 8 || bits == 16 || bits == 32);
            boolean floats = format == 3 && (bits == 32 || bits == 64);
            return predictor == 1 && (integers || floats) || predictor == 2 && integers || predictor == 3 && floats;
        }

        /** Bytes of one sample of band 1. */
        int bytesPerSample() {
            return (int) bitsPerSample[0] / 8;
        }

        /** Whether any block under columns {@code [col, col+w)} and rows {@code [row, row+h)} is sparse. */
        boolean coversSparse(int col, int row, int w, int h) {
            for (int br = row / blockHeight; br <= (row + h - 1) / blockHeight; br++) {
                for (int bc = col / blockWidth; bc <= (col + w - 1) / blockWidth; bc++) {
                    if (isSparse(br * blocksAcross() + bc)) {
                        return true;
                    }
                }
            }
            return false;
        }
    }

    /**
     * The synthetic image: its head bytes, the shift of the file behind them, and the image pixel that its
     * (0, 0) is.
     */
    record Subset(byte[] head, long shift, int x0, int y0, int width, int height) {
    }

    private TiffSubset() {
    }

    /** The subset of whole blocks covering columns {@code [col, col+w)} and rows {@code [row, row+h)}. */
    static Subset of(Layout l, int col, int row, int w, int h) {
        return build(l, col, row, w, h, false);
    }

    /**
     * The same blocks declared as 8-bit bytes without a predictor, each block row as wide as the block in bytes
     * ({@code blockWidth × bytesPerSample}; tiles are never cropped at the east edge, so every block row is
     * whole): the decoder only decompresses, and the caller undoes the predictor ({@link PredictorUndo}). The
     * subset's x0, y0, width and height are in samples, its decoded image {@code width × bytesPerSample} bytes
     * wide.
     */
    static Subset ofBytes(Layout l, int col, int row, int w, int h) {
        return build(l, col, row, w, h, true);
    }

    private static Subset build(Layout l, int col, int row, int w, int h, boolean bytes) {
        int bc0 = col / l.blockWidth();
        int bc1 = (col + w + l.blockWidth() - 1) / l.blockWidth();
        int br0 = row / l.blockHeight();
        int br1 = (row + h + l.blockHeight() - 1) / l.blockHeight();
        int x0 = bc0 * l.blockWidth();
        int y0 = br0 * l.blockHeight();
        int sw = (bytes && l.tiled() ? bc1 * l.blockWidth() : Math.min(bc1 * l.blockWidth(), l.width())) - x0;
        int b = bytes ? l.bytesPerSample() : 1;
        int sh = Math.min(br1 * l.blockHeight(), l.height()) - y0;
        int n = (bc1 - bc0) * (br1 - br0);
        long[] offsets = new long[n];
        long[] counts = new long[n];
        int k = 0;
        for (int br = br0; br < br1; br++) {
            for (int bc = bc0; bc < bc1; bc++) {
                int i = br * l.blocksAcross() + bc; // plane 0 comes first in planar files
                offsets[k] = l.offsets()[i];
                counts[k] = l.byteCounts()[i];
                k++;
            }
        }
        boolean onlyBand1 = l.planar() == 2 || l.samplesPerPixel() == 1;
        int spp = onlyBand1 ? 1 : l.samplesPerPixel();
        List<long[]> entries = new ArrayList<>(); // {tag, type, values...}
        entries.add(entry(256, LONG8, (long) sw * b));
        entries.add(entry(257, LONG8, sh));
        entries.add(entry(258, SHORT, bytes ? new long[] {8}
                : onlyBand1 ? new long[] {l.bitsPerSample()[0]} : l.bitsPerSample()));
        entries.add(entry(259, SHORT, l.compression()));
        entries.add(entry(262, SHORT, spp == 1 ? 1 : l.photometric()));
        entries.add(entry(277, SHORT, spp));
        entries.add(entry(284, SHORT, 1));
        if (l.predictor() != 1 && !bytes) {
            entries.add(entry(317, SHORT, l.predictor()));
        }
        if (!onlyBand1 && l.extraSamples().length > 0) {
            entries.add(entry(338, SHORT, l.extraSamples()));
        }
        entries.add(entry(339, SHORT, bytes ? new long[] {1}
                : onlyBand1 ? new long[] {l.sampleFormat()[0]} : l.sampleFormat()));
        if (l.tiled()) {
            entries.add(entry(322, LONG8, (long) l.blockWidth() * b));
            entries.add(entry(323, LONG8, l.blockHeight()));
            entries.add(entry(324, LONG8, offsets));
            entries.add(entry(325, LONG8, counts));
        } else {
            entries.add(entry(273, LONG8, offsets));
            entries.add(entry(278, LONG8, l.blockHeight()));
            entries.add(entry(279, LONG8, counts));
        }
        entries.sort(Comparator.comparingLong(e -> e[0]));
        return withHead(new Subset(null, 0, x0, y0, sw, sh), entries, l.order());
    }

    private static long[] entry(int tag, int type, long... values) {
        long[] e = new long[values.length + 2];
        e[0] = tag;
        e[1] = type;
        System.arraycopy(values, 0, e, 2, values.length);
        return e;
    }

    /** Writes header + directory + out-of-line values; block offsets are shifted by the head's length. */
    private static Subset withHead(Subset s, List<long[]> entries, ByteOrder order) {
        int dirBytes = 8 + entries.size() * 20 + 8;
        int extra = 0;
        for (long[] e : entries) {
            int bytes = (e.length - 2) * (e[1] == SHORT ? 2 : 8);
            if (bytes > 8) {
                extra += bytes;
            }
        }
        int headLength = 16 + dirBytes + extra;
        long shift = (headLength + 7) / 8 * 8;
        ByteBuffer b = ByteBuffer.allocate(headLength).order(order);
        b.put((byte) (order == ByteOrder.LITTLE_ENDIAN ? 'I' : 'M'));
        b.put((byte) (order == ByteOrder.LITTLE_ENDIAN ? 'I' : 'M'));
        b.putShort((short) 43).putShort((short) 8).putShort((short) 0).putLong(16);
        b.putLong(entries.size());
        int outOfLine = 16 + dirBytes;
        for (long[] e : entries) {
            int tag = (int) e[0];
            boolean shifted = tag == 273 || tag == 324;
            int n = e.length - 2;
            int size = e[1] == SHORT ? 2 : 8;
            b.putShort((short) tag).putShort((short) e[1]).putLong(n);
            int at = n * size > 8 ? outOfLine : b.position();
            if (n * size > 8) {
                b.putLong(outOfLine);
                outOfLine += n * size;
            }
            int save = b.position();
            b.position(at);
            for (int i = 0; i < n; i++) {
                long v = e[i + 2] + (shifted ? shift : 0);
                if (size == 2) {
                    b.putShort((short) v);
                } else {
                    b.putLong(v);
                }
            }
            b.position(n * size > 8 ? save : at + 8);
        }
        b.putLong(0); // no next directory
        return new Subset(b.array(), shift, s.x0(), s.y0(), s.width(), s.height());
    }
}
