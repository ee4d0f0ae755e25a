package io.github.jdem846.output;

import java.util.Arrays;

/**
 * Raw deflate data (RFC 1951) that codes every byte as a literal: one block with its own Huffman code per
 * {@link #BLOCK_BYTES} bytes of input, or a stored block where that would be no smaller. This is zlib's
 * {@code Z_HUFFMAN_ONLY} strategy, which {@link PngWriter} uses for continuous-tone gray rows, written out in Java:
 * zlib still keeps its window and hash tables up to date in that mode and builds a code every 16 K symbols, and the
 * rows of a 4000² hillshade took about three times as long in it as here (docs/performance.md, "Writing PNG and
 * GeoTIFF"). The bytes differ from zlib's, the data they inflate to do not; the same input gives the same bytes on
 * every JVM.
 *
 * <p>Not thread-safe: one per thread, reused from segment to segment.
 */
final class HuffmanBlocks {

    /** Input bytes per block: at most 65 535, the most a stored block holds. */
    static final int BLOCK_BYTES = 65535;
    /** Longest literal/length code deflate allows. */
    private static final int MAX_BITS = 15;
    /** Longest code-length code. */
    private static final int MAX_LENGTH_BITS = 7;
    private static final int END_OF_BLOCK = 256;
    /** Literals 0–255 and end-of-block: the length codes (257 …) are never used. */
    private static final int LITERALS = 257;
    /** The order in which a block header lists the code-length code's lengths. */
    private static final int[] LENGTH_ORDER = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

    private final int[] counts = new int[LITERALS];
    /** The literal counts of each block of the range {@link #count} took, and that range. */
    private int[][] blockCounts = new int[0][];
    private byte[] countedData;
    private int countedFrom = -1;
    private int countedLength = -1;
    private final int[] lengths = new int[LITERALS];
    /** Per literal: its bit-reversed code in the low 16 bits and its length above. */
    private final int[] codes = new int[LITERALS];
    /** The run-length coded code lengths of a block header (symbol | extra value << 8). */
    private final int[] header = new int[LITERALS + 1];
    private final int[] lengthCounts = new int[19];
    private final int[] lengthLengths = new int[19];
    private final int[] lengthCodes = new int[19];
    private final HuffmanLengths huffman = new HuffmanLengths(LITERALS);
    private final HuffmanLengths lengthHuffman = new HuffmanLengths(19);

    private byte[] out;
    private int position;
    private long bits;
    private int bitCount;

    /** The most bytes {@link #deflate} writes for {@code n} input bytes. */
    static int bound(int n) {
        return n + 5 * (n / BLOCK_BYTES + 1) + 8;
    }

    /**
     * Counts the bytes of {@code data[from, from + n)} block by block, for a {@link #deflate} of the same range that
     * follows, and returns the counts of the whole range (a new array): one pass over the bytes for both.
     *
     * @return 256 counts, one per byte value
     */
    int[] count(byte[] data, int from, int n) {
        int blocks = Math.max(1, (n + BLOCK_BYTES - 1) / BLOCK_BYTES);
        if (blockCounts.length < blocks) {
            blockCounts = new int[blocks][LITERALS];
        }
        int[] total = new int[256];
        for (int b = 0; b < blocks; b++) {
            int start = from + b * BLOCK_BYTES;
            countLiterals(data, start, Math.min(BLOCK_BYTES, from + n - start), blockCounts[b]);
            for (int v = 0; v < 256; v++) {
                total[v] += blockCounts[b][v];
            }
        }
        countedData = data;
        countedFrom = from;
        countedLength = n;
        return total;
    }

    /**
     * Deflates {@code data[from, from + n)} into {@code target} from index 0 and returns the length written. The
     * data ends with the final block when {@code last}, else with an empty stored block (zlib's sync flush), which
     * leaves it on a byte boundary so that data deflated on its own may follow.
     *
     * @param target at least {@link #bound(int) bound(n)} long
     */
    int deflate(byte[] data, int from, int n, boolean last, byte[] target) {
        if (target.length < bound(n)) {
            throw new IllegalArgumentException("target of " + target.length + " bytes, " + bound(n) + " needed");
        }
        out = target;
        position = 0;
        bits = 0;
        bitCount = 0;
        boolean counted = data == countedData && from == countedFrom && n == countedLength;
        countedData = null;
        int end = from + n;
        for (int block = from; block < end || block == from; block += BLOCK_BYTES) {
            int length = Math.min(BLOCK_BYTES, end - block);
            boolean lastBlock = last && block + length >= end;
            if (counted) {
                System.arraycopy(blockCounts[(block - from) / BLOCK_BYTES], 0, counts, 0, LITERALS);
            } else {
                countLiterals(data, block, length, counts);
            }
            writeBlock(data, block, length, lastBlock);
        }
        if (!last) {
            putBits(0, 3);                   // an empty stored block, not final
            storedLength(0);
        }
        flushBits();
        out = null;
        return position;
    }

