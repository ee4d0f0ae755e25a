package io.github.jdem846.projection;

/**
 * The Winkel Tripel projection, as PROJ's {@code +proj=wintri} (Snyder 1993, p. 231): the mean of the {@link
 * Aitoff} projection and the equirectangular projection with standard parallel φ₁,
 * x = (λ cos φ₁ + x_Aitoff) / 2, y = (φ + y_Aitoff) / 2. Winkel's own φ₁ = arccos(2/π) ≈ 50.4598° is the default
 * (ESRI's "World_Winkel_Tripel_NGS" uses 50.467°). It has no closed inverse: {@link NewtonInverse} solves it, from
 * the {@link Aitoff} point at the same place in the outline.
 *
 * @param standardParallel φ₁ in degrees, in [0, 90)
 */
public record WinkelTripel(double standardParallel) implements SphericalFormula {

    /** Winkel's standard parallel, arccos(2/π), in degrees. */
    public static final double WINKEL_PARALLEL = Math.toDegrees(Math.acos(2 / Math.PI));

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
        double halfWidth = (Math.PI * cosPhi1 + Math.PI) / 2; // x of (±π, 0)
        double ex = x / halfWidth;
        double ey = y / (Math.PI / 2);
        if (Math.abs(ex) > 1 + 1e-12 || Math.abs(ey) > 1 + 1e-12) {
            lambdaPhi[0] = Double.NaN;
            lambdaPhi[1] = Double.NaN;
            return;
        }
        // start: the Aitoff point at the same place in the outline (both maps span ±π/2 in y)
        double[] guess = new double[2];
        new Aitoff().inverse(ex * Math.PI, ey * Math.PI / 2 * Math.sqrt(Math.max(0, 1 - ex * ex)), guess);
        NewtonInverse.solve(this, x, y, hint, guess, lambdaPhi);
    }

    @Override
    public String wktName() {
        return "Winkel_Tripel";
    }
}
