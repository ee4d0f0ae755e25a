package io.github.jdem846.shadow;

import io.github.jdem846.raster.Dem;

/**
 * One ray per cell, marched toward the sun (article section 4.2, eq. 9–11, tests 1–4), used by {@code march} and by
 * the {@code exact} reference.
 *
 * <p>From the cell centre at its own elevation the ray advances one step at a time; the ray height is the cell's
 * elevation plus the horizontal distance times tan(elevation) (eq. 11 in metres). Each sample is tested in the
 * article's order: test 2 (out of the grid → lit), test 3 (no-data → keep going), test 1 (terrain above the ray →
 * shadow), test 4 (ray above the data maximum → lit). A no-data sample also ends the ray as lit when the ray is
 * already above the maximum: test 4 would end it at the next valid sample anyway, so no result changes, but a long
 * no-data run cannot make the ray crawl. The number of steps is bounded by the grid's size.
 */
final class RayMarcher {

    private final float[] v;
    private final RayFrame f;
    private final int w;
    private final int h;
    private final boolean bilinear;
    /** Step along the major axis, in cells; NaN = the article's radius interval. */
    private final double stepCells;
    private final long maxSteps;

    RayMarcher(Dem dem, RayFrame frame, StepSize step, boolean bilinear) {
        this.v = dem.backingArray();
        this.f = frame;
        this.w = dem.width();
        this.h = dem.height();
        this.bilinear = bilinear;
        this.stepCells = step.cells();
        double minStep;
        if (step.isArticle()) {
            double maxMps = 0;
            double minRi = Double.POSITIVE_INFINITY;
            for (int r = 0; r < h; r++) {
                maxMps = Math.max(maxMps, frame.metresPerStep[r]);
                minRi = Math.min(minRi, frame.radiusInterval[r]);
            }
            minStep = Math.max(minRi * frame.cosElevation / maxMps, 1e-9);
        } else {
            minStep = stepCells;
        }
        this.maxSteps = (long) Math.ceil((w + h + 2) / minStep) + 8;
    }

    private double sample(double x, double y) {
        return bilinear ? TerrainSampler.bilinear(v, w, h, x, y) : TerrainSampler.nearest(v, w, h, x, y);
    }

    /** Shadowed fraction of cell (c, r): 0 or 1 for hard shadows, the hidden part of the sun's disk when soft. */
    float shade(int c, int r) {
        double z0 = v[r * w + c];
        if (z0 != z0) {
            return 0f;
        }
        return f.soft() ? (float) soft(c, r, z0) : (hardBlocked(c, r, z0) ? 1f : 0f);
    }

    private double stepOf(int cellRow, double y) {
        return Double.isNaN(stepCells)
                ? f.radiusInterval[cellRow] * f.cosElevation / f.metresPerStep[f.clampRow(y)]
                : stepCells;
    }

    private boolean hardBlocked(int c, int r, double z0) {
        double x = c;
        double y = r;
        double dist = 0;
        double tan = f.tanElevation;
        double b = f.curvature;
        double zMax = f.zMax;
        for (long n = 0; n < maxSteps; n++) {
            double dt = stepOf(r, y);
            dist += dt * f.metresPerStep[f.clampRow(y)];
            x += f.ux * dt;
            y += f.uy * dt;
            if (TerrainSampler.isOutside(x, y, w, h)) {
                return false;                                   // test 2
            }
            double ray = z0 + dist * tan;                       // eq. 11
            double z = sample(x, y);
            if (z != z) {                                       // test 3
                if (ray > zMax) {
                    return false;
                }
                continue;
            }
            if (z - b * dist * dist > ray) {                    // test 1
                return true;
            }
            if (ray > zMax) {                                   // test 4
                return false;
            }
        }
        return false;
    }

    private double soft(int c, int r, double z0) {
        double x = c;
        double y = r;
        double dist = 0;
        double tanLo = f.tanLowerLimb();
        double tanHi = f.tanUpperLimb();
        double b = f.curvature;
        double zMax = f.zMax;
        double maxSlope = Double.NEGATIVE_INFINITY;
        for (long n = 0; n < maxSteps; n++) {
            double dt = stepOf(r, y);
            dist += dt * f.metresPerStep[f.clampRow(y)];
            x += f.ux * dt;
            y += f.uy * dt;
            if (TerrainSampler.isOutside(x, y, w, h)) {
                break;
            }
            double z = sample(x, y);
            if (z == z) {
                double slope = (z - b * dist * dist - z0) / dist;
                if (slope > maxSlope) {
                    maxSlope = slope;
                    if (maxSlope >= tanHi) {
                        return 1;
                    }
                }
            }
            if (z0 + dist * tanLo > zMax) {
                break;
            }
        }
        return SunDisk.hiddenFraction(f.elevationDeg, Math.toDegrees(Math.atan(maxSlope)), f.sunRadiusDeg);
    }
}
