package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The lockstep walks ({@link UniformLockstep}, {@link LatLonLockstep}) for several sun elevations at once, the soft
 * sweep's one walk ({@link SunSweep#runLevels}): each line's sample is read once ({@link LockstepBlock}) and feeds
 * one running maximum per elevation, and each cell gets one bit per elevation, decided by exactly the arithmetic of
 * a single-elevation walk (its drop, floor and first-cell test), so bit e is that walk's mask at elevation e.
 *
 * <p>The single-elevation walks keep their own loops over the lines' running maxima (a few lines each, on the same
 * {@link SweepCell} pieces): an interface over the two kinds of line state, one elevation or several, cost the
 * single-elevation lat/lon walk 12–22 % (JMH, three alternating pairs). {@code SoftSweepOneWalkTest} holds this
 * walk to them, level by level.
 */
final class LevelsWalk {

    private final SweepGrid g;
    private final SweepCell rule;
    private final double[] tans;
    private final int n;
    private final double tFirst;
    /**
     * Per table row and elevation e, at row·n + e: a step's rise, step·tan, and the floor ({@link SweepGrid#floor}).
     * One table row on a grid with one step length (rowMul = 0), else one per grid row (rowMul = 1).
     */
    private final double[] rise;
    private final double[] floor;
    private final int rowMul;

    /** The walk for the elevations whose tangents are {@code tans}. */
    LevelsWalk(SweepGrid g, SweepCell rule, double[] tans) {
        this.g = g;
        this.rule = rule;
        this.tans = tans;
        this.n = tans.length;
        this.tFirst = rule.tFirst();
        boolean uniform = g.uniform();
        double[] steps = g.f.metresPerStep;
        int rows = uniform ? 1 : steps.length;
        rowMul = uniform ? 0 : 1;
        rise = new double[rows * n];
        floor = new double[rows * n];
        for (int r = 0; r < rows; r++) {
            double step = uniform ? g.uniformStep : steps[r];
            for (int e = 0; e < n; e++) {
                rise[r * n + e] = step * tans[e];
                floor[r * n + e] = g.floor(step, tans[e]);
            }
        }
    }

    /**
     * Sets bit e of {@code bits[c]} (c row-major over the block's window) when the cell c between the block's lines
     * is in shadow at the elevation whose tangent is {@code tans[e]}.
     */
    void walk(LockstepBlock block, int[] bits) {
        double[] h = new double[block.lines * n];      // per line q, elevation e at q·n + e
        if (g.uniform()) {
            walkUniform(block, h, bits);
        } else {
            walkLatLon(block, h, bits);
        }
    }

    /** The lines' running maxima on a grid with one step length: {@link UniformLockstep}'s, per elevation. */
    private void walkUniform(LockstepBlock block, double[] h, int[] bits) {
        int lines = block.lines;
        double[] drop = rise;                          // table row 0: uniformStep·tan
        double[] best = new double[lines * n];
        double[] prev = new double[lines * n];
        Arrays.fill(best, Double.NEGATIVE_INFINITY);
        Arrays.fill(prev, Double.NEGATIVE_INFINITY);
        if (block.iStart == g.nMaj - 1 && g.upstreamEdgeSample) {
            for (int q = 0; q < lines; q++) {
                for (int e = 0; e < n; e++) {
                    prev[q * n + e] = g.edgeStart(block.kFrom + q, drop[e]);
                }
            }
        }
        double[] zs = block.z;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            block.sample(i);
            for (int q = 0; q < lines; q++) {
                double z = zs[q];
                for (int e = 0, at = q * n; e < n; e++, at++) {
                    SweepCell.advance(best, prev, h, at, z, drop[e]);
                }
            }
            cells(block, i, h, bits);
        }
    }

    /** The lines' running maxima on a grid with a step length per row: {@link LatLonLockstep}'s, per elevation. */
    private void walkLatLon(LockstepBlock block, double[] h, int[] bits) {
        int lines = block.lines;
        LatLonLines at = new LatLonLines(g, block.kFrom, lines, block.iStart);
        double[] best = new double[lines * n];
        double[] twoUp = new double[lines * n];
        double[] oneUp = new double[lines * n];
        Arrays.fill(best, Double.NEGATIVE_INFINITY);
        Arrays.fill(twoUp, Double.NEGATIVE_INFINITY);
        for (int q = 0; q < lines; q++) {
            for (int e = 0; e < n; e++) {
                oneUp[q * n + e] = SweepCell.lifted(at.edgeZ[q], tans[e], at.edgeP[q]);
            }
        }
        double[] pos = at.pos;
        int[] top = at.top;
        double[] zs = block.z;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            block.sample(i);
            at.moveTo(i);
            for (int q = 0; q < lines; q++) {
                double p = pos[q];
                double z = i <= top[q] ? zs[q] : Double.NaN;
                for (int e = 0, k = q * n; e < n; e++, k++) {
                    SweepCell.climb(best, twoUp, oneUp, h, k, z, tans[e], p);
                }
            }
            cells(block, i, h, bits);
        }
    }

    /** The cells between the lines at major index i, whose lines' shadow heights are {@code h}. */
    private void cells(LockstepBlock block, int i, double[] h, int[] bits) {
        if (!block.cells(i)) {
            return;
        }
        float[] v = g.v;
        double m = g.m;
        int nMin = g.nMin;
        int sj = g.strideJ;
        int jTraced = g.jTraced;
        int off = block.off;
        double phi = block.phi;
        boolean inner = block.inner;
        int up = block.up;
        int rowI = rowMul * (g.r0 + g.ri * i);         // the table row of cell j: rowI + rowJ·j
        int rowJ = rowMul * g.rj;
        // inline cell evaluation and exclusive bound: see UniformLockstep
        for (int q = block.q0, qEnd = block.q1; q < qEnd; q++) {
            int j = off + q;
            int cell = block.base + sj * j;
            double z0 = v[cell];
            int blocked = 0;
            if (z0 == z0) {
                int t = (rowI + rowJ * j) * n;
                boolean edge = j >= jTraced;
                // the first-cell test of SweepCell.firstStepBlocked, its terms that do not depend on the elevation
                // once
                boolean closed = inner && j + 1 < nMin;
                boolean above = false;
                double lin0 = 0;
                double quad = 0;
                if (closed) {
                    int u = up + sj * j;
                    double z10 = v[u];
                    double z01 = v[cell + sj];
                    double z11 = v[u + sj];
                    lin0 = SweepCell.slope(z0, z10, z01, m);
                    quad = SweepCell.bend(z0, z10, z01, z11, m);
                    closed = lin0 + quad == lin0 + quad;       // no no-data corner
                    above = SweepCell.above(z0, z10, z01, z11);
                }
                for (int e = 0; e < n; e++) {
                    boolean lineShadow = edge ? rule.rayBlockedToEdge(i, j, z0, tans[e])
                            : SweepCell.between(h[q * n + e], h[(q + 1) * n + e], phi, floor[t + e]) > z0;
                    boolean first = closed ? above & SweepCell.rises(lin0 - rise[t + e], quad, tFirst)
                            : rule.firstStepBlocked(i, j, cell, z0, inner, up, rise[t + e], tFirst, tans[e]);
                    if (lineShadow || first) {
                        blocked |= 1 << e;
                    }
                }
            }
            bits[block.outBase + block.outStrideJ * j] = blocked;
        }
    }
}
