package io.github.jdem846.render;

/**
 * How tint, illumination and cast shadows combine into a pixel, with the original jDem846's defaults (era B
 * {@code lightingContext.*}).
 *
 * @param relativeLightIntensity scales a positive brightness (original 0.75)
 * @param relativeDarkIntensity  scales a negative brightness (original 1.0)
 * @param spotExponent           sharpens highlights: d → sign(d)·|d|^spot (original 1; sign-preserving, unlike the
 *                               original, whose even exponents turned shade into light)
 * @param shadowIntensity        a cell in cast shadow loses 2 × this much brightness (original 0.4)
 */
public record Composition(double relativeLightIntensity, double relativeDarkIntensity, double spotExponent,
                          double shadowIntensity) {

    /** The original's defaults: 0.75, 1.0, 1, 0.4. */
    public static final Composition ORIGINAL = new Composition(0.75, 1.0, 1.0, 0.4);

    public Composition {
        requireIn("relative light intensity", relativeLightIntensity, 0, 1);
        requireIn("relative dark intensity", relativeDarkIntensity, 0, 1);
        requireIn("shadow intensity", shadowIntensity, 0, 1);
        if (!(spotExponent > 0) || Double.isInfinite(spotExponent)) {
            throw new IllegalArgumentException("spot exponent must be positive and finite, got " + spotExponent);
        }
    }

    private static void requireIn(String what, double v, double lo, double hi) {
        if (!(v >= lo && v <= hi)) {
            throw new IllegalArgumentException(what + " must be between " + lo + " and " + hi + ", got " + v);
        }
    }
}
