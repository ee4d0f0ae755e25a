package io.github.jdem846.projection;

import org.apache.sis.referencing.operation.transform.AbstractMathTransform2D;
import org.opengis.referencing.operation.MathTransform2D;
import org.opengis.referencing.operation.Matrix;
import org.opengis.referencing.operation.TransformException;

/**
 * A {@link SphericalFormula} as an Apache SIS transform: longitude, latitude in degrees (east, north) to easting,
 * northing in metres on a sphere of the given radius, about a central meridian. Longitudes are taken modulo 360°
 * into [λ₀ − 180°, λ₀ + 180°]; a latitude beyond ±90° gives NaN. Its {@link #inverse()} gives longitudes in that
 * range and NaN outside the map. Derivatives are not provided.
 */
final class FormulaTransform extends AbstractMathTransform2D {

    private final SphericalFormula formula;
    private final double radius;
    private final double centralMeridian;
    private final Inverse inverse = new Inverse();

    /**
     * @param formula         the projection of the unit sphere
     * @param radius          the sphere's radius in metres
     * @param centralMeridian λ₀ in degrees
     */
    FormulaTransform(SphericalFormula formula, double radius, double centralMeridian) {
        this.formula = formula;
        this.radius = radius;
        this.centralMeridian = centralMeridian;
    }

    @Override
    public Matrix transform(double[] src, int srcOff, double[] dst, int dstOff, boolean derivate)
            throws TransformException {
        if (derivate) {
            throw new TransformException(formula.wktName() + ": derivatives are not provided");
        }
        double lon = src[srcOff];
        double lat = src[srcOff + 1];
        double[] xy = new double[2];
        if (Math.abs(lat) > 90 + 1e-9 || !Double.isFinite(lon) || !Double.isFinite(lat)) {
            dst[dstOff] = Double.NaN;
            dst[dstOff + 1] = Double.NaN;
            return null;
        }
        formula.forward(Math.toRadians(wrap(lon - centralMeridian)),
                Math.toRadians(Math.max(-90, Math.min(90, lat))), xy);
        dst[dstOff] = xy[0] * radius;
        dst[dstOff + 1] = xy[1] * radius;
        return null;
    }

    /** {@code degrees} taken modulo 360 into [−180, 180]; ±180 kept as given. */
    static double wrap(double degrees) {
        if (degrees >= -180 && degrees <= 180) {
            return degrees;
        }
        double w = degrees - 360 * Math.floor((degrees + 180) / 360);
        return w == -180 && degrees > 0 ? 180 : w;
    }

    @Override
    public MathTransform2D inverse() {
        return inverse;
    }

    @Override
    protected int computeHashCode() {
        return super.computeHashCode() ^ formula.hashCode() ^ Double.hashCode(radius)
                ^ Double.hashCode(centralMeridian);
    }

    @Override
    public boolean equals(Object object, org.apache.sis.util.ComparisonMode mode) {
        return object instanceof FormulaTransform t && t.formula.equals(formula) && t.radius == radius
                && t.centralMeridian == centralMeridian;
    }

    /** Easting, northing in metres to longitude, latitude in degrees. */
    private final class Inverse extends AbstractMathTransform2D.Inverse {

        Inverse() {
        }

        @Override
        public MathTransform2D inverse() {
            return FormulaTransform.this;
        }

        @Override
        public Matrix transform(double[] src, int srcOff, double[] dst, int dstOff, boolean derivate)
                throws TransformException {
            if (derivate) {
                throw new TransformException(formula.wktName() + ": derivatives are not provided");
            }
            double[] lp = new double[2];
            formula.inverse(src[srcOff] / radius, src[srcOff + 1] / radius, lp);
            dst[dstOff] = Math.toDegrees(lp[0]) + centralMeridian;
            dst[dstOff + 1] = Math.toDegrees(lp[1]);
            return null;
        }

        /**
         * Each point's first start is extrapolated from the two before it (their solutions, when both were on the
         * map), else the one before it, if on the map: along a row of pixels the start is then within about
         * 10⁻¹² rad of the solution and an iterative inverse converges in one step.
         */
        @Override
        public void transform(double[] src, int srcOff, double[] dst, int dstOff, int numPts) {
            double[] in = java.util.Arrays.copyOfRange(src, srcOff, srcOff + 2 * numPts);
            double[] hint = {Double.NaN, Double.NaN};
            double[] previous = {Double.NaN, Double.NaN};
            double[] last = {Double.NaN, Double.NaN};
            double[] lp = new double[2];
            for (int i = 0; i < numPts; i++) {
                if (!Double.isNaN(previous[0])) {
                    hint[0] = 2 * last[0] - previous[0];
                    hint[1] = 2 * last[1] - previous[1];
                } else {
                    hint[0] = last[0];
                    hint[1] = last[1];
                }
                formula.inverse(in[2 * i] / radius, in[2 * i + 1] / radius, hint, lp);
                dst[dstOff + 2 * i] = Math.toDegrees(lp[0]) + centralMeridian;
                dst[dstOff + 2 * i + 1] = Math.toDegrees(lp[1]);
                previous[0] = last[0];
                previous[1] = last[1];
                last[0] = lp[0]; // NaN off the map: the next point starts afresh
                last[1] = lp[1];
            }
        }
    }
}
