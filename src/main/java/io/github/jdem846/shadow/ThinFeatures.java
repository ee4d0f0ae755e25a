package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The sweep's thin-features pass ({@link ShadowOptions#thinFeatures()}): each cell also tests one sample of its own
 * ray, at the row where the cells between its two lines (its strip) have the steepest terrain bound as seen from the
 * cell ({@link StripHull}), so that a feature one cell wide, which the lines see only partly, shades its whole lee.
 * {@link Strips} serves a block of strips walked in lockstep ({@link UniformLockstep}); {@link #walkStrip} one strip
 * for the line-by-line walk ({@link ReferenceWalk}).
 */
final class ThinFeatures {

    private final SweepGrid g;

    ThinFeatures(SweepGrid g) {
        this.g = g;
    }

    /** The strips of a lockstep block of {@code n} + 1 lines. */
    Strips strips(int n) {
        return new Strips(n);
    }

    /**
     * The terrain a cell's own ray meets at major index {@code iStar}, on the line position k + φ (φ = the cell's
     * fraction between lines k and k + 1, its offset across the sun direction, the same at every major index),
     * less the ray's rise over the {@code iStar − i} steps: one sample of the cell's own march, read as the lines
     * read theirs. {@code −∞} when there is none (no index, off the grid, no-data).
     */
    double ownSample(int k, int i, double phi, int iStar, double drop) {
        if (iStar < 0) {
            return Double.NEGATIVE_INFINITY;
        }
        double z = ownTerrain(k, phi, iStar);
        return z == z ? z - (iStar - i) * drop : Double.NEGATIVE_INFINITY;
    }

    /** The terrain on line position k + φ at major index iStar (NaN = none). */
    private double ownTerrain(int k, double phi, int iStar) {
        double t = g.pr[iStar] + phi;
        int ft = t >= 1 ? 1 : 0;
        return g.sampleAt(iStar, k + g.pf[iStar] + ft, t - ft);
    }

    /**
     * The strip's terrain bound at major index i, whose strip cell is s: the highest of cells s − 1, s and s + 1
     * ({@link SweepGrid#cellOrNone}), a bound on every sample {@link SweepGrid#sampleAt} takes between positions
     * s − 1 and s + 1; or {@code −∞} when no own-ray sample there can be above the lines' estimate. The lines pass
     * the row at s − 1 + p and s + p (p = the row's fraction); a cell between them samples the two segments through
     * s, whose excess over the chord between the lines' samples is at most p·(1 − p)·(2·z(s) − z(s − 1) − z(s + 1)):
     * nothing when the lines pass through cell centres (p = 0) or when cell s is not above the mean of its
     * neighbours (then the cell's own samples lie on or below the chord, and the interpolated shadow height at least
     * as high). A row with a missing cell is kept.
     */
    double around(int i, int s) {
        return g.pr[i] > 0 ? bound(g.cellOrNone(i, s - 1), g.cellOrNone(i, s), g.cellOrNone(i, s + 1))
                : Double.NEGATIVE_INFINITY;
    }

    /** {@link #around} from the three cells ({@code −∞} = none). */
    private static double bound(double a, double b, double c) {
        boolean all = a > Double.NEGATIVE_INFINITY && b > Double.NEGATIVE_INFINITY && c > Double.NEGATIVE_INFINITY;
        if (all && 2 * b <= a + c) {
            return Double.NEGATIVE_INFINITY;
        }
        double mx = a >= b ? a : b;
        return mx >= c ? mx : c;
    }

    /**
     * Per strip (the cells between two adjacent lines): the hull of its terrain bounds ({@link #around}) two or
     * more major steps upstream, and the highest of bound − i·drop over them: a cell at i below that plus i·drop
     * cannot be shaded by any sample of its own ray, so the hull is not asked. Rows whose bound is {@code −∞} cost
     * one test and nothing else.
     */
    final class Strips {
        private final double[] best;
        private final StripHull[] hull;

        private Strips(int n) {
            best = new double[Math.max(n, 0)];
            hull = new StripHull[best.length];
            Arrays.fill(best, Double.NEGATIVE_INFINITY);
            for (int q = 0; q < hull.length; q++) {
                hull[q] = new StripHull();
            }
        }

        /** Takes row r of every strip of a lockstep block whose first line is kFrom. */
        void take(int r, int kFrom, double drop) {
            int n = best.length;
            if (n == 0 || !(g.pr[r] > 0)) {
                return;   // the lines pass through cell centres: no bound (see around)
            }
            int off = kFrom + g.pf[r] + 1;
            double left = g.cellOrNone(r, off - 1);
            double centre = g.cellOrNone(r, off);
            for (int q = 0; q < n; q++) {
                double right = g.cellOrNone(r, off + q + 1);
                double b = bound(left, centre, right);
                if (b > Double.NEGATIVE_INFINITY) {
                    take(q, r, b, drop);
                }
                left = centre;
                centre = right;
            }
        }

        /** Takes the bound of strip q at row r ({@code −∞}: nothing). */
        void take(int q, int r, double around, double drop) {
            if (around > Double.NEGATIVE_INFINITY) {
                hull[q].push(-r, around, r);
                double key = around - drop * r;
                if (key > best[q]) {
                    best[q] = key;
                }
            }
        }

        /** True when the own-ray sample of strip q's cell at i, chosen by the hull, is above the cell. */
        boolean blocks(int q, int k, int i, double phi, double z0, double drop) {
            if (!(best[q] + drop * i > z0)) {
                return false;
            }
            int iStar = hull[q].tangent(-i, z0);
            return ownSample(k, i, phi, iStar, drop) > z0;
        }
    }

    /**
     * Walks the strip between lines k and k + 1 from iTop down to the window and stores in {@code blocked}, per
     * window column, whether the strip's cell there is shaded by its own-ray sample: with one step length and no
     * curvature by exactly the lockstep walk's arithmetic ({@link Strips}); otherwise with x = the distance along
     * the strip (summed row by row along its cells, into {@code pos}), the rise tan·d and curvature.
     */
    void walkStrip(SweepWindow w, int k, boolean[] blocked, double[] pos) {
        int wi0 = w.wi0();
        int wi1 = w.wi1();
        int nMin = g.nMin;
        if (g.f.curvature == 0 && g.uniform()) {
            double drop = g.f.tanElevation * g.uniformStep;
            Strips one = new Strips(1);
            int rTop = Math.min(w.iTop(), g.nMaj - 1);
            for (int i = w.iTop(); i >= wi0; i--) {
                int r = i + 2;
                if (r <= rTop) {
                    one.take(0, r, around(r, g.stripCell(k, r)), drop);
                }
                if (i <= wi1) {
                    int j = g.stripCell(k, i);
                    double z0 = j >= 0 && j < nMin ? g.v[g.idx(i, j)] : Double.NaN;
                    double phi = g.pr[i] > 0 ? 1 - g.pr[i] : 0;
                    blocked[i - wi0] = z0 == z0 && one.blocks(0, k, i, phi, z0, drop);
                }
            }
            return;
        }
        double tan = g.f.tanElevation;
        double bc = g.f.curvature;
        StripHull hull = new StripHull();
        double best = Double.NEGATIVE_INFINITY;     // max of bound + tan·x over the hull's points
        double prevVal = Double.NEGATIVE_INFINITY;
        double prevAround = Double.NEGATIVE_INFINITY;
        for (int i = w.iTop(); i >= wi0; i--) {
            int j = g.stripCell(k, i);
            int at = i - wi0;
            pos[at] = i == w.iTop() ? 0
                    : pos[at + 1] + g.f.metresPerStep[g.rowOf(i, Math.max(0, Math.min(nMin - 1, j)))];
            double x = pos[at];
            if (i <= wi1) {
                double z0 = j >= 0 && j < nMin ? g.v[g.idx(i, j)] : Double.NaN;
                boolean b = false;
                if (z0 == z0 && best - tan * x > z0) {
                    int iStar = hull.tangent(x, z0);
                    double phi = g.pr[i] > 0 ? 1 - g.pr[i] : 0;
                    double z = ownTerrain(k, phi, iStar);
                    double dist = x - pos[iStar - wi0];
                    b = z == z && z - bc * dist * dist > z0 + dist * tan;
                }
                blocked[at] = b;
            }
            if (prevAround > Double.NEGATIVE_INFINITY) {
                hull.push(pos[at + 1], prevAround, i + 1);
                if (prevVal > best) {
                    best = prevVal;
                }
            }
            double a = around(i, j);
            prevAround = a;
            prevVal = a + tan * x;
        }
    }
}
