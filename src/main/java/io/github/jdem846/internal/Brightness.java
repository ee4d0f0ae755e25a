package io.github.jdem846.internal;

/**
 * The article's brightness adjustment (eq. 8) and the original jDem846's two tone steps that precede it. Pure
 * functions of numbers; NaN in gives NaN out.
 */
public final class Brightness {

    private Brightness() {
    }

    /**
     * Eq. 8: darkens a colour channel toward 0 for {@code d < 0} ({@code c·(1 + d)}) and lightens it toward 1 for
     * {@code d ≥ 0} ({@code c + (1 − c)·d}). {@code d} is clamped to [−1, 1] and the result to [0, 1], so a channel
     * never leaves its range.
     *
     * @param channel a colour channel in [0, 1]
     * @param d       the (toned) illumination in [−1, 1]
     */
    public static double adjustBrightness(double channel, double d) {
        double t = Clamp.between(d, -1.0, 1.0);
        double c = t < 0 ? channel * (1 + t) : channel + (1 - channel) * t;
        return Clamp.between(c, 0.0, 1.0);
    }

    /**
     * Eq. 8 on each channel of a non-premultiplied ARGB colour (alpha kept), rounding to the nearest 8-bit value as
     * the original did ({@code Math.round(c·255)}). The same value as {@link #adjustBrightness(double, double)} on
     * each channel {@code c/255}, with the clamp and the branch taken once per pixel.
     */
    public static int adjustBrightness(int argb, double d) {
        double t = Clamp.between(d, -1.0, 1.0);
        int a = argb >>> 24;
        int r = (argb >> 16) & 0xFF;
        int g = (argb >> 8) & 0xFF;
        int b = argb & 0xFF;
        if (t < 0) {
            double f = 1 + t;
            r = toByte(UNIT[r] * f);
            g = toByte(UNIT[g] * f);
            b = toByte(UNIT[b] * f);
        } else {
            r = toByte(UNIT[r] + (1 - UNIT[r]) * t);
            g = toByte(UNIT[g] + (1 - UNIT[g]) * t);
            b = toByte(UNIT[b] + (1 - UNIT[b]) * t);
        }
        return (a << 24) | (r << 16) | (g << 8) | b;
    }

    /** {@code UNIT[c] = c / 255.0}, the 8-bit channel values in [0, 1] (a lookup instead of a division). */
    private static final double[] UNIT = new double[256];

    static {
        for (int c = 0; c < 256; c++) {
            UNIT[c] = c / 255.0;
        }
    }

    private static int toByte(double c) {
        return (int) Math.round(Clamp.between(c, 0.0, 1.0) * 255.0);
    }

    /**
     * The original's light/dark intensity step: a positive illumination is multiplied by {@code light}, a negative
     * one by {@code dark} (defaults 0.75 and 1.0: lit slopes brighten less than shaded ones darken).
     */
    public static double intensity(double d, double light, double dark) {
        return d > 0 ? d * light : d < 0 ? d * dark : d;
    }

    /**
     * The spot exponent, sign-preserving: sign(d)·|d|^{@code exponent}. The original's {@code pow(d, spot)} turned
     * shade into light for even exponents (pow(−0.8, 2) = +0.64); here −0.8 stays dark (−0.64).
     */
    public static double spot(double d, double exponent) {
        if (exponent == 1.0 || d == 0 || Double.isNaN(d)) {
            return d;
        }
        return Math.copySign(Math.pow(Math.abs(d), exponent), d);
    }
}
