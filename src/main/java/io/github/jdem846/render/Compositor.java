package io.github.jdem846.render;

import io.github.jdem846.internal.Brightness;
import io.github.jdem846.internal.Clamp;
import io.github.jdem846.shade.HillshadeOptions;

/**
 * Combines a tint colour, the illumination (eq. 7's dot product) and the cast-shadow fraction into one ARGB pixel,
 * in the original's era-B order: the dot product, minus 2 × shadow intensity × shadowed fraction (and any twilight
 * fade), clamped to [−1, 1], then the jDem846 tone (relative light/dark intensity, sign-preserving spot exponent,
 * {@link HillshadeOptions#tone}), then eq. 8 on each channel ({@link Brightness#adjustBrightness(int, double)}).
 */
final class Compositor {

    /** The original's {@code shadowIntensity} default. */
    public static final double DEFAULT_SHADOW_INTENSITY = 0.4;

    private final HillshadeOptions tone;
    private final double shadowIntensity;

    /**
     * @param tone            supplies the light/dark intensities and spot exponent
     * @param shadowIntensity a cell fully in cast shadow loses 2 × this much brightness; 0 to 1
     */
    public Compositor(HillshadeOptions tone, double shadowIntensity) {
        if (!(shadowIntensity >= 0 && shadowIntensity <= 1)) {
            throw new IllegalArgumentException("shadow intensity must be between 0 and 1 (default 0.4), got "
                    + shadowIntensity);
        }
        this.tone = tone;
        this.shadowIntensity = shadowIntensity;
    }

    /**
     * The toned brightness handed to eq. 8.
     *
     * @param dot            cosine of incidence in [−1, 1] (0 when illumination is disabled)
     * @param shadowFraction 0 = lit … 1 = fully in cast shadow
     * @param fade           extra darkening in [0, 2], e.g. the twilight fade (0 in daylight)
     */
    public double brightness(double dot, double shadowFraction, double fade) {
        double d = dot - fade - 2 * shadowIntensity * shadowFraction;
        return tone.tone(Clamp.between(d, -1.0, 1.0));
    }

    /**
     * The pixel for one cell. A transparent tint (no-data) or a NaN dot stays fully transparent (0).
     *
     * @param tintArgb non-premultiplied ARGB of the cell's tint
     */
    public int compose(int tintArgb, double dot, double shadowFraction, double fade) {
        if ((tintArgb >>> 24) == 0 || Double.isNaN(dot)) {
            return 0;
        }
        return Brightness.adjustBrightness(tintArgb, brightness(dot, shadowFraction, fade));
    }
}
