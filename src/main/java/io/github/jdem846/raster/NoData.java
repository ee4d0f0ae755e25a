package io.github.jdem846.raster;

/**
 * The no-data rule: a declared value, compared as float32 so that header text such as {@code -3.40282e+38},
 * {@code -3.4028235e38} or {@code -32768.0} matches the stored cells, and NaN, which is always no-data.
 */
public final class NoData {

    private NoData() {
    }

    /**
     * True when {@code cell} is no-data under the declared value ({@code NaN} = none declared).
     *
     * @param cell the stored value
     * @param declared the declared no-data value, or NaN when none is declared
     * @return whether the cell is NaN or equals the declared value as float32
     */
    public static boolean isNoData(float cell, double declared) {
        return Float.isNaN(cell) || (!Double.isNaN(declared) && cell == toFloat32(declared));
    }

    /** Relative distance from ±Float.MAX_VALUE within which a declared value means ±Float.MAX_VALUE. */
    private static final double FLOAT_MAX_SNAP = 1e-5;

    /**
     * The declared value as the float32 that a file storing it would hold. Values near the end of the float range
     * mean ±{@code Float.MAX_VALUE}, the usual no-data of float rasters, however the header rounded it: printed
     * with more digits ({@code -3.4028235e38}, which overflows float32) or fewer ({@code -3.40282e+38}, as
     * {@code printf %g} writes it, which would otherwise be a different float32).
     *
     * @param declared the declared no-data value, or NaN
     * @return the float32 a cell holding that value has, NaN for NaN
     */
    public static float toFloat32(double declared) {
        if (Double.isNaN(declared)) {
            return Float.NaN;
        }
        if (!Double.isInfinite(declared)
                && Math.abs(Math.abs(declared) - Float.MAX_VALUE) <= FLOAT_MAX_SNAP * Float.MAX_VALUE) {
            return (float) Math.copySign(Float.MAX_VALUE, declared);
        }
        return (float) declared;
    }

    /**
     * Replaces every no-data cell of {@code values} with NaN, in place.
     *
     * @param values the cells, changed in place
     * @param declared the declared no-data value, or NaN when none is declared (then only NaN cells are no-data and
     *     nothing changes)
     */
    public static void normalize(float[] values, double declared) {
        if (Double.isNaN(declared)) {
            return;
        }
        float nd = toFloat32(declared);
        for (int i = 0; i < values.length; i++) {
            if (values[i] == nd) {
                values[i] = Float.NaN;
            }
        }
    }
}
