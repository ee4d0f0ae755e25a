package io.github.jdem846.raster;

/**
 * The no-data rule: a declared value, compared as float32 so that header text such as {@code -3.40282e+38},
 * {@code -3.4028235e38} or {@code -32768.0} matches the stored cells, and NaN, which is always no-data.
 */
public final class NoData {

    private NoData() {
    }

    /** True when {@code cell} is no-data under the declared value ({@code NaN} = none declared). */
    public static boolean isNoData(float cell, double declared) {
        return Float.isNaN(cell) || (!Double.isNaN(declared) && cell == toFloat32(declared));
    }

    /**
     * The declared value as the float32 that a file storing it would hold. Values just beyond the float range
     * (a rounded {@code -3.4028235e38} printed with more digits) map to ±Float.MAX_VALUE rather than infinity.
     */
    public static float toFloat32(double declared) {
        if (Double.isNaN(declared)) {
            return Float.NaN;
        }
        float f = (float) declared;
        if (Float.isInfinite(f) && !Double.isInfinite(declared) && Math.abs(declared) < 3.5e38) {
            return Math.copySign(Float.MAX_VALUE, (float) declared);
        }
        return f;
    }

    /** Replaces every no-data cell of {@code values} with NaN, in place. */
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
