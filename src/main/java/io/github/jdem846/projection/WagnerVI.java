package io.github.jdem846.projection;

/**
 * The Wagner VI pseudocylindrical projection, as PROJ's {@code +proj=wag6} (Snyder 1993, p. 204, where it is
 * x = λ√(1 − 3(φ/π)²), y = φ; PROJ and ESRI scale both by 0.94745): x = 0.94745 λ √(1 − 3(φ/π)²),
 * y = 0.94745 φ. The inverse is closed: φ = y / 0.94745, λ = x / (0.94745 √(1 − 3(φ/π)²)).
 */
public record WagnerVI() implements SphericalFormula {

    /** PROJ's scale of both axes. */
    static final double SCALE = 0.94745;

    @Override
    public void forward(double lambda, double phi, double[] xy) {
        double t = phi / Math.PI;
        xy[0] = SCALE * lambda * Math.sqrt(1 - 3 * t * t);
        xy[1] = SCALE * phi;
    }

    @Override
    public void inverse(double x, double y, double[] lambdaPhi) {
        double phi = y / SCALE;
        double t = phi / Math.PI;
        double width = SCALE * Math.sqrt(Math.max(0, 1 - 3 * t * t));
        double lambda = x / width;
        if (!(Math.abs(phi) <= Math.PI / 2 + 1e-12) || !(Math.abs(lambda) <= Math.PI + 1e-12)) {
            lambdaPhi[0] = Double.NaN;
            lambdaPhi[1] = Double.NaN;
            return;
        }
        lambdaPhi[0] = Math.max(-Math.PI, Math.min(Math.PI, lambda));
        lambdaPhi[1] = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, phi));
    }

    @Override
    public String wktName() {
        return "Wagner_VI";
    }
}
