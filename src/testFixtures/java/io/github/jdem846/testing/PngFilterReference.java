package io.github.jdem846.testing;

/**
 * PNG row filtering written one byte at a time, straight from the definitions (PNG spec 9) and PngEncoder's rule
 * for choosing a row's filter: the smallest sum of absolute values plus the filter's type number, the first on ties,
 * none summing the unsigned samples and the others their signed bytes. The reference for the encoder's word-wise
 * filter in the tests, and its baseline in the benchmarks.
 */
public final class PngFilterReference {

    private final int bpp;
    private final byte[] paeth;

    /**
     * @param sampleBytes   bytes of a row's samples (without the filter-type byte)
     * @param bytesPerPixel distance to the byte on the left
     */
    public PngFilterReference(int sampleBytes, int bytesPerPixel) {
        this.bpp = bytesPerPixel;
        this.paeth = new byte[1 + sampleBytes];
    }

    /**
     * Filters {@code row} under {@code above} (both with their samples from index 1) into {@code out} at
     * {@code off}: the filter type, then the filtered samples.
     *
     * @return the filter type, 0..4
     */
    public int filterRow(byte[] row, byte[] above, byte[] out, int off) {
        int type = choose(row, above);
        apply(type, row, above, out, off);
        return type;
    }

    /**
     * The five filters' sums for {@code row} under {@code above}: absolute values plus the type number, the rule's
     * scores (the Paeth output is kept for {@link #filterRow}).
     */
    public long[] sums(byte[] c, byte[] p) {
        long[] sums = {0, 1, 2, 3, 4};
        for (int i = 1; i < c.length; i++) {
            int x = c[i] & 0xFF;
            int a = i > bpp ? c[i - bpp] & 0xFF : 0;
            int b = p[i] & 0xFF;
            int d = i > bpp ? p[i - bpp] & 0xFF : 0;
            sums[0] += x;
            sums[1] += Math.abs((byte) (x - a));
            sums[2] += Math.abs((byte) (x - b));
            sums[3] += Math.abs((byte) (x - ((a + b) >> 1)));
            paeth[i] = (byte) (x - paeth(a, b, d));
            sums[4] += Math.abs(paeth[i]);
        }
        return sums;
    }

    private int choose(byte[] c, byte[] p) {
        long[] sums = sums(c, p);
        int best = 0;
        for (int type = 1; type < 5; type++) {
            if (sums[type] < sums[best]) {
                best = type;
            }
        }
        return best;
    }

    private void apply(int type, byte[] c, byte[] p, byte[] out, int off) {
        out[off] = (byte) type;
        for (int i = 1; i < c.length; i++) {
            int x = c[i] & 0xFF;
            int a = i > bpp ? c[i - bpp] & 0xFF : 0;
            int b = p[i] & 0xFF;
            int predicted = switch (type) {
                case 0 -> 0;
                case 1 -> a;
                case 2 -> b;
                case 3 -> (a + b) >> 1;
                default -> x - paeth[i];
            };
            out[off + i] = (byte) (x - predicted);
        }
    }

    /** The Paeth predictor of left {@code a}, above {@code b}, upper left {@code d}, as the PNG spec writes it. */
    public static int paeth(int a, int b, int d) {
        int p = a + b - d;
        int pa = Math.abs(p - a);
        int pb = Math.abs(p - b);
        int pc = Math.abs(p - d);
        if (pa <= pb && pa <= pc) {
            return a;
        }
        return pb <= pc ? b : d;
    }
}
