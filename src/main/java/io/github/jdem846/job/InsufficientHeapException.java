package io.github.jdem846.job;

import java.util.Locale;

/**
 * A picture that is allowed but cannot fit in this JVM's heap: refused before anything is read or allocated. The
 * message gives the picture's size, the least memory it needs and the heap's maximum.
 */
public final class InsufficientHeapException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private InsufficientHeapException(String message) {
        super(message);
    }

    /**
     * Throws unless {@code cells} grid cells (4 bytes each) and {@code width × height} pixels of {@code
     * bytesPerPixel} fit in {@code maxHeap} bytes.
     */
    static void requireFits(long cells, int width, int height, long bytesPerPixel, long maxHeap) {
        double need = (double) cells * Float.BYTES + (double) width * height * bytesPerPixel;
        if (need > maxHeap) {
            throw new InsufficientHeapException("a picture of " + width + "×" + height + " pixels needs at least "
                    + human(need) + " of Java heap (the grid at that resolution and the picture), but the heap "
                    + "holds at most " + human(maxHeap));
        }
    }

    /** Bytes in binary units, e.g. "6.4 GiB". */
    private static String human(double bytes) {
        double mib = bytes / 1048576.0;
        return mib < 1024 ? String.format(Locale.ROOT, "%.0f MiB", mib)
                : String.format(Locale.ROOT, "%.1f GiB", mib / 1024);
    }
}