    // Small methods with one loop each: quick to compile, and no long compilation of one large method (with the
    // optimising JIT, a single method with all the loops ran uncompiled for a second on 16 million bytes).

    /** One block of the literals counted in {@link #counts}. */
    private void writeBlock(byte[] data, int from, int n, boolean last) {
        huffman.lengths(counts, MAX_BITS, lengths);
        int headerCount = runLengths();
        int orderCount = lengthCode(headerCount);
        if (storedBits(n) <= dynamicBits(orderCount)) {
            writeStored(data, from, n, last);
            return;
        }
        writeHeader(headerCount, orderCount, last);
        canonicalCodes(lengths, codes, LITERALS);
        writeLiterals(data, from, n);
        putBits(codes[END_OF_BLOCK] & 0xFFFF, codes[END_OF_BLOCK] >>> 16);
    }

    /** The counts of one block's bytes, and end-of-block's 1, in {@code c}. */
    private static void countLiterals(byte[] data, int from, int n, int[] c) {
        Arrays.fill(c, 0);
        for (int i = from; i < from + n; i++) {
            c[data[i] & 0xFF]++;
        }
        c[END_OF_BLOCK] = 1;
    }

    /**
     * The code-length code of the {@code headerCount} symbols in {@link #header}, in {@link #lengthLengths}.
     *
     * @return how many of its lengths the header lists (trailing zeros in {@link #LENGTH_ORDER} left out)
     */
    private int lengthCode(int headerCount) {
        Arrays.fill(lengthCounts, 0);
        for (int k = 0; k < headerCount; k++) {
            lengthCounts[header[k] & 0xFF]++;
        }
        lengthHuffman.lengths(lengthCounts, MAX_LENGTH_BITS, lengthLengths);
        int orderCount = 19;
        while (orderCount > 4 && lengthLengths[LENGTH_ORDER[orderCount - 1]] == 0) {
            orderCount--;
        }
        return orderCount;
    }

    /** The size of the block with its own codes, in bits. */
    private long dynamicBits(int orderCount) {
        long total = 3 + 5 + 5 + 4 + 3L * orderCount;
        for (int s = 0; s < 19; s++) {
            total += (long) lengthCounts[s] * lengthLengths[s];
        }
        total += 2L * lengthCounts[16] + 3L * lengthCounts[17] + 7L * lengthCounts[18];
        for (int s = 0; s < LITERALS; s++) {
            total += (long) counts[s] * lengths[s];
        }
        return total;
    }

    /** The most a stored block of {@code n} bytes takes, in bits: header, padding to a byte, LEN, NLEN, bytes. */
    private static long storedBits(int n) {
        return 3 + 7 + 32 + 8L * n;
    }

    private void writeStored(byte[] data, int from, int n, boolean last) {
        putBits(last ? 1 : 0, 3);                        // BFINAL, BTYPE = 0 (stored)
        storedLength(n);
        System.arraycopy(data, from, out, position, n);
        position += n;
    }

    private void writeHeader(int headerCount, int orderCount, boolean last) {
        putBits((last ? 1 : 0) | 2 << 1, 3);            // BFINAL, BTYPE = 2 (dynamic codes)
        putBits(LITERALS - 257, 5);                      // HLIT
        putBits(0, 5);                                   // HDIST: one distance code, of length 0 (none used)
        putBits(orderCount - 4, 4);                      // HCLEN
        for (int k = 0; k < orderCount; k++) {
            putBits(lengthLengths[LENGTH_ORDER[k]], 3);
        }
        canonicalCodes(lengthLengths, lengthCodes, 19);
        for (int k = 0; k < headerCount; k++) {
            int symbol = header[k] & 0xFF;
            putBits(lengthCodes[symbol] & 0xFFFF, lengthCodes[symbol] >>> 16);
            if (symbol >= 16) {
                putBits(header[k] >>> 8, symbol == 16 ? 2 : symbol == 17 ? 3 : 7);
            }
        }
    }

