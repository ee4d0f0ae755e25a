package io.github.jdem846.render;

/**
 * Combines a tint colour, the illumination (eq. 7's dot product) and the cast-shadow fraction into one ARGB pixel:
 * the original's era-B order — dot, minus 2 × shadow intensity × shadowed fraction, clamped at −1, scaled by the
 * relative light or dark intensity, spot exponent (sign-preserving) — then eq. 8 on each channel.
 */
public final class Compositor {

    private final Composition composition;

    public Compositor(Composition composition) {
        this.composition = composition;
    }

    /**
     * The brightness d in [−1, 1] handed to eq. 8.
     *
     * @param dot            cosine of incidence in [−1, 1] (0 when illumination is disabled)
     * @param shadowFraction 0 = lit … 1 = fully in cast shadow
     * @param fade           extra darkening in [0, 2], e.g. twilight (0 in daylight)
     */
    public double brightness(double dot, double shadowFraction, double fade) {
        double d = dot - fade - 2 * composition.shadowIntensity() * shadowFraction;
        d = Math.max(-1, Math.min(1, d));
        d *= d > 0 ? composition.relativeLightIntensity() : composition.relativeDarkIntensity();
        if (composition.spotExponent() != 1 && d != 0) {
            d = Math.copySign(Math.pow(Math.abs(d), composition.spotExponent()), d);
        }
        return d;
    }

    /**
     * Eq. 8 on one channel in [0, 1]: {@code c·(1 + d)} when d &lt; 0, {@code c + (1 − c)·d} otherwise.
     */
    public static double adjustBrightness(double channel, double d) {
        return d < 0 ? channel * (1 + d) : channel + (1 - channel) * d;
    }

    /**
     * The pixel for one cell. A transparent tint (no-data) or a NaN dot stays fully transparent.
     *
     * @param tintArgb non-premultiplied ARGB of the cell's tint
     */
    public int compose(int tintArgb, double dot, double shadowFraction, double fade) {
        int alpha = tintArgb >>> 24;
        if (alpha == 0 || Double.isNaN(dot)) {
            return 0;
        }
        double d = brightness(dot, shadowFraction, fade);
        int r = channel((tintArgb >> 16) & 0xff, d);
        int g = channel((tintArgb >> 8) & 0xff, d);
        int b = channel(tintArgb & 0xff, d);
        return (alpha << 24) | (r << 16) | (g << 8) | b;
    }

    private static int channel(int value, double d) {
        long v = Math.round(adjustBrightness(value / 255.0, d) * 255.0);
        return (int) Math.max(0, Math.min(255, v));
    }
}
