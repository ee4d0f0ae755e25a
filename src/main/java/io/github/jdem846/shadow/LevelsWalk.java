package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The lockstep walks ({@link UniformLockstep}, {@link LatLonLockstep}) for several sun elevations at once, the soft
 * sweep's one walk ({@link SunSweep#runLevels}): each line's sample is read once ({@link LockstepBlock}) and feeds
 * one running maximum per elevation, and each cell gets one bit per elevation, decided by exactly the arithmetic of
 * a single-elevation walk (its drop, floor and first-cell test), so bit k is that walk's mask at elevation k.
 *
 * <p>The single-elevation walks are not this walk with one elevation: the loop over elevations in every line and
 * cell cost them 12–22 % (JMH, three alternating pairs, when the lat/lon walks shared their line state); both
 * build on the same {@link SweepCell} pieces, which {@code SoftSweepOneWalkTest} and {@code
 * SunSweepConsistencyTest} hold to the reference walk.
 */
final class LevelsWalk {

    private final SweepGrid g;
    private final SweepCell rule;

    LevelsWalk(SweepGrid g, SweepCell rule) {
        this.g = g;
        this.rule = rule;
    }

    /**
     * Sets bit e of {@code bits[c]} (c row-major over w's window) when the cell between lines kFrom … kTo + 1 is in
     * shadow at the elevation whose tangent is {@code tans[e]}, on a grid with one step length.
     */
    void walkUniform(SweepWindow w, int kFrom, int kTo, double[] tans, int[] bits) {
        LockstepBlock block = LockstepBlock.of(g, w, kFrom, kTo);
        if (block == null) {
            return;
        }
        int lines = block.lines;
        int n = tans.length;
        double step = g.uniformStep;
        double[] drop = new double[n];
        double[] dTan = new double[n];
        double[] floor = new double[n];
        for (int e = 0; e < n; e++) {
            drop[e] = tans[e] * step;
            dTan[e] = step * tans[e];
            floor[e] = g.floor(step, tans[e]);
        }
        double tFirst = rule.tFirst();
        // per line q, elevation e at q·n + e
        double[] best = new double[lines * n];
        double[] prev = new double[lines * n];
        double[] h = new double[lines * n];
        Arrays.fill(best, Double.NEGATIVE_INFINITY);
        Arrays.fill(prev, Double.NEGATIVE_INFINITY);
        if (block.iStart == g.nMaj - 1 && g.upstreamEdgeSample) {
            for (int q = 0; q < lines; q++) {
                for (int e = 0; e < n; e++) {
                    prev[q * n + e] = g.edgeStart(kFrom + q, drop[e]);
                }
            }
        }
        float[] v = g.v;
        double m = g.m;
        int nMin = g.nMin;
        int sj = g.strideJ;
        int jTraced = g.jTraced;
        int outStrideJ = block.outStrideJ;
        double[] zs = block.z;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            block.sample(i);
            for (int q = 0; q < lines; q++) {
                double z = zs[q];
                for (int e = 0, at = q * n; e < n; e++, at++) {
                    double b = best[at];
                    h[at] = b;
                    best[at] = SweepCell.joined(b, prev[at], drop[e]);
                    prev[at] = SweepCell.pending(z, drop[e]);
                }
            }
            if (!block.cells(i)) {
                continue;
            }
            int off = block.off;
            double phi = block.phi;
            boolean inner = block.inner;
            int up = block.up;
            for (int q = block.q0, qEnd = block.q1; q < qEnd; q++) {
                int j = off + q;
                int cell = block.base + sj * j;
                double z0 = v[cell];
                int blocked = 0;
                if (z0 == z0) {
                    boolean edge = j >= jTraced;
                    // the first-cell test of SweepCell.firstStepBlocked, its terms that do not depend on the
                    // elevation once
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
                                : SweepCell.between(h[q * n + e], h[(q + 1) * n + e], phi, floor[e]) > z0;
                        boolean first = closed ? above & SweepCell.rises(lin0 - dTan[e], quad, tFirst)
                                : rule.firstStepBlocked(i, j, cell, z0, inner, up, dTan[e], tFirst, tans[e]);
                        if (lineShadow || first) {
                            blocked |= 1 << e;
                        }
                    }
                }
                bits[block.outBase + outStrideJ * j] = blocked;
            }
        }
    }

    /** {@link #walkUniform} on a grid whose step length changes from row to row ({@link LatLonLockstep}'s walk). */
    void walkLatLon(SweepWindow w, int kFrom, int kTo, double[] tans, int[] bits) {
        LockstepBlock block = LockstepBlock.of(g, w, kFrom, kTo);
        if (block == null) {
            return;
        }
        int lines = block.lines;
        int n = tans.length;
        double[] steps = g.f.metresPerStep;
        double tFirst = rule.tFirst();
        LatLonLines at = new LatLonLines(g, kFrom, lines, block.iStart);
        // per line q, elevation e at q·n + e: as LatLonLockstep's
        double[] best = new double[lines * n];
        double[] twoUp = new double[lines * n];
        double[] oneUp = new double[lines * n];
        double[] h = new double[lines * n];
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
        float[] v = g.v;
        int sj = g.strideJ;
        int jTraced = g.jTraced;
        int outStrideJ = block.outStrideJ;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            block.sample(i);
            at.moveTo(i);
            for (int q = 0; q < lines; q++) {
                double p = pos[q];
                double z = i <= top[q] ? zs[q] : Double.NaN;
                for (int e = 0, k = q * n; e < n; e++, k++) {
                    double tan = tans[e];
                    double b = SweepCell.higher(best[k], twoUp[k]);
                    best[k] = b;
                    h[k] = SweepCell.heightAt(b, tan, p);
                    twoUp[k] = oneUp[k];
                    oneUp[k] = SweepCell.lifted(z, tan, p);
                }
            }
            if (!block.cells(i)) {
                continue;
            }
            int off = block.off;
            double phi = block.phi;
            boolean inner = block.inner;
            int up = block.up;
            for (int q = block.q0, qEnd = block.q1; q < qEnd; q++) {
                int j = off + q;
                int cell = block.base + sj * j;
                double z0 = v[cell];
                int blocked = 0;
                if (z0 == z0) {
                    double step = steps[g.rowOf(i, j)];
                    boolean edge = j >= jTraced;
                    for (int e = 0; e < n; e++) {
                        double tan = tans[e];
                        boolean lineShadow = edge ? rule.rayBlockedToEdge(i, j, z0, tan)
                                : SweepCell.between(h[q * n + e], h[(q + 1) * n + e], phi, g.floor(step, tan)) > z0;
                        if (lineShadow || rule.firstStepBlocked(i, j, cell, z0, inner, up, step * tan, tFirst, tan)) {
                            blocked |= 1 << e;
                        }
                    }
                }
                bits[block.outBase + outStrideJ * j] = blocked;
            }
        }
    }
}
