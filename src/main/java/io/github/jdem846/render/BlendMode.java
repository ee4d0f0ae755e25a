package io.github.jdem846.render;

import io.github.jdem846.internal.Brightness;
import io.github.jdem846.shade.HillshadeOptions;

/**
 * How the light of a cell is laid on its tint ({@link Compositor}). Each mode first turns the light model's
 * brightness d in [−1, 1] (the dot product, less any cast shadow and fade, with any sky light; {@link LightModel})
 * into one value per pixel, the <em>layer</em> ({@link #layer}), then combines it with each tint channel c in
 * [0, 1] ({@link #blend}).
 *
 * <p>The original jDem846's three {@code hillShadeType}s (era A) apply the article's eq. 8 to the tint:
 * <ul>
 *   <li>{@link #JDEM846} (its COMBINED, the default): the jDem846 tone t of d (light/dark intensity, spot
 *       exponent), then eq. 8: c·(1 + t) for t &lt; 0, c + (1 − c)·t otherwise;</li>
 *   <li>{@link #JDEM846_LIGHTEN}: eq. 8 with e = (1 + d′)/2 ≥ 0, d′ the spot exponent of d: shade only lightens,
 *       the tint is kept where d = −1 and sunlit slopes go toward white;</li>
 *   <li>{@link #JDEM846_DARKEN}: eq. 8 with e = (d′ − 1)/2 ≤ 0: shade only darkens, the tint is kept where d = 1.</li>
 * </ul>
 * The original's LIGHTEN was e = 1 − (d′ + 1)/2 and its DARKEN e = −|(d′ + 1)/2|: both turned the relief inside out
 * (slopes facing away from the light lightest, or sunlit slopes black); here d′ enters with its sign, so the light
 * comes from where the sun is. Neither uses the light/dark intensities (the original applied them to COMBINED only).
 *
 * <p>The blend modes of image editors, QGIS and the W3C <em>Compositing and Blending Level 1</em> recommendation lay a
 * gray hillshade g (the source) over the tint c (the backdrop). g is the gray of the {@code hillshade} command's
 * jdem846 product before rounding, g = (1 + 127·(1 + t))/255 ({@link #gray}), so a blend of a render equals the
 * same blend of the {@code tint} and {@code hillshade} pictures:
 * <ul>
 *   <li>{@link #MULTIPLY}: c·g (white is neutral);</li>
 *   <li>{@link #SCREEN}: c + g − c·g (black is neutral);</li>
 *   <li>{@link #OVERLAY}: 2·c·g for c ≤ ½, else the screen of g with 2c − 1 (gray ½ is neutral);</li>
 *   <li>{@link #SOFT_LIGHT}: c − (1 − 2g)·c·(1 − c) for g ≤ ½, else c + (2g − 1)·(D(c) − c) with D(c) =
 *       ((16c − 12)·c + 4)·c for c ≤ ¼ and √c otherwise (gray ½ is neutral).</li>
 * </ul>
 */
public enum BlendMode {

    /** The original's COMBINED: eq. 8 with the jDem846 tone of the brightness (the default). */
    JDEM846("jdem846") {
        @Override
        public double layer(double d, HillshadeOptions tone) {
            return tone.tone(d);
        }

        @Override
        public double blend(double c, double layer) {
            return Brightness.adjustBrightness(c, layer);
        }
    },

    /** The original's LIGHTEN, its sign fixed: eq. 8 with (1 + d′)/2, never darker than the tint. */
    JDEM846_LIGHTEN("jdem846-lighten") {
        @Override
        public double layer(double d, HillshadeOptions tone) {
            return (1 + Brightness.spot(d, tone.spotExponent())) / 2;
        }

        @Override
        public double blend(double c, double layer) {
            return Brightness.adjustBrightness(c, layer);
        }
    },

    /** The original's DARKEN, its sign fixed: eq. 8 with (d′ − 1)/2, never lighter than the tint. */
    JDEM846_DARKEN("jdem846-darken") {
        @Override
        public double layer(double d, HillshadeOptions tone) {
            return (Brightness.spot(d, tone.spotExponent()) - 1) / 2;
        }

        @Override
        public double blend(double c, double layer) {
            return Brightness.adjustBrightness(c, layer);
        }
    },

    /** W3C multiply: c·g. */
    MULTIPLY("multiply") {
        @Override
        public double blend(double c, double g) {
            return multiply(c, g);
        }
    },

    /** W3C screen: c + g − c·g. */
    SCREEN("screen") {
        @Override
        public double blend(double c, double g) {
            return screen(c, g);
        }
    },

    /** W3C overlay: the hard light of the tint on the hillshade. */
    OVERLAY("overlay") {
        @Override
        public double blend(double c, double g) {
            return c <= 0.5 ? multiply(g, 2 * c) : screen(g, 2 * c - 1);
        }
    },

    /** W3C soft light. */
    SOFT_LIGHT("soft-light") {
        @Override
        public double blend(double c, double g) {
            if (g <= 0.5) {
                return c - (1 - 2 * g) * c * (1 - c);
            }
            double dc = c <= 0.25 ? ((16 * c - 12) * c + 4) * c : Math.sqrt(c);
            return c + (2 * g - 1) * (dc - c);
        }
    };

    private final String cliName;

    BlendMode(String cliName) {
        this.cliName = cliName;
    }

    /** {@return the mode's name on the command line, e.g. {@code soft-light}} */
    public String cliName() {
        return cliName;
    }

    /**
     * The mode named {@code name} ({@link #cliName()}, case-insensitive; {@code _} may stand for {@code -}).
     *
     * @param name a mode's name, e.g. {@code multiply} or {@code jdem846-darken}
     * @return the mode
     * @throws IllegalArgumentException when no mode has that name; the message lists the names
     */
    public static BlendMode named(String name) {
        String wanted = name == null ? "" : name.trim().replace('_', '-');
        for (BlendMode m : values()) {
            if (m.cliName.equalsIgnoreCase(wanted)) {
                return m;
            }
        }
        StringBuilder names = new StringBuilder();
        for (BlendMode m : values()) {
            names.append(names.length() == 0 ? "" : ", ").append(m.cliName);
        }
        throw new IllegalArgumentException("unknown blend mode '" + name + "'; expected one of " + names);
    }

    /**
     * The per-pixel value this mode combines with each tint channel: for the W3C modes the gray hillshade
     * {@link #gray}(tone of d); for the jDem846 modes the argument of eq. 8.
     *
     * @param d    the light model's brightness, in [−1, 1]
     * @param tone the jDem846 tone (light/dark intensity, spot exponent)
     * @return the layer value
     */
    public double layer(double d, HillshadeOptions tone) {
        return gray(tone.tone(d));
    }

    /**
     * One tint channel with this mode's layer laid on it.
     *
     * @param c     the tint channel, in [0, 1]
     * @param layer the value of {@link #layer}
     * @return the blended channel, in [0, 1] (up to rounding)
     */
    public abstract double blend(double c, double layer);

    /**
     * The gray of the {@code hillshade} command's jdem846 product, before rounding, as a fraction of 255: eq. 8 on
     * mid-gray, 0.5·(1 + t), stretched onto 1 … 255: g = (1 + 254·0.5·(1 + t))/255. t = −1 → 1/255, 1 → 1.
     *
     * @param t the toned brightness, in [−1, 1]
     * @return the gray, in [1/255, 1]
     */
    public static double gray(double t) {
        return (1 + 254 * Brightness.adjustBrightness(0.5, t)) / 255;
    }

    private static double multiply(double b, double s) {
        return b * s;
    }

    private static double screen(double b, double s) {
        return b + s - b * s;
    }
}
