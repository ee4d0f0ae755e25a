package io.github.jdem846.output;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * PNG filtering of rows (PNG spec 9): each row takes the filter (none, sub, up, average, Paeth) whose output has the
 * smallest sum of absolute values, plus the filter's type number, the first on ties; none sums the unsigned samples,
 * the others their signed bytes (PngEncoder's rule, so that its files and ours compress alike).
 *
 * <p>Eight bytes at a time in a {@code long} (SIMD within a register): byte-wise differences and absolute values,
 * summed in 16-bit lanes, and the Paeth predictor without a branch on 16-bit lanes, four bytes at once
 * ({@link #paeth4}). The five sums are taken in one pass over the row that keeps the Paeth output (the filter most
 * rows of shading take); only the chosen filter is then written. The choice and every output byte are those of the
 * one-byte-at-a-time definition, which the tests check; Java 17's compiler vectorises none of these loops itself.
 */
final class PngRowFilter {

    private static final VarHandle LONGS = MethodHandles.byteArrayViewVarHandle(long[].class,
            ByteOrder.LITTLE_ENDIAN);
    /** The top bit, the low bit of every byte. */
    private static final long HIGH = 0x8080808080808080L;
    private static final long LOW = 0x0101010101010101L;
    /** The low byte of every 16-bit lane; the low bit of every 16-bit lane. */
    private static final long EVEN = 0x00FF00FF00FF00FFL;
    private static final long LOW16 = 0x0001000100010001L;
    /**
     * Words (8 bytes) summed in 16-bit lanes before the lanes are added up: at most 2 × 255 per word and lane, so
     * 64 words stay below 2^16.
     */
    private static final int WORDS_PER_SUM = 64;

    private final int bpp;
    private byte[] prev;
    private byte[] cur;
    /** The current row Paeth-filtered, which {@link #choose} keeps. */
    private final byte[] paeth;
    /** The five sums of the row being chosen for. */
    private final long[] sums = new long[5];

    /**
     * @param sampleBytes   bytes of a row's samples (without the filter-type byte)
     * @param bytesPerPixel bytes of one pixel: the distance to the byte on the left that sub, average and Paeth use
     */
    PngRowFilter(int sampleBytes, int bytesPerPixel) {
        int n = 1 + sampleBytes;
        bpp = bytesPerPixel;
        prev = new byte[n];
        cur = new byte[n];
        paeth = new byte[n];
    }

    /** Filters the rows of {@code segment} into {@code out}, one after another, after the row above it. */
    void filter(RowChunks.Chunk segment, byte[] out) {
        segment.rowAbove(prev, 1);
        int n = cur.length;
        for (int r = 0; r < segment.rows(); r++) {
            segment.row(r, cur, 1);
            filterRow(cur, prev, out, r * n);
            byte[] t = prev;
            prev = cur;
            cur = t;
        }
    }

    /**
     * Filters one row: {@code row} and the row {@code above} hold their samples from index 1 (index 0 is not read);
     * writes the filter type and the filtered samples to {@code out} at {@code off}.
     *
     * @return the filter type, 0..4
     */
    int filterRow(byte[] row, byte[] above, byte[] out, int off) {
        int type = choose(row, above);
        apply(type, row, above, out, off);
        return type;
    }

    /** The filter type for {@code c} under {@code p}, the Paeth output kept in {@link #paeth}. */
    private int choose(byte[] c, byte[] p) {
        byte[] t = paeth;
        long sumNone = 0;
        long sumSub = 1;
        long sumUp = 2;
        long sumAvg = 3;
        long sumPaeth = 4;
        int n = c.length;
        int head = Math.min(n, 1 + bpp);
        for (int i = 1; i < head; i++) {              // no pixel to the left: a = d = 0
            int x = c[i] & 0xFF;
            int b = p[i] & 0xFF;
            sumNone += x;
            sumSub += Math.abs((byte) x);
            sumUp += Math.abs((byte) (x - b));
            sumAvg += Math.abs((byte) (x - (b >> 1)));
            t[i] = (byte) (x - b);                      // Paeth of (0, b, 0) is b
            sumPaeth += Math.abs(t[i]);
        }
        int i = head;
        long[] s = sums;
        s[0] = sumNone;
        s[1] = sumSub;
        s[2] = sumUp;
        s[3] = sumAvg;
        s[4] = sumPaeth;
        while (i <= n - 8) {
            int end = n - 8 - i <= 8 * (WORDS_PER_SUM - 1) ? n - 8 : i + 8 * (WORDS_PER_SUM - 1); // no overflow
            words(c, p, t, bpp, i, end, s);
            i = end + 8 - (end - i) % 8;
        }
        sumNone = s[0];
        sumSub = s[1];
        sumUp = s[2];
        sumAvg = s[3];
        sumPaeth = s[4];
        for (; i < n; i++) {
            int x = c[i] & 0xFF;
            int b = p[i] & 0xFF;
            int a = c[i - bpp] & 0xFF;
            int d = p[i - bpp] & 0xFF;
            sumNone += x;
            sumSub += Math.abs((byte) (x - a));
            sumUp += Math.abs((byte) (x - b));
            sumAvg += Math.abs((byte) (x - ((a + b) >> 1)));
            byte e = (byte) (x - paeth(a, b, d));
            t[i] = e;
            sumPaeth += Math.abs(e);
        }
        int best = 0;
        long min = sumNone;
        if (min > sumSub) {
            best = 1;
            min = sumSub;
        }
        if (min > sumUp) {
            best = 2;
            min = sumUp;
        }
        if (min > sumAvg) {
            best = 3;
            min = sumAvg;
        }
        if (min > sumPaeth) {
            best = 4;
        }
        return best;
    }

    /**
     * The words at {@code from, from + 8, …} up to {@code end} (at most {@link #WORDS_PER_SUM}): adds the five
     * filters' sums to {@code sums} and writes the Paeth output to {@code t}. A method of its own, called several
     * times per row, so that the just-in-time compiler takes it up after a few rows of a one-shot command.
     */
    private static void words(byte[] c, byte[] p, byte[] t, int bpp, int from, int end, long[] sums) {
        long none = 0;
        long sub = 0;
        long up = 0;
        long avg = 0;
        long pae = 0;
        for (int i = from; i <= end; i += 8) {
            long x = (long) LONGS.get(c, i);
            long a = (long) LONGS.get(c, i - bpp);
            long b = (long) LONGS.get(p, i);
            long d = (long) LONGS.get(p, i - bpp);
            none += pairs(x);
            sub += pairs(abs(minus(x, a)));
            up += pairs(abs(minus(x, b)));
            avg += pairs(abs(minus(x, average(a, b))));
            long e = minus(x, paeth4(a & EVEN, b & EVEN, d & EVEN)
                    | paeth4(a >>> 8 & EVEN, b >>> 8 & EVEN, d >>> 8 & EVEN) << 8);
            LONGS.set(t, i, e);
            pae += pairs(abs(e));
        }
        sums[0] += lanes(none);
        sums[1] += lanes(sub);
        sums[2] += lanes(up);
        sums[3] += lanes(avg);
        sums[4] += lanes(pae);
    }

    /** Writes row {@code c} filtered with {@code type} (its type byte first) to {@code out} at {@code off}. */
    private void apply(int type, byte[] c, byte[] p, byte[] out, int off) {
        int n = c.length;
        out[off] = (byte) type;
        if (type == 0) {
            System.arraycopy(c, 1, out, off + 1, n - 1);
            return;
        }
        if (type == 4) {
            System.arraycopy(paeth, 1, out, off + 1, n - 1);
            return;
        }
        int head = type == 2 ? 1 : Math.min(n, 1 + bpp);
        for (int i = 1; i < head; i++) {              // sub and average with no pixel to the left
            out[off + i] = (byte) (type == 1 ? c[i] : c[i] - ((p[i] & 0xFF) >> 1));
        }
        int i = head;
        for (; i <= n - 8; i += 8) {
            long x = (long) LONGS.get(c, i);
            long y = type == 2 ? (long) LONGS.get(p, i)
                    : type == 1 ? (long) LONGS.get(c, i - bpp)
                    : average((long) LONGS.get(c, i - bpp), (long) LONGS.get(p, i));
            LONGS.set(out, off + i, minus(x, y));
        }
        for (; i < n; i++) {
            int y = type == 2 ? p[i] & 0xFF
                    : type == 1 ? c[i - bpp] & 0xFF
                    : ((c[i - bpp] & 0xFF) + (p[i] & 0xFF)) >> 1;
            out[off + i] = (byte) (c[i] - y);
        }
    }

    /** The Paeth predictor (PNG spec 9.4) of left {@code a}, above {@code b}, upper left {@code d}. */
    static int paeth(int a, int b, int d) {
        int q = a + b - d;
        int pa = Math.abs(q - a);
        int pb = Math.abs(q - b);
        int pc = Math.abs(q - d);
        return pa <= pb && pa <= pc ? a : pb <= pc ? b : d;
    }

    /**
     * {@link #paeth} of four 16-bit lanes at once, each holding a byte (0..255) of left {@code a}, above {@code b},
     * upper left {@code d}: the differences are biased to stay non-negative in their lane (0x100 + b − d,
     * 0x200 + a + b − 2d), their absolute values taken by the bias bit, and the comparisons read from bit 10 of
     * 0x400 + x − y. Checked against {@link #paeth} for all 2^24 inputs by the tests.
     */
    static long paeth4(long a, long b, long d) {
        final long k100 = 0x0100010001000100L;
        final long k200 = 0x0200020002000200L;
        final long k400 = 0x0400040004000400L;
        long dbd = (b | k100) - d;                                  // 0x100 + b − d
        long neg = (dbd >>> 8 & LOW16) ^ LOW16;
        long pa = ((dbd ^ neg * 0xFF) & EVEN) + neg;                // |b − d|
        long dad = (a | k100) - d;
        neg = (dad >>> 8 & LOW16) ^ LOW16;
        long pb = ((dad ^ neg * 0xFF) & EVEN) + neg;                // |a − d|
        long dp = a + b + k200 - (d << 1);                          // 0x200 + a + b − 2d
        neg = (dp >>> 9 & LOW16) ^ LOW16;
        long pc = ((dp ^ neg * 0x1FF) & 0x01FF01FF01FF01FFL) + neg; // |a + b − 2d|
        long takeB = (pc + k400 - pb >>> 10 & LOW16) * 0xFFFF;      // pb <= pc
        long bd = d ^ ((b ^ d) & takeB);
        long minBd = pc ^ ((pb ^ pc) & takeB);
        long takeA = (minBd + k400 - pa >>> 10 & LOW16) * 0xFFFF;   // pa <= pb and pa <= pc
        return bd ^ ((a ^ bd) & takeA);
    }

    /** {@code x − y} in each byte, modulo 256. */
    static long minus(long x, long y) {
        return ((x | HIGH) - (y & ~HIGH)) ^ ((x ^ ~y) & HIGH);
    }

    /** {@code (x + y) >> 1} in each byte, unsigned. */
    static long average(long x, long y) {
        return (x & y) + ((x ^ y) >>> 1 & 0x7F7F7F7F7F7F7F7FL);
    }

    /** The absolute value of each byte read as signed: 0..128. */
    private static long abs(long e) {
        long neg = e >>> 7 & LOW;
        return (e ^ neg * 0xFF) + neg;
    }

    /** Adds the bytes in pairs: four 16-bit lanes. */
    private static long pairs(long v) {
        return (v & EVEN) + (v >>> 8 & EVEN);
    }

    /** The sum of the four 16-bit lanes. */
    private static long lanes(long v) {
        long w = (v & 0x0000FFFF0000FFFFL) + (v >>> 16 & 0x0000FFFF0000FFFFL);
        return (w & 0xFFFFFFFFL) + (w >>> 32);
    }
}
