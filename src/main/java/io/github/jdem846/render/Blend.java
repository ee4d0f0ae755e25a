package io.github.jdem846.render;

import java.util.Objects;

/**
 * How the shading is laid on the tint: a {@link BlendMode} and the opacity of the shaded layer. The pixel is
 * c·(1 − opacity) + blend(c)·opacity on each channel, the original jDem846's {@code lightingMultiple} of era A
 * ({@code interpolateColor(relief, hill, lightingMultiple)}, 0.75 there) and the opacity of a hillshade layer in
 * QGIS.
 *
 * @param mode    how the light and the tint combine
 * @param opacity the weight of the shaded colour against the bare tint, 0 (the tint alone) to 1 (the default)
 */
public record Blend(BlendMode mode, double opacity) {

    /** The default: the original's COMBINED (eq. 8), fully opaque, byte for byte the render without a blend. */
    public static final Blend DEFAULT = new Blend(BlendMode.JDEM846, 1);

    /**
     * Checks the mode is given and the opacity is in [0, 1].
     *
     * @param mode    how the light and the tint combine
     * @param opacity the weight of the shaded colour against the bare tint, 0 to 1
     */
    public Blend {
        Objects.requireNonNull(mode, "mode");
        if (!(opacity >= 0 && opacity <= 1)) {
            throw new IllegalArgumentException("hillshade opacity must be between 0 and 1 (the original's era A used"
                    + " 0.75), got " + opacity);
        }
    }

    /**
     * The same opacity with another mode.
     *
     * @param m the blend mode
     * @return the new blend
     */
    public Blend withMode(BlendMode m) {
        return new Blend(m, opacity);
    }

    /**
     * The same mode with another opacity.
     *
     * @param o the opacity, 0 to 1
     * @return the new blend
     */
    public Blend withOpacity(double o) {
        return new Blend(mode, o);
    }

    /** {@return true for the default composition, eq. 8 fully opaque} */
    public boolean isDefault() {
        return mode == BlendMode.JDEM846 && opacity == 1;
    }
}
