package io.github.jdem846.projection;

/**
 * The Aitoff projection, as PROJ's {@code +proj=aitoff} (Snyder 1993, p. 130; Snyder &amp; Voxland 1989, USGS
 * PP 1453, p. 233): with cos α = cos φ cos(λ/2), x = 2 cos φ sin(λ/2) / sinc α, y = sin φ / sinc α
 * (sinc α = sin α / α). It has no closed inverse: {@link NewtonInverse} solves it, starting from the closed inverse
 * of the {@link Hammer} projection, whose map has the same outline scaled. The map is the ellipse
 * (x/π)² + (y/(π/2))² ≤ 1.
 */
public record Aitoff() implements SphericalFormula {

    @Override
    public void forward(double lambda, double phi, double[] xy) {
        double cosPhi = Math.cos(phi);
        double cosAlpha = cosPhi * Math.cos(lambda / 2);
        double alpha = Math.acos(Math.max(-1, Math.min(1, cosAlpha)));
        double overSinc = alpha < 1e-8 ? 1 : alpha / Math.sin(alpha); // 1 / sinc α
        xy[0] = 2 * cosPhi * Math.sin(lambda / 2) * overSinc;
        xy[1] = Math.sin(phi) * overSinc;
    }

    @Override
    public void inverse(double x, double y, double[] lambdaPhi) {
        double ex = x / Math.PI;
        double ey = y / (Math.PI / 2);
        if (ex * ex + ey * ey > 1 + 1e-12) {
            lambdaPhi[0] = Double.NaN;
            lambdaPhi[1] = Double.NaN;
            return;
        }
        NewtonInverse.solve(this, x, y, hammerGuess(ex, ey), lambdaPhi);
    }

    /** The point of the Hammer map with the same place in the outline: a start close to the Aitoff solution. */
    static double[] hammerGuess(double ex, double ey) {
        double[] guess = new double[2];
        double r = Math.hypot(ex, ey);
        double shrink = r > 0.999 ? 0.999 / r : 1; // keep the start inside, where λ is defined
        new Hammer().inverse(ex * shrink * 2 * Math.sqrt(2), ey * shrink * Math.sqrt(2), guess);
        return guess;
    }

    @Override
    public String wktName() {
        return "Aitoff";
    }
}
