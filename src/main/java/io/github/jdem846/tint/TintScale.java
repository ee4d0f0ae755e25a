package io.github.jdem846.tint;

/**
 * How a percent ramp spreads a DEM's range over its stops: the original jDem846's elevation scalers
 * ({@code scaling/LinearScaler}, {@code LogarithmicScaler}, {@code ExponentialScaler}, {@code CubicScaler}) with an
 * elevation multiple of 1, applied to the tint only (slopes and shadows keep the true heights).
 *
 * <p>Each maps a position {@code r} in [0, 1] of a range {@code R} metres tall to a position in [0, 1], monotone,
 * with 0 ↦ 0 and 1 ↦ 1; see docs/tint.md for the formulas and pictures.
 */
public enum TintScale {

    /** r ↦ r: the ramp as written (the original's default). */
    LINEAR,
    /**
     * r ↦ log(10·r·R) / log(10·R), clamped to [0, 1]: low ground takes most of the ramp (the original's formula,
     * which paints the lowest 0.1 m black; here it takes the first colour). Ranges under 0.1 m stay linear.
     */
    LOGARITHMIC,
    /**
     * r ↦ (2^(r·R/10000) − 1) / (2^(R/10000) − 1): high ground takes more of the ramp, by an amount that grows with
     * the range (10 km doubles the rate; almost linear for a few hundred metres), as the original's divisor 10000.
     */
    EXPONENTIAL,
    /** r ↦ r³: the lowest half of the range takes the first eighth of the ramp. */
    CUBIC;

    private static final double LN2 = Math.log(2);

    /** (e^(a·r) − 1) / (e^a − 1), written so that neither part overflows for huge a. */
    private static double exponential(double r, double a) {
        if (!(a > 0)) {
            return r;
        }
        if (a < 1) {
            return Math.expm1(a * r) / Math.expm1(a);
        }
        return Math.exp(a * (r - 1)) * (-Math.expm1(-a * r)) / (-Math.expm1(-a));
    }

    /**
     * {@return the scaled position, in [0, 1]}
     *
     * @param ratio position in the range, in [0, 1]
     * @param range the range's height in metres (≥ 0)
     */
    public double apply(double ratio, double range) {
        double r = Math.min(1, Math.max(0, ratio));
        return switch (this) {
            case LINEAR -> r;
            case LOGARITHMIC -> range * 10 <= 1 ? r
                    : Math.min(1, Math.max(0, Math.log(10 * r * range) / Math.log(10 * range)));
            case EXPONENTIAL -> exponential(r, range / 10000 * LN2);
            case CUBIC -> r * r * r;
        };
    }
}
