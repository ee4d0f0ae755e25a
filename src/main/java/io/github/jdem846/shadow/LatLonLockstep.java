package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The sweep's lines for hard shadows on the bilinear surface of a grid whose step length changes from row to row
 * (lat/lon grids), without curvature or thin features, walked in lockstep ({@link LockstepBlock}) with the
 * arithmetic of {@link ReferenceWalk} for such grids: a running maximum of z + tan·P over each line's samples from
 * two steps upstream on (P = the distance from the line's top, {@link LatLonLines}), and the cells between them
 * evaluated with their own row's step and floor, so the mask is bit-identical to the line-by-line walk's.
 */
final class LatLonLockstep {

    private final SweepGrid g;
    private final SweepCell rule;

    LatLonLockstep(SweepGrid g, SweepCell rule) {
        this.g = g;
        this.rule = rule;
    }

    /** Computes the cells between the block's lines into its window's output. */
    void walk(LockstepBlock block) {
        int lines = block.lines;
        double tan = g.f.tanElevation;
        double[] steps = g.f.metresPerStep;
        double[] floorOfRow = g.floorOfRow;
        double tFirst = rule.tFirst();
        LatLonLines at = new LatLonLines(g, block.kFrom, lines, block.iStart);
        // per line: the running maximum of z + tan·P, the two samples still to join it, the shadow height
        double[] best = new double[lines];
        double[] twoUp = new double[lines];
        double[] oneUp = new double[lines];
        double[] h = new double[lines];
        Arrays.fill(best, Double.NEGATIVE_INFINITY);
        Arrays.fill(twoUp, Double.NEGATIVE_INFINITY);
        for (int q = 0; q < lines; q++) {
            oneUp[q] = SweepCell.lifted(at.edgeZ[q], tan, at.edgeP[q]);
        }
        double[] pos = at.pos;
        int[] top = at.top;
        double[] zs = block.z;
        float[] v = g.v;
        float[] out = block.w.out();
        int outStrideJ = block.outStrideJ;
        int sj = g.strideJ;
        int jTraced = g.jTraced;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            // the direct run read in this loop, fused with the running maxima, and exclusive bounds: see
            // UniformLockstep
            block.sampleEdges(i);
            at.moveTo(i);
            int d0 = block.direct0;
            int d1 = block.direct1;
            for (int q = 0; q < d0; q++) {
                SweepCell.climb(best, twoUp, oneUp, h, q, i <= top[q] ? zs[q] : Double.NaN, tan, pos[q]);
            }
            if (d0 < d1) {
                int k = block.at0;
                double fr = g.pr[i];
                double za = v[k];
                for (int q = d0; q < d1; q++) {
                    k += sj;
                    double zb = v[k];
                    double z = fr == 0 ? za : SweepGrid.mix(za, zb, fr);
                    SweepCell.climb(best, twoUp, oneUp, h, q, i <= top[q] ? z : Double.NaN, tan, pos[q]);
                    za = zb;
                }
            }
            for (int q = d1; q < lines; q++) {
                SweepCell.climb(best, twoUp, oneUp, h, q, i <= top[q] ? zs[q] : Double.NaN, tan, pos[q]);
            }
            if (!block.cells(i)) {
                continue;
            }
            int off = block.off;
            double phi = block.phi;
            int outBase = block.outBase;
            int base = block.base;
            boolean inner = block.inner;
            int up = block.up;
            // inline cell evaluation and exclusive bound: see UniformLockstep
            for (int q = block.q0, qEnd = block.q1; q < qEnd; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    int row = g.rowOf(i, j);
                    boolean shadow = j >= jTraced ? rule.rayBlockedToEdge(i, j, z0, tan)
                            : SweepCell.between(h[q], h[q + 1], phi, floorOfRow[row]) > z0;
                    result = shadow || rule.firstStepBlocked(i, j, cell, z0, inner, up, steps[row] * tan, tFirst, tan)
                            ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
        }
    }
}
