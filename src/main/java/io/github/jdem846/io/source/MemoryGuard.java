package io.github.jdem846.io.source;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.ReadRequest;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Refuses, before allocating, a grid or a read buffer whose float32 array would not fit in one Java array or in
 * the Java heap. Sizes are computed without overflow (in {@code long} where they fit, saturating or in
 * {@code double} where they may not), so messages give true figures.
 */
public final class MemoryGuard {

    /** Largest Java array length the JVM allows in practice. */
    public static final long MAX_ARRAY = Integer.MAX_VALUE - 8L;

    private MemoryGuard() {
    }

    /**
     * Checks that {@code width × height} float32 cells, plus {@code workBytes} of working buffers, fit in the heap
     * now available.
     *
     * @throws DemFormatException saying how much memory the grid needs and how much the heap allows
     */
    public static void requireFits(Path file, int width, int height, long workBytes, String advice)
            throws DemFormatException {
        requireFits(file, width, height, workBytes, Long.MAX_VALUE, advice);
    }

    /**
     * Like {@link #requireFits(Path, int, int, long, String)}, within at most {@code limit} bytes
     * ({@link ReadRequest#memoryLimit()}) even where the heap has more.
     */
    public static void requireFits(Path file, int width, int height, long workBytes, long limit, String advice)
            throws DemFormatException {
        long cells = (long) width * height;
        long bytes = saturatedMultiply(cells, Float.BYTES);
        long need = saturatedAdd(bytes, workBytes);
        if (limit < Long.MAX_VALUE && cells <= MAX_ARRAY && need > limit) {
            throw new DemFormatException(file, needs(width, height, bytes, workBytes)
                    + ", more than the read's limit of " + human(limit));
        }
        long max = Runtime.getRuntime().maxMemory();
        long available = cells > MAX_ARRAY ? available() : available(need);
        if (cells > MAX_ARRAY) {
            throw new DemFormatException(file, "a " + width + " × " + height + " grid has " + cells
                    + " cells, more than one Java array can hold (" + MAX_ARRAY + "); it would need "
                    + human(cells * (double) Float.BYTES) + " (" + advice + ")");
        }
        if (need > available) {
            throw new DemFormatException(file, needs(width, height, bytes, workBytes)
                    + ", but the Java heap allows at most " + human(max) + " (Runtime.maxMemory()), "
                    + human(Math.max(0, available)) + " of it free; " + advice);
        }
    }

    /**
     * Checks that a read buffer of {@code width × rows} float32 cells (a band of whole strips or tiles) fits in
     * one Java array and in the heap now available.
     *
     * @throws DemFormatException saying how large the buffer is and why it is needed
     */
    public static void requireBandFits(Path file, int width, long rows, String advice) throws DemFormatException {
        double cells = (double) width * rows;
        if (cells > MAX_ARRAY) {
            throw new DemFormatException(file, band(width, rows) + ", more than one Java array can hold ("
                    + MAX_ARRAY + " cells); " + advice);
        }
        long available = available((long) cells * Float.BYTES);
        if ((long) cells * Float.BYTES > available) {
            throw new DemFormatException(file, band(width, rows) + ", but the Java heap has "
                    + human(Math.max(0, available)) + " free of at most " + human(Runtime.getRuntime().maxMemory())
                    + "; " + advice);
        }
    }

    /**
     * What a band buffer takes, for a refusal only: formatting it loads {@link java.util.Formatter} and locale data,
     * tens of milliseconds on the first read of a JVM.
     */
    private static String band(int width, long rows) {
        return "reading it takes " + width + " × " + rows + " cells at a time (whole strips or tiles, or the rows"
                + " of a decimation block), " + human((double) width * rows * Float.BYTES) + " as float32";
    }

    /**
     * What a read needs, e.g. "a 100 × 100 grid needs 39.1 KiB as float32" or, when the working buffers are the
     * larger part (a strip or tile decoded whole), "… and 6.0 GiB to decode the strips or tiles it covers".
     */
    private static String needs(int width, int height, long bytes, long workBytes) {
        String grid = width == 0 && height == 0 ? "reading the file" : "a " + width + " × " + height + " grid";
        String needs = grid + " needs " + (bytes > 0 ? human(bytes) + " as float32" : "");
        if (workBytes > bytes) {
            needs += (bytes > 0 ? " and " : "") + human(workBytes) + " to decode the strips or tiles it covers"
                    + " (each is decoded whole)";
        }
        return needs;
    }

    /** True when {@code width × height} float32 cells plus {@code workBytes} fit in the heap now available. */
    public static boolean fits(int width, int height, long workBytes) {
        long cells = (long) width * height;
        return cells <= MAX_ARRAY && saturatedAdd(cells * Float.BYTES, workBytes)
                <= available(saturatedAdd(cells * Float.BYTES, workBytes));
    }

    /** {@code a × b} for non-negative factors, {@link Long#MAX_VALUE} when it overflows. */
    public static long saturatedMultiply(long a, long b) {
        long hi = Math.multiplyHigh(a, b);
        long lo = a * b;
        return hi != 0 || lo < 0 ? Long.MAX_VALUE : lo;
    }

    /** {@code a + b} for non-negative terms, {@link Long#MAX_VALUE} when it overflows. */
    public static long saturatedAdd(long a, long b) {
        long s = a + b;
        return s < 0 ? Long.MAX_VALUE : s;
    }

    /**
     * Heap bytes not in use, for an allocation of {@code need} bytes: when less is free now, after a garbage
     * collection, since the arrays of earlier reads that nothing holds any more (the pieces of a picture rendered
     * tile by tile) count as allocated until one.
     */
    private static long available(long need) {
        long a = available();
        if (need > a && need <= Runtime.getRuntime().maxMemory()) {
            System.gc();
            a = available();
        }
        return a;
    }

    /** Heap bytes not in use now (the maximum heap minus what is allocated and not free). */
    private static long available() {
        Runtime rt = Runtime.getRuntime();
        return rt.maxMemory() - (rt.totalMemory() - rt.freeMemory());
    }

    /** Bytes in binary units, e.g. "37.3 GiB"; {@link Long#MAX_VALUE} (a saturated size) is "more than 8 EiB". */
    public static String human(long bytes) {
        if (bytes == Long.MAX_VALUE) {
            return "more than 8 EiB";
        }
        return bytes < 1024 ? bytes + " bytes" : human((double) bytes);
    }

    /** Bytes in binary units for sizes that may exceed a {@code long}, e.g. "16.0 EiB". */
    public static String human(double bytes) {
        String[] units = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB"};
        double v = bytes;
        int u = 0;
        while (v >= 1024 && u < units.length - 1) {
            v /= 1024;
            u++;
        }
        return u == 0 ? (long) bytes + " bytes" : String.format(Locale.ROOT, "%.1f %s", v, units[u]);
    }
}