    /** The literals' codes: the per-byte loop, 32 bits at a time to the output. */
    private void writeLiterals(byte[] data, int from, int n) {
        final int[] table = codes;
        final byte[] target = out;
        long buffer = bits;
        int count = bitCount;
        int p = position;
        final int end = from + n;
        int i = from;
        for (; i + 1 < end; i += 2) {
            // two codes of at most 15 bits each, then at most 32 bits out: count stays below 32 + 30
            final int first = table[data[i] & 0xFF];
            final int second = table[data[i + 1] & 0xFF];
            buffer |= ((long) (first & 0xFFFF) | (long) (second & 0xFFFF) << (first >>> 16)) << count;
            count += (first >>> 16) + (second >>> 16);
            if (count >= 32) {
                target[p] = (byte) buffer;
                target[p + 1] = (byte) (buffer >>> 8);
                target[p + 2] = (byte) (buffer >>> 16);
                target[p + 3] = (byte) (buffer >>> 24);
                p += 4;
                buffer >>>= 32;
                count -= 32;
            }
        }
        bits = buffer;
        bitCount = count;
        position = p;
        if (i < end) {
            final int code = table[data[i] & 0xFF];
            putBits(code & 0xFFFF, code >>> 16);
        }
    }

    /**
     * The literal/length code lengths and the one distance code length (0) as code-length symbols in
     * {@link #header}: runs of zeros as 17 and 18, runs of a repeated length as 16, as zlib's send_tree does.
     *
     * @return how many symbols
     */
    private int runLengths() {
        int total = LITERALS + 1;
        int k = 0;
        int i = 0;
        while (i < total) {
            int value = i < LITERALS ? lengths[i] : 0;
            int run = 1;
            while (i + run < total && (i + run < LITERALS ? lengths[i + run] : 0) == value) {
                run++;
            }
            i += run;
            if (value == 0) {
                while (run >= 11) {
                    int r = Math.min(run, 138);
                    header[k++] = 18 | (r - 11) << 8;
                    run -= r;
                }
                if (run >= 3) {
                    header[k++] = 17 | (run - 3) << 8;
                    run = 0;
                }
            } else {
                header[k++] = value;
                run--;
                while (run >= 3) {
                    int r = Math.min(run, 6);
                    header[k++] = 16 | (r - 3) << 8;
                    run -= r;
                }
            }
            while (run-- > 0) {
                header[k++] = value;
            }
        }
        return k;
    }

    /** Canonical codes (RFC 1951, 3.2.2) of {@code lengths}, bit-reversed, with their lengths above bit 16. */
    private static void canonicalCodes(int[] lengths, int[] codes, int n) {
        int[] perLength = new int[MAX_BITS + 1];
        for (int s = 0; s < n; s++) {
            perLength[lengths[s]]++;
        }
        perLength[0] = 0;
        int[] next = new int[MAX_BITS + 1];
        int code = 0;
        for (int b = 1; b <= MAX_BITS; b++) {
            code = (code + perLength[b - 1]) << 1;
            next[b] = code;
        }
        for (int s = 0; s < n; s++) {
            int length = lengths[s];
            codes[s] = length == 0 ? 0 : Integer.reverse(next[length]++) >>> (32 - length) | length << 16;
        }
    }

    private void storedLength(int n) {
        flushBits();
        out[position++] = (byte) n;
        out[position++] = (byte) (n >>> 8);
        out[position++] = (byte) ~n;
        out[position++] = (byte) (~n >>> 8);
    }

    private void putBits(int value, int count) {
        bits |= (long) value << bitCount;
        bitCount += count;
        while (bitCount >= 8) {
            out[position++] = (byte) bits;
            bits >>>= 8;
            bitCount -= 8;
        }
    }

    /** Writes the bits held, padded with zeros to a whole byte. */
    private void flushBits() {
        while (bitCount > 0) {
            out[position++] = (byte) bits;
            bits >>>= 8;
            bitCount -= 8;
        }
        bits = 0;
        bitCount = 0;
    }
}
