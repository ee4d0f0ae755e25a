package io.github.jdem846.projection;

/**
 * The Aitoff projection, as PROJ's {@code +proj=aitoff} (Snyder 1993, p. 130; Snyder &amp; Voxland 1989, USGS
 * PP 1453, p. 233): with cos α = cos φ cos(λ/2), x = 2 cos φ sin(λ/2) / sinc α, y = sin φ / sinc α
 * (sinc α = sin α / α). It is the equatorial azimuthal equidistant projection of (λ/2, φ) with x doubled, whose
 * inverse is closed (Snyder 1987, USGS PP 1395, p. 196): with X = x/2, ρ = √(X² + y²) (the angle α),
 * φ = atan2(y sinc ρ, √((X sinc ρ)² + cos² ρ)), λ = 2 atan2(X sinc ρ, cos ρ). The map is the ellipse (x/π)² + (y/(π/2))² ≤ 1.
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
        double halfX = x / 2;
        double rho = Math.min(Math.PI / 2, Math.sqrt(halfX * halfX + y * y)); // bounded: no need of hypot
        if (rho < 1e-15) {
            lambdaPhi[0] = 0;
            lambdaPhi[1] = 0;
            return;
        }
        // sin φ = y sinc ρ, cos φ sin(λ/2) = X sinc ρ, cos φ cos(λ/2) = cos ρ: atan2 keeps the poles accurate
        double sinc = Math.sin(rho) / rho;
        double east = halfX * sinc;
        double cosRho = Math.cos(rho);
        lambdaPhi[1] = Math.atan2(y * sinc, Math.sqrt(east * east + cosRho * cosRho));
        lambdaPhi[0] = 2 * Math.atan2(east, cosRho);
    }

    @Override
    public String wktName() {
        return "Aitoff";
    }
}
