package io.github.jdem846.projection;

/**
 * The Winkel Tripel projection, as PROJ's {@code +proj=wintri} (Snyder 1993, p. 231): the mean of the {@link
 * Aitoff} projection and the equirectangular projection with standard parallel φ₁,
 * x = (λ cos φ₁ + x_Aitoff) / 2, y = (φ + y_Aitoff) / 2. Winkel's own φ₁ = arccos(2/π) ≈ 50.4598° is the default
 * (ESRI's "World_Winkel_Tripel_NGS" uses 50.467°).
 *
 * <p>It has no closed inverse: Newton's method with the analytic Jacobian starts from the given hint (a
 * neighbouring pixel's solution), where it converges in one or two steps; failing that, a point outside the map's
 * outline (the images of the meridians ±180°) is refused, and one inside is started from the {@link Aitoff} point
 * at the same place in the outline; should that fail too, {@link NewtonInverse} tries other starts.
 *
 * @param standardParallel φ₁ in degrees, in [0, 90)
 */
public record WinkelTripel(double standardParallel) implements SphericalFormula {

    /** Winkel's standard parallel, arccos(2/π), in degrees. */
    public static final double WINKEL_PARALLEL = Math.toDegrees(Math.acos(2 / Math.PI));

    /** Residual (unit sphere) at which the analytic Newton iteration stops: about 6 nm on the Earth. */
    private static final double CONVERGED = 1e-15;

    /**
     * A Newton step at most this long (radians) is taken as the last: the error after it is of the order of its
     * square times the ratio of the second to the first derivatives (below 10⁻¹⁵ rad on this map).
     */
    private static final double QUADRATIC = 1e-8;

    private static final int MAX_STEPS = 12;

    /** Steps from a neighbour's solution before trying elsewhere: it converges in one or two. */
    private static final int HINTED_STEPS = 4;

    /**
     * Checks that the standard parallel is in [0, 90) degrees.
     *
     * @param standardParallel φ₁ in degrees, in [0, 90)
     */
    public WinkelTripel {
        if (!(standardParallel >= 0 && standardParallel < 90)) {
            throw new IllegalArgumentException("the Winkel Tripel standard parallel must be in [0, 90) degrees, got "
                    + standardParallel);
        }
    }

    /** Winkel's own projection, φ₁ = arccos(2/π). */
    public WinkelTripel() {
        this(WINKEL_PARALLEL);
    }

    @Override
    public void forward(double lambda, double phi, double[] xy) {
        new Aitoff().forward(lambda, phi, xy);
        xy[0] = (lambda * Math.cos(Math.toRadians(standardParallel)) + xy[0]) / 2;
        xy[1] = (phi + xy[1]) / 2;
    }

    @Override
    public void inverse(double x, double y, double[] lambdaPhi) {
        inverse(x, y, null, lambdaPhi);
    }

    @Override
    public void inverse(double x, double y, double[] hint, double[] lambdaPhi) {
        double cosPhi1 = Math.cos(Math.toRadians(standardParallel));
        if (hint != null && Double.isFinite(hint[0]) && Double.isFinite(hint[1])
                && newton(x, y, hint[0], hint[1], cosPhi1, HINTED_STEPS, lambdaPhi)) {
            return; // a solution with |λ| ≤ π: on the map
        }
        if (!onMap(x, y, cosPhi1)) {
            lambdaPhi[0] = Double.NaN;
            lambdaPhi[1] = Double.NaN;
            return;
        }
        // start: the Aitoff point at the same place in the outline (both maps span ±π/2 in y)
        double halfWidth = (Math.PI * cosPhi1 + Math.PI) / 2; // x of (±π, 0)
        double ex = Math.max(-1, Math.min(1, x / halfWidth));
        double ey = y / (Math.PI / 2);
        double[] guess = new double[2];
        new Aitoff().inverse(ex * Math.PI, ey * Math.PI / 2 * Math.sqrt(1 - ex * ex), guess);
        if (newton(x, y, guess[0], guess[1], cosPhi1, MAX_STEPS, lambdaPhi)) {
            return;
        }
        NewtonInverse.solve(this, x, y, hint, guess, lambdaPhi);
    }

