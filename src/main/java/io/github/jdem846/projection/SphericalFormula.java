package io.github.jdem846.projection;

/**
 * A world projection of the unit sphere that Apache SIS does not implement, written from its published formulas:
 * longitude difference from the central meridian λ ∈ [−π, π] and latitude φ ∈ [−π/2, π/2], both in radians, to
 * x, y on a sphere of radius 1. {@link FormulaTransform} scales them to metres and makes them an Apache SIS
 * transform.
 */
public sealed interface SphericalFormula permits Aitoff, Hammer, WinkelTripel, WagnerVI {

    /**
     * Projects a point.
     *
     * @param lambda longitude from the central meridian in radians, in [−π, π]
     * @param phi    latitude in radians, in [−π/2, π/2]
     * @param xy     receives x and y on the unit sphere
     */
    void forward(double lambda, double phi, double[] xy);

    /**
     * Finds the point that projects to {@code (x, y)}.
     *
     * @param x         x on the unit sphere
     * @param y         y on the unit sphere
     * @param lambdaPhi receives λ and φ in radians, or NaN, NaN when {@code (x, y)} lies outside the map
     */
    void inverse(double x, double y, double[] lambdaPhi);

    /**
     * Finds the point that projects to {@code (x, y)}, given a point likely near it (an iterative inverse starts
     * there); the same as {@link #inverse(double, double, double[])} for a closed inverse.
     *
     * @param x         x on the unit sphere
     * @param y         y on the unit sphere
     * @param hint      λ and φ in radians of a nearby solution, or NaN
     * @param lambdaPhi receives λ and φ in radians, or NaN, NaN when {@code (x, y)} lies outside the map
     */
    default void inverse(double x, double y, double[] hint, double[] lambdaPhi) {
        inverse(x, y, lambdaPhi);
    }

    /** {@return the projection's name as ESRI and GDAL write it in WKT 1 ({@code PROJECTION["…"]})} */
    String wktName();
}
