package io.github.jdem846.projection;

/**
 * Inverts a {@link SphericalFormula} without a closed inverse by Newton's method on (λ, φ), with the Jacobian
 * taken by forward differences (towards the equator). Each step is limited (at most 0.5 rad) and kept on the sphere (|λ| ≤ π,
 * |φ| ≤ π/2); a point whose forward projection does not come back within {@link #TOLERANCE} of (x, y) from the
 * given start or from a few others lies outside the map and gives NaN.
 */
final class NewtonInverse {

    /** Largest accepted distance on the unit sphere's map between (x, y) and the forward of the solution. */
    static final double TOLERANCE = 1e-12;

    private static final int MAX_ITERATIONS = 60;
    private static final double H = 1e-7;

    private NewtonInverse() {
    }

    /**
     * Solves forward(λ, φ) = (x, y).
     *
     * @param formula   the projection
     * @param x         x on the unit sphere
     * @param y         y on the unit sphere
     * @param guess     the first start, λ and φ in radians
     * @param lambdaPhi receives λ and φ, or NaN, NaN when no start converges
     */
    static void solve(SphericalFormula formula, double x, double y, double[] guess, double[] lambdaPhi) {
        solve(formula, x, y, null, guess, lambdaPhi);
    }

    /**
     * Solves forward(λ, φ) = (x, y), trying {@code hint} (e.g. the solution of the neighbouring point) first.
     *
     * @param hint the first start, or null
     */
    static void solve(SphericalFormula formula, double x, double y, double[] hint, double[] guess,
                      double[] lambdaPhi) {
        double[] none = {Double.NaN, Double.NaN};
        double[][] starts = {hint != null ? hint : none, guess, {x, y / 2}, {x / 2, y}, {0, y}};
        for (double[] start : starts) {
            if (Double.isFinite(start[0]) && Double.isFinite(start[1])
                    && iterate(formula, x, y, start[0], start[1], lambdaPhi)) {
                return;
            }
        }
        lambdaPhi[0] = Double.NaN;
        lambdaPhi[1] = Double.NaN;
    }

    private static boolean iterate(SphericalFormula formula, double x, double y, double lambda0, double phi0,
                                   double[] out) {
        double lambda = clamp(lambda0, Math.PI);
        double phi = clamp(phi0, Math.PI / 2);
        double[] f = new double[2];
        double[] a = new double[2];
        double[] b = new double[2];
        for (int i = 0; i < MAX_ITERATIONS; i++) {
            formula.forward(lambda, phi, f);
            double fx = f[0] - x;
            double fy = f[1] - y;
            if (Math.abs(fx) <= TOLERANCE * 1e-3 && Math.abs(fy) <= TOLERANCE * 1e-3) {
                break;
            }
            formula.forward(lambda + H, phi, a);
            double dxdl = (a[0] - f[0]) / H;
            double dydl = (a[1] - f[1]) / H;
            formula.forward(lambda, phi + (phi > 0 ? -H : H), b);
            double dxdp = (b[0] - f[0]) / (phi > 0 ? -H : H);
            double dydp = (b[1] - f[1]) / (phi > 0 ? -H : H);
            double det = dxdl * dydp - dxdp * dydl;
            if (det == 0 || !Double.isFinite(det)) {
                break;
            }
            double dl = (fx * dydp - fy * dxdp) / det;
            double dp = (fy * dxdl - fx * dydl) / det;
            double step = Math.max(Math.abs(dl), Math.abs(dp));
            if (step > 0.5) {
                dl *= 0.5 / step;
                dp *= 0.5 / step;
            }
            lambda = clamp(lambda - dl, Math.PI);
            phi = clamp(phi - dp, Math.PI / 2);
            if (step < 1e-15) {
                break;
            }
        }
        formula.forward(lambda, phi, f);
        if (Math.abs(f[0] - x) <= TOLERANCE && Math.abs(f[1] - y) <= TOLERANCE) {
            out[0] = lambda;
            out[1] = phi;
            return true;
        }
        return false;
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }
}
