package io.github.jdem846.render;

import io.github.jdem846.internal.Brightness;
import io.github.jdem846.internal.Clamp;
import io.github.jdem846.shade.HillshadeOptions;

/**
 * Combines a tint colour, the illumination (eq. 7's dot product), the cast-shadow fraction and the sky-view factor
 * into one ARGB pixel: the brightness of the scene's {@link LightModel} (the original's era-B order for {@link
 * LightModel#JDEM846}: the dot product, minus 2 × shadow intensity × shadowed fraction and any twilight fade),
 * clamped to [−1, 1], then the jDem846 tone (relative light/dark intensity, sign-preserving spot exponent, {@link
 * HillshadeOptions#tone}), then eq. 8 on each channel ({@link Brightness#adjustBrightness(int, double)}). Another
 * {@link Blend} lays the brightness on the tint by its {@link BlendMode} and mixes the result with the bare tint by
 * its opacity.
 */
final class Compositor {

    /** The original's {@code shadowIntensity} default. */
    public static final double DEFAULT_SHADOW_INTENSITY = 0.4;

    private final HillshadeOptions tone;
    private final double shadowIntensity;
    private final LightModel model;
    private final double ambient;
    private final Blend blend;

    /**
     * The original's composition ({@link LightModel#JDEM846}, no sky light).
     *
     * @param tone            supplies the light/dark intensities and spot exponent
     * @param shadowIntensity a cell fully in cast shadow loses 2 × this much brightness; 0 to 1
     */
    public Compositor(HillshadeOptions tone, double shadowIntensity) {
        this(tone, shadowIntensity, LightModel.JDEM846, 0);
    }

    /**
     * @param tone            supplies the light/dark intensities and spot exponent
     * @param shadowIntensity {@link LightModel#JDEM846}: a cell fully in cast shadow loses 2 × this much brightness;
     *                        0 to 1
     * @param model           how sun, shadow and sky combine
     * @param ambient         the weight W of the sky light, 0 to 1 (0: the sky-view factor is not used)
     */
    public Compositor(HillshadeOptions tone, double shadowIntensity, LightModel model, double ambient) {
        this(tone, shadowIntensity, model, ambient, Blend.DEFAULT);
    }

    /**
     * @param tone            supplies the light/dark intensities and spot exponent
     * @param shadowIntensity {@link LightModel#JDEM846}: a cell fully in cast shadow loses 2 × this much brightness;
     *                        0 to 1
     * @param model           how sun, shadow and sky combine
     * @param ambient         the weight W of the sky light, 0 to 1 (0: the sky-view factor is not used)
     * @param blend           how the brightness is laid on the tint
     */
    public Compositor(HillshadeOptions tone, double shadowIntensity, LightModel model, double ambient, Blend blend) {
        if (!(shadowIntensity >= 0 && shadowIntensity <= 1)) {
            throw new IllegalArgumentException("shadow intensity must be between 0 and 1 (default 0.4), got "
                    + shadowIntensity);
        }
        if (!(ambient >= 0 && ambient <= 1)) {
            throw new IllegalArgumentException("ambient weight must be between 0 and 1, got " + ambient);
        }
        this.tone = tone;
        this.shadowIntensity = shadowIntensity;
        this.model = java.util.Objects.requireNonNull(model, "model");
        this.ambient = ambient;
        this.blend = java.util.Objects.requireNonNull(blend, "blend");
    }

    /**
     * The toned brightness handed to eq. 8, without sky light.
     *
     * @param dot            cosine of incidence in [−1, 1] (0 when illumination is disabled)
     * @param shadowFraction 0 = lit … 1 = fully in cast shadow
     * @param fade           extra darkening in [0, 2], e.g. the twilight fade (0 in daylight)
     * @return the toned brightness in [−1, 1]
     */
    public double brightness(double dot, double shadowFraction, double fade) {
        return brightness(dot, shadowFraction, 1, fade);
    }

    /**
     * The toned brightness handed to eq. 8 ({@link LightModel}).
     *
     * @param dot            cosine of incidence in [−1, 1]
     * @param shadowFraction 0 = lit … 1 = fully in cast shadow
     * @param skyView        the sky-view factor in [0, 1] (read only when the ambient weight is above 0)
     * @param fade           extra darkening in [0, 2], e.g. the twilight fade (0 in daylight)
     * @return the toned brightness in [−1, 1]
     */
    public double brightness(double dot, double shadowFraction, double skyView, double fade) {
        return tone.tone(light(dot, shadowFraction, skyView, fade));
    }

    /** The light model's brightness before the tone, clamped to [−1, 1] ({@link LightModel}). */
    double light(double dot, double shadowFraction, double skyView, double fade) {
        double d;
        if (model == LightModel.JDEM846) {
            d = dot - fade - 2 * shadowIntensity * shadowFraction;
            if (ambient > 0) {
                d = (1 - ambient) * d + ambient * (2 * skyView - 1);
            }
        } else {
            double direct = (dot > 0 ? dot : 0) * (1 - shadowFraction);
            double light = ambient > 0 ? direct + ambient * skyView : direct;
            d = 2 * light - 1 - fade;
        }
        return Clamp.between(d, -1.0, 1.0);
    }

    /**
     * The pixel for one cell, without sky light. A transparent tint (no-data) or a NaN dot stays fully transparent.
     *
     * @param tintArgb non-premultiplied ARGB of the cell's tint
     * @return the ARGB pixel
     */
    public int compose(int tintArgb, double dot, double shadowFraction, double fade) {
        return compose(tintArgb, dot, shadowFraction, 1, fade);
    }

    /**
     * The pixel for one cell. A transparent tint (no-data) or a NaN dot stays fully transparent (0).
     *
     * @param tintArgb non-premultiplied ARGB of the cell's tint
     * @param skyView  the sky-view factor (read only when the ambient weight is above 0)
     * @return the ARGB pixel
     */
    public int compose(int tintArgb, double dot, double shadowFraction, double skyView, double fade) {
        if ((tintArgb >>> 24) == 0 || Double.isNaN(dot)) {
            return 0;
        }
        if (blend.isDefault()) {
            return Brightness.adjustBrightness(tintArgb, brightness(dot, shadowFraction, skyView, fade));
        }
        BlendMode mode = blend.mode();
        double layer = mode.layer(light(dot, shadowFraction, skyView, fade), tone);
        double o = blend.opacity();
        return (tintArgb & 0xFF000000) | channel(mode, (tintArgb >> 16) & 0xFF, layer, o) << 16
                | channel(mode, (tintArgb >> 8) & 0xFF, layer, o) << 8 | channel(mode, tintArgb & 0xFF, layer, o);
    }

    /** One 8-bit channel: (1 − o)·c + o·blend(c), rounded as the original did ({@code Math.round(c·255)}). */
    private static int channel(BlendMode mode, int value, double layer, double opacity) {
        double c = value / 255.0;
        double mixed = (1 - opacity) * c + opacity * mode.blend(c, layer);
        return (int) Math.round(Clamp.between(mixed, 0.0, 1.0) * 255.0);
    }
}
