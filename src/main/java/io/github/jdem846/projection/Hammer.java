package io.github.jdem846.projection;

/**
 * The Hammer (Hammer–Aitoff) equal-area projection, as PROJ's {@code +proj=hammer} (Snyder 1993, p. 130;
 * Snyder &amp; Voxland 1989, USGS PP 1453, p. 233):
 * x = 2√2 cos φ sin(λ/2) / √(1 + cos φ cos(λ/2)), y = √2 sin φ / √(1 + cos φ cos(λ/2)); inverse in closed
 * form: z = √(1 − (x/4)² − (y/2)²), λ = 2 atan2(z x, 2(2z² − 1)), φ = asin(z y)
 * (computed as atan2 for accuracy at the poles). The map is the ellipse
 * x²/8 + y²/2 ≤ 1.
 */
public record Hammer() implements SphericalFormula {

    @Override
    public void forward(double lambda, double phi, double[] xy) {
        double cosPhi = Math.cos(phi);
        double d = Math.sqrt(2 / (1 + cosPhi * Math.cos(lambda / 2)));
        xy[0] = 2 * d * cosPhi * Math.sin(lambda / 2);
        xy[1] = d * Math.sin(phi);
    }

    @Override
    public void inverse(double x, double y, double[] lambdaPhi) {
        double zz = 1 - x * x / 16 - y * y / 4;
        if (!(zz >= 0.5 - 1e-12)) { // outside the ellipse x²/8 + y²/2 ≤ 1
            lambdaPhi[0] = Double.NaN;
            lambdaPhi[1] = Double.NaN;
            return;
        }
        double z = Math.sqrt(Math.max(zz, 0.5));
        // cos φ sin(λ/2) = z x / 2, cos φ cos(λ/2) = 2z² − 1, sin φ = z y: atan2 keeps the poles accurate
        double east = z * x / 2;
        double c = Math.max(0, 1 - x * x / 8 - y * y / 2); // 2z² − 1 without the rounding of z
        lambdaPhi[0] = 2 * Math.atan2(east, c);
        lambdaPhi[1] = Math.atan2(z * y, Math.hypot(east, c));
    }

    @Override
    public String wktName() {
        return "Hammer_Aitoff";
    }
}
