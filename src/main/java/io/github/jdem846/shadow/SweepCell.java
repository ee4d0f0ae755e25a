package io.github.jdem846.shadow;

/**
 * The rule that decides one cell of the sweep, in one place for every walk: the lines' running maxima, the test of a
 * cell against the shadow height between its two lines, the test of its first step on the bilinear surface and the
 * trace of a ray that leaves through the file's edge. The walks' hot loops call the static pieces, small enough for
 * the JIT to inline; they do not wrap a whole cell in one method (see {@link UniformLockstep}).
 */
final class SweepCell {

    private final SweepGrid g;

    SweepCell(SweepGrid g) {
        this.g = g;
    }

    // --- running maximum on a grid with one step length: values relative to the current major index ---

    /**
     * The running maximum one major step on: the higher of {@code best} and the sample that joins it ({@link
     * #pending}), lowered by one step's drop. Never NaN: a comparison, not Math.max (see Clamp).
     */
    static double joined(double best, double pending, double drop) {
        return (best >= pending ? best : pending) - drop;
    }

    /** A line's sample z as it joins the running maximum one step later: z − drop, {@code −∞} for NaN (no terrain). */
    static double pending(double z, double drop) {
        return z == z ? z - drop : Double.NEGATIVE_INFINITY;
    }

    /**
     * Line state k one major step on, whose sample there is z: its shadow height h[k] is the running maximum best[k]
     * of the samples two or more steps upstream, and the sample one step upstream, prev[k] ({@link #pending}), joins
     * it.
     */
    static void advance(double[] best, double[] prev, double[] h, int k, double z, double drop) {
        double b = best[k];
        h[k] = b;
        best[k] = joined(b, prev[k], drop);
        prev[k] = pending(z, drop);
    }

    // --- running maximum on a grid whose step length changes from row to row: values of z + tan·P ---

    /** A line's sample z at distance P from the line's top as it joins the running maximum; {@code −∞} for NaN. */
    static double lifted(double z, double tan, double p) {
        return z == z ? z + tan * p : Double.NEGATIVE_INFINITY;
    }

    /** The running maximum with a sample joining ({@link #lifted}). */
    static double higher(double best, double joining) {
        return joining > best ? joining : best;
    }

    /** The shadow height at distance P from the line's top, from the running maximum of z + tan·P. */
    static double heightAt(double best, double tan, double p) {
        return best - tan * p;
    }

    /**
     * Line state k at distance P from the line's top, whose sample there is z (NaN = none): the sample two steps
     * upstream, twoUp[k], joins the running maximum best[k] ({@link #higher}), h[k] is the shadow height, and z
     * waits two steps in oneUp[k] ({@link #lifted}).
     */
    static void climb(double[] best, double[] twoUp, double[] oneUp, double[] h, int k, double z, double tan,
                      double p) {
        double b = higher(best[k], twoUp[k]);
        best[k] = b;
        h[k] = heightAt(b, tan, p);
        twoUp[k] = oneUp[k];
        oneUp[k] = lifted(z, tan, p);
    }

    // --- the cell against its two lines ---

    /**
     * A cell's shadow height between its two lines, {@code phi} of the way from line a to line b. A line below
     * {@code floor} counts as having no terrain, so the other line's height is taken whole: the same answer
     * whether or not a window's halo reaches that line's distant samples.
     */
    static double between(double ha, double hb, double phi, double floor) {
        if (phi == 0 || !(hb >= floor)) {
            return ha;
        }
        if (!(ha >= floor)) {
            return hb;
        }
        return ha + (hb - ha) * phi;
    }

    // --- the first step on the bilinear surface: terrain − ray along it is t·(lin + quad·t) ---

    /** lin + dTan: the first step's linear term before the ray's rise (cell z0, its neighbours up, across). */
    static double slope(double z0, double z10, double z01, double m) {
        return (z10 - z0) + (z01 - z0) * m;
    }

    /** The first step's quadratic term (without curvature): the bilinear cell's twist. */
    static double bend(double z0, double z10, double z01, double z11, double m) {
        return (z11 - z10 - z01 + z0) * m;
    }

    /** True when a corner of the first step's bilinear cell is above z0 (else the surface never exceeds it). */
    static boolean above(double z0, double z10, double z01, double z11) {
        return z10 > z0 | z01 > z0 | z11 > z0;
    }

    /**
     * True when terrain − ray, t·(lin + quad·t), is positive at a first-step sample: linear in t after dividing by
     * t > 0, so decided at the first sample {@code tFirst} and the last (t = 1).
     */
    static boolean rises(double lin, double quad, double tFirst) {
        return lin + quad * tFirst > 0 | lin + quad > 0;
    }

    /**
     * Offset of the first first-step sample in eighths: eighths up to one cell on the bilinear surface, else just
     * the one-cell sample. With nearest sampling the eighths would meet the next cell's block from t = ½ on while
     * the ray is still only half a step up, shading cells that the nearest march leaves lit.
     */
    int firstSample() {
        return g.firstCellTest && g.bilinear ? 1 : SweepGrid.SUB_STEPS;
    }

