package io.github.jdem846.tint;

/**
 * The colour lookup shared by every ramp: stops at ascending positions on one axis (an elevation, or the ratio
 * {@code a} of eq. 1), each with a colour, and a {@link ColorSelection}.
 *
 * <p>Rules, chosen to agree with {@code gdaldem color-relief} (GDAL ≥ 3.9.2) wherever gdaldem is well defined:
 * <ul>
 *   <li>at or below the first stop: the first colour; above the last stop: the last colour (never black);</li>
 *   <li>exactly on a stop: that stop's colour; on several stops at the same position (a hard step): the first
 *       one listed, so values just below the step blend into the first colour and values just above it start
 *       from the last;</li>
 *   <li>{@link ColorSelection#EXACT}: anything not exactly on a stop is transparent, including values beyond
 *       the end stops;</li>
 *   <li>NaN: the no-data colour.</li>
 * </ul>
 * Immutable and thread-safe.
 */
final class StopTable {

    private final double[] positions;
    private final int[] colours;
    private final int[] red;
    private final int[] green;
    private final int[] blue;
    private final int[] alpha;
    private final ColorSelection selection;
    private final int noDataArgb;

    /**
     * @param positions  finite stop positions, ascending (equal neighbours allowed), at least one
     * @param colours    the stop colours, same length
     */
    StopTable(double[] positions, int[] colours, ColorSelection selection, int noDataArgb) {
        if (positions.length == 0 || positions.length != colours.length) {
            throw new IllegalArgumentException("need at least one stop and one colour per stop");
        }
        for (int i = 0; i < positions.length; i++) {
            if (!Double.isFinite(positions[i]) || (i > 0 && positions[i] < positions[i - 1])) {
                throw new IllegalArgumentException("stop positions must be finite and ascending");
            }
        }
        this.positions = positions.clone();
        this.colours = colours.clone();
        int n = colours.length;
        red = new int[n];
        green = new int[n];
        blue = new int[n];
        alpha = new int[n];
        for (int i = 0; i < n; i++) {
            red[i] = Argb.red(colours[i]);
            green[i] = Argb.green(colours[i]);
            blue[i] = Argb.blue(colours[i]);
            alpha[i] = Argb.alpha(colours[i]);
        }
        this.selection = selection;
        this.noDataArgb = noDataArgb;
    }

    int size() {
        return positions.length;
    }

    double position(int i) {
        return positions[i];
    }

    int colour(int i) {
        return colours[i];
    }

    /** The colour at position {@code x} (NaN = no-data). */
    int argb(double x) {
        if (x != x) {
            return noDataArgb;
        }
        int n = positions.length;
        int i = firstAtOrAbove(x);
        if (selection == ColorSelection.EXACT) {
            return i < n && positions[i] == x ? colours[i] : Argb.TRANSPARENT;
        }
        if (i == 0) {
            return colours[0];                       // at or below the first stop
        }
        if (i == n) {
            return colours[n - 1];                   // above the last stop
        }
        if (positions[i] == x) {
            return colours[i];                       // on a stop (the first of equal ones)
        }
        double lower = positions[i - 1];             // lower < x < upper
        double upper = positions[i];
        if (selection == ColorSelection.NEAREST) {
            return x - lower < upper - x ? colours[i - 1] : colours[i];
        }
        // eq. 2: where x lies between the bracketing stops, 0 at the lower one, 1 at the upper one.
        double r = (x - lower) / (upper - lower);
        if (!(r >= 0)) {
            r = 0;                                   // only reachable by overflow of upper − lower
        } else if (r > 1) {
            r = 1;
        }
        int k = i - 1;
        return Argb.of(blend(red[k], red[i], r), blend(green[k], green[i], r), blend(blue[k], blue[i], r),
                blend(alpha[k], alpha[i], r));
    }

    /**
     * eq. 3 for one channel: c = c_lower·(1 − r) + c_upper·r, evaluated as c_lower + r·(c_upper − c_lower) (the
     * same value, and the form gdaldem uses), rounded half up.
     */
    private static int blend(int lower, int upper, double r) {
        int c = (int) (lower + r * (upper - lower) + 0.5);
        return c < 0 ? 0 : Math.min(c, 255);
    }

    /** The index of the first stop at or above {@code x}, or {@code size()} when all are below. */
    private int firstAtOrAbove(double x) {
        int lo = 0;
        int hi = positions.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (positions[mid] < x) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }
}
