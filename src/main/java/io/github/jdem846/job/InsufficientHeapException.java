package io.github.jdem846.job;

import java.util.Locale;

/**
 * A picture that is allowed but cannot be made in this JVM's heap: refused before anything is read or allocated.
 * In memory ({@link ReliefJob#run}): a grid and picture larger than the heap or than one Java array, which written
 * to a file ({@link ReliefJob#runAndWrite}) are rendered in tiles instead; in tiles: a smallest tile that, with the
 * halo its stages read around it, needs more than the memory budget. The message gives what is needed and what the
 * heap or the budget holds.
 */
public final class InsufficientHeapException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** Whether the message already says what would make the picture fit. */
    private final boolean advises;

    private InsufficientHeapException(String message) {
        this(message, false);
    }

    private InsufficientHeapException(String message, boolean advises) {
        super(message);
        this.advises = advises;
    }

    /** {@return true when the message already says what would make the picture fit} */
    public boolean givesAdvice() {
        return advises;
    }

    /**
     * Throws unless {@code cells} grid cells (4 bytes each) and {@code width × height} pixels of {@code
     * bytesPerPixel} fit in {@code maxHeap} bytes.
     */
    static void requireFits(long cells, int width, int height, long bytesPerPixel, long maxHeap) {
        if (cells > PicturePlan.MAX_ARRAY || (long) width * height > PicturePlan.MAX_ARRAY) {
            throw new InsufficientHeapException("a picture of " + width + "×" + height + " pixels from " + cells
                    + " cells has more than one Java array holds (" + PicturePlan.MAX_ARRAY + "); written to a file,"
                    + " it is rendered in tiles");
        }
        double need = (double) cells * Float.BYTES + (double) width * height * bytesPerPixel;
        if (need > maxHeap) {
            throw new InsufficientHeapException("a picture of " + width + "×" + height + " pixels needs at least "
                    + human(need) + " of Java heap (the grid at that resolution and the picture), but the heap "
                    + "holds at most " + human(maxHeap) + "; written to a file, it is rendered in tiles");
        }
    }

    /**
     * The refusal of a picture too large for memory whose smallest tile, with the halo its stages read around it,
     * needs more than the memory budget.
     *
     * @param smallest the smallest tiles, or null when one of them would not even fit in one Java array
     * @param budget   the memory budget in bytes
     * @param shadows  true when the halo includes the cast shadows' reach
     */
    static InsufficientHeapException tileTooLarge(TileLayout smallest, long budget, boolean shadows) {
        String reach = shadows ? ": the cast shadows' reach toward the sun, the file's relief / tan(sun elevation)" : "";
        String advice = "give a larger budget (--memory; Java's heap, -Xmx, bounds it)"
                + (shadows ? ", a higher sun" : "") + " or make a smaller picture (--scale, --width)";
        if (smallest == null) {
            return new InsufficientHeapException("even the smallest tile and the halo read around it" + reach
                    + " are more than one Java array can hold: " + advice, true);
        }
        return new InsufficientHeapException("even the smallest tile, " + smallest.tileWidth() + "×"
                + smallest.tileHeight() + " pixels, with the halo read around it (" + smallest.west() + ", "
                + smallest.north() + ", " + smallest.east() + " and " + smallest.south()
                + " cells west, north, east and south" + reach + ") needs " + human(smallest.bytes())
                + ", more than the memory budget of " + human(budget) + ": " + advice, true);
    }

    /** Bytes in binary units, e.g. "6.4 GiB", "12 MiB", "300 KiB". */
    static String human(double bytes) {
        double mib = bytes / 1048576.0;
        if (mib < 1) {
            return String.format(Locale.ROOT, "%.0f KiB", Math.ceil(bytes / 1024));
        }
        return mib < 1024 ? String.format(Locale.ROOT, "%.0f MiB", mib)
                : String.format(Locale.ROOT, "%.1f GiB", mib / 1024);
    }
}
