package io.github.jdem846.shadow;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * The geometry shared by every ray of one computation: the direction toward the sun in grid units, the metric
 * length of a step per row, the slope of the ray and the curvature drop.
 *
 * <p>The direction is built straight from sin and cos of the azimuth (not eq. 10's chain of square roots) and the
 * metric cell sizes of the middle row of the grid (of the grid it was cut from, for a window): east = sin a /
 * cellWidthMeters, south = −cos a / cellHeightMeters.
 * It is scaled so that its larger component is exactly ±1: one "major step" moves one column or one row. The metric
 * length of a major step is then computed per row, so lat/lon grids get the right shadow length at every latitude
 * (the original stepped in flat degrees).
 */
final class RayFrame {

    final int width;
    final int height;
    /** Grid displacement (columns, rows) of one major step toward the sun; max(|ux|, |uy|) = 1. */
    final double ux;
    final double uy;
    final boolean xMajor;
    /** Horizontal metres of one major step, per row. */
    final double[] metresPerStep;
    /** Eq. 9 with metric cell sizes: hypot(cell width, cell height) in metres, per row. */
    final double[] radiusInterval;
    final double elevationDeg;
    final double tanElevation;
    final double cosElevation;
    /** Curvature drop coefficient b: terrain at distance d is lowered by b·d²; 0 when off. */
    final double curvature;
    /** Highest valid elevation (NaN when the DEM is all no-data). */
    final double zMax;
    /** Angular radius of the sun for soft shadows (0 = hard shadows). */
    final double sunRadiusDeg;

    RayFrame(Dem dem, LightDirection light, ShadowOptions opt) {
        this(dem.geometry(), dem.statistics().max(), light, opt);
    }

    RayFrame(GridGeometry g, double zMax, LightDirection light, ShadowOptions opt) {
        this.width = g.width();
        this.height = g.height();
        // the direction in grid units from the middle row of the grid this one was cut from (if it was), so that
        // a window of a lat/lon grid traces the same rays as the whole grid
        int refRow = g.placement().rootHeight() / 2 - g.placement().row();
        double wRef = positive(g.cellWidthMeters(refRow), g.cellHeightMeters(refRow));
        double hRef = positive(g.cellHeightMeters(refRow), wRef);
        double az = Math.toRadians(light.azimuthDegrees());
        double gx = Math.sin(az) / wRef;
        double gy = -Math.cos(az) / hRef;
        this.xMajor = Math.abs(gx) >= Math.abs(gy);
        if (xMajor) {
            this.ux = Math.signum(gx);
            this.uy = gy / Math.abs(gx);
        } else {
            this.ux = gx / Math.abs(gy);
            this.uy = Math.signum(gy);
        }
        this.metresPerStep = new double[height];
        this.radiusInterval = new double[height];
        for (int r = 0; r < height; r++) {
            double w = positive(g.cellWidthMeters(r), wRef);
            double h = positive(g.cellHeightMeters(r), hRef);
            metresPerStep[r] = Math.hypot(ux * w, uy * h);
            radiusInterval[r] = Math.hypot(w, h);
        }
        this.elevationDeg = light.elevationDegrees();
        double e = Math.toRadians(elevationDeg);
        this.tanElevation = Math.tan(e);
        this.cosElevation = Math.cos(e);
        if (opt.earthCurvature()) {
            double radius = Double.isNaN(opt.earthRadiusMeters()) ? g.ellipsoid().meanRadius()
                    : opt.earthRadiusMeters();
            this.curvature = (1 - opt.refractionCoefficient()) / (2 * radius);
        } else {
            this.curvature = 0;
        }
        this.zMax = zMax;
        this.sunRadiusDeg = opt.softShadows() ? opt.sunDiameterDegrees() / 2 : 0;
    }

    /** A usable metric size: {@code value} when positive and finite, else a tiny fraction of {@code fallback}. */
    private static double positive(double value, double fallback) {
        if (value > 0 && Double.isFinite(value)) {
            return value;
        }
        return fallback > 0 && Double.isFinite(fallback) ? fallback * 1e-9 : 1e-9;
    }

    /** The row nearest to fractional row {@code y}, clamped into the grid. */
    int clampRow(double y) {
        int r = (int) Math.floor(y + 0.5);
        return r < 0 ? 0 : (r >= height ? height - 1 : r);
    }

    /** True when soft shadows are asked for. */
    boolean soft() {
        return sunRadiusDeg > 0;
    }

    /** tan of the elevation of the sun's lower limb (may be ≤ 0). */
    double tanLowerLimb() {
        return Math.tan(Math.toRadians(elevationDeg - sunRadiusDeg));
    }

    /** tan of the elevation of the sun's upper limb (+∞ at or past the zenith). */
    double tanUpperLimb() {
        double up = elevationDeg + sunRadiusDeg;
        return up >= 90 ? Double.POSITIVE_INFINITY : Math.tan(Math.toRadians(up));
    }

    /** Smallest metric length of a major step over all rows. */
    double minMetresPerStep() {
        double m = Double.POSITIVE_INFINITY;
        for (double v : metresPerStep) {
            m = Math.min(m, v);
        }
        return m;
    }

    /** Largest metric length of a major step over all rows. */
    double maxMetresPerStep() {
        double m = 0;
        for (double v : metresPerStep) {
            m = Math.max(m, v);
        }
        return m;
    }
}