    /** {@link #firstSample} as a fraction of the step. */
    double tFirst() {
        return (double) firstSample() / SweepGrid.SUB_STEPS;
    }

    /**
     * {@link #localBlocked} for the lockstep loops: the closed form ({@link #rises}) from the four corners; a no-data
     * corner makes lin + quad NaN (also when m = 0), and then, or at the last row or column, localBlocked decides.
     *
     * @param up  the flat index of frame cell (i + 1, 0) when {@code inner}
     * @param tan the tangent of the sun's elevation (dTan = the step's length × tan)
     */
    boolean firstStepBlocked(int i, int j, int cell, double z0, boolean inner, int up, double dTan, double tFirst,
                             double tan) {
        if (!inner || j + 1 >= g.nMin) {
            return localBlocked(i, j, z0, tan);
        }
        float[] v = g.v;
        int sj = g.strideJ;
        int u = up + sj * j;
        double z10 = v[u];
        double z01 = v[cell + sj];
        double z11 = v[u + sj];
        double lin = slope(z0, z10, z01, g.m) - dTan;
        double quad = bend(z0, z10, z01, z11, g.m);
        double end = lin + quad;
        if (end == end) {
            return above(z0, z10, z01, z11) & rises(lin, quad, tFirst);
        }
        return localBlocked(i, j, z0, tan);
    }

    /** True when the ray from cell (i, j) toward a sun whose elevation has the tangent {@code tan} is blocked within
     * its first major step: in closed form on a whole bilinear cell, else sample by sample. */
    boolean localBlocked(int i, int j, double z0, double tan) {
        double d = g.f.metresPerStep[g.rowOf(i, j)];
        double bc = g.f.curvature;
        if (g.bilinear && i + 1 < g.nMaj && j + 1 < g.nMin) {
            double z10 = g.v[g.idx(i + 1, j)];
            double z01 = g.v[g.idx(i, j + 1)];
            double z11 = g.v[g.idx(i + 1, j + 1)];
            if (z10 == z10 && z01 == z01 && z11 == z11) {
                if (!above(z0, z10, z01, z11)) {
                    return false;
                }
                double lin = slope(z0, z10, z01, g.m) - d * tan;
                double quad = bend(z0, z10, z01, z11, g.m) - bc * d * d;
                return rises(lin, quad, tFirst());
            }
        }
        for (int q = firstSample(); q <= SweepGrid.SUB_STEPS; q++) {
            double t = (double) q / SweepGrid.SUB_STEPS;
            double fi = i + t;
            double fj = j + g.m * t;
            if (fi > g.nMaj - 0.5 || fj > g.nMin - 0.5) {
                return false;
            }
            double z = g.frameSample(i, j, t);
            double dist = t * d;
            if (z == z && z - bc * dist * dist > z0 + dist * tan) {
                return true;
            }
        }
        return false;
    }

    /**
     * For a cell j ≥ {@link SweepGrid#jTraced}: true when its own ray, after the first step ({@link #localBlocked}),
     * meets the bilinear surface before it leaves the grid through the file's side edge. It is marched as {@code
     * exact} marches, in eighth steps, so these cells get the reference's answer; there are at most about m·S + 1 of
     * them per major index, each at most 8·S samples.
     */
    boolean rayBlockedToEdge(int i, int j, double z0, double tan) {
        double d = g.f.metresPerStep[g.rowOf(i, j)];
        double bc = g.f.curvature;
        double room = g.cellHi - j + 0.5;
        int nMaj = g.nMaj;
        for (int q = SweepGrid.SUB_STEPS + 1; ; q++) {
            double t = (double) q / SweepGrid.SUB_STEPS;
            double y = g.m * t;
            if (y > room || i + t > nMaj - 0.5) {
                return false;
            }
            // bilinear in the frame: major cells ia, ia + 1 (clamped at the last), minor cells ja, ja + 1 (clamped
            // at the last, the outer half cell); a no-data corner falls back to the renormalising sampler
            int ia = i + q / SweepGrid.SUB_STEPS;
            double wa = (double) (q % SweepGrid.SUB_STEPS) / SweepGrid.SUB_STEPS;
            int ib = Math.min(ia + 1, nMaj - 1);
            int jo = (int) y;
            double wb = y - jo;
            int ja = j + jo;
            int jb = Math.min(ja + 1, g.cellHi);
            double z00 = g.v[g.idx(ia, ja)];
            double z10 = g.v[g.idx(ib, ja)];
            double z01 = g.v[g.idx(ia, jb)];
            double z11 = g.v[g.idx(ib, jb)];
            double z = (z00 + (z10 - z00) * wa) * (1 - wb) + (z01 + (z11 - z01) * wa) * wb;
            if (z != z) {
                z = g.frameSample(i, j, t);
            }
            double dist = t * d;
            if (z == z && z - bc * dist * dist > z0 + dist * tan) {
                return true;
            }
        }
    }
}