    /**
     * Whether (x, y) lies within the map's outline, to 10⁻⁹: |y| ≤ π/2 and |x| at most the x of the meridian ±π
     * at that y. Along λ = π, x = (π cos φ₁ + π cos φ) / 2 and y = (φ + (π/2) sin φ) / 2, increasing with φ.
     */
    static boolean onMap(double x, double y, double cosPhi1) {
        double ay = Math.abs(y);
        if (!(ay <= Math.PI / 2 + 1e-12) || !Double.isFinite(x)) {
            return false;
        }
        double ax = Math.abs(x);
        double inner = Math.PI * cosPhi1 / 2; // x of the edge at the poles: every |x| up to it is on the map
        if (ax <= inner) {
            return true;
        }
        if (ax > (Math.PI * cosPhi1 + Math.PI) / 2 + 1e-9) {
            return false;
        }
        // φ of the edge at this y: y(φ) is increasing and concave on [0, π/2], so Newton from π/2 converges
        double phi = Math.PI / 2;
        for (int i = 0; i < 50; i++) {
            double f = (phi + Math.PI / 2 * Math.sin(phi)) / 2 - ay;
            double step = f / ((1 + Math.PI / 2 * Math.cos(phi)) / 2);
            phi = Math.max(0, phi - step);
            if (Math.abs(step) < 1e-15) {
                break;
            }
        }
        return ax <= (Math.PI * cosPhi1 + Math.PI * Math.cos(phi)) / 2 + 1e-9;
    }

    /**
     * Newton's method with the analytic Jacobian from (λ₀, φ₀), at most {@code maxSteps} steps of at most 0.5 rad,
     * kept on the sphere.
     *
     * @return true, with the solution in {@code out}, when forward(λ, φ) comes within {@link
     *     NewtonInverse#TOLERANCE} of (x, y)
     */
    private boolean newton(double x, double y, double lambda0, double phi0, double cosPhi1, int maxSteps,
                           double[] out) {
        double lambda = Math.max(-Math.PI, Math.min(Math.PI, lambda0));
        double phi = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, phi0));
        double fx = Double.NaN;
        double fy = Double.NaN;
        for (int i = 0; i <= maxSteps; i++) {
            // the forward projection, as forward() computes it, and its partial derivatives
            double cosPhi = Math.cos(phi);
            double sinPhi = Math.sin(phi);
            double sinHalf = Math.sin(lambda / 2);
            double cosHalf = Math.cos(lambda / 2);
            double u = cosPhi * cosHalf; // cos α
            double alpha = Math.acos(Math.max(-1, Math.min(1, u)));
            double sinAlpha = Math.sin(alpha);
            double g = alpha < 1e-8 ? 1 : alpha / sinAlpha; // 1 / sinc α
            fx = (lambda * cosPhi1 + 2 * cosPhi * sinHalf * g) / 2 - x;
            fy = (phi + sinPhi * g) / 2 - y;
            if (Math.abs(fx) <= CONVERGED && Math.abs(fy) <= CONVERGED) {
                out[0] = lambda;
                out[1] = phi;
                return true;
            }
            if (i == maxSteps) {
                break;
            }
            // dg/du = −(sin α − α cos α) / sin³ α, → −(1/3 + 2α²/15) as α → 0
            double dg = alpha < 1e-2 ? -(1.0 / 3 + 2 * alpha * alpha / 15)
                    : -(sinAlpha - alpha * u) / (sinAlpha * sinAlpha * sinAlpha);
            double dudl = -0.5 * cosPhi * sinHalf;
            double dudp = -sinPhi * cosHalf;
            double dxdl = (cosPhi1 + cosPhi * cosHalf * g + 2 * cosPhi * sinHalf * dg * dudl) / 2;
            double dxdp = (-2 * sinPhi * sinHalf * g + 2 * cosPhi * sinHalf * dg * dudp) / 2;
            double dydl = sinPhi * dg * dudl / 2;
            double dydp = (1 + cosPhi * g + sinPhi * dg * dudp) / 2;
            double det = dxdl * dydp - dxdp * dydl;
            if (det == 0 || !Double.isFinite(det)) {
                break;
            }
            double dl = (fx * dydp - fy * dxdp) / det;
            double dp = (fy * dxdl - fx * dydl) / det;
            double step = Math.max(Math.abs(dl), Math.abs(dp));
            if (step <= QUADRATIC) {
                // Newton converges quadratically: from within 10⁻⁸ rad, this step lands within ~10⁻¹⁶ rad
                out[0] = Math.max(-Math.PI, Math.min(Math.PI, lambda - dl));
                out[1] = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, phi - dp));
                return true;
            }
            if (step > 0.5) {
                dl *= 0.5 / step;
                dp *= 0.5 / step;
            }
            lambda = Math.max(-Math.PI, Math.min(Math.PI, lambda - dl));
            phi = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, phi - dp));
        }
        if (Math.abs(fx) <= NewtonInverse.TOLERANCE && Math.abs(fy) <= NewtonInverse.TOLERANCE) {
            out[0] = lambda;
            out[1] = phi;
            return true;
        }
        return false;
    }

    @Override
    public String wktName() {
        return "Winkel_Tripel";
    }
}
