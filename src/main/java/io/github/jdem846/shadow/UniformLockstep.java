package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The sweep's lines for hard shadows on the bilinear surface of a grid with one step length and no curvature
 * (projected grids), walked in lockstep ({@link LockstepBlock}): each line carries the running maximum of {@link
 * ReferenceWalk}'s walk for such grids, and the cells between two lines are evaluated as soon as both have reached
 * them, with their own-ray sample when thin features are on ({@link ThinFeatures}). The mask is bit-identical to
 * {@link ReferenceWalk}'s.
 */
final class UniformLockstep {

    private final SweepGrid g;
    private final SweepCell rule;
    /** Null without thin features. */
    private final ThinFeatures thin;

    UniformLockstep(SweepGrid g, SweepCell rule, ThinFeatures thin) {
        this.g = g;
        this.rule = rule;
        this.thin = thin;
    }

    /** Computes the cells between the block's lines into its window's output. */
    void walk(LockstepBlock block) {
        SweepWindow w = block.w;
        int kFrom = block.kFrom;
        int lines = block.lines;
        double tan = g.f.tanElevation;
        double drop = tan * g.uniformStep;
        double dTan = g.uniformStep * tan;
        double tFirst = rule.tFirst();
        double floor = g.uniformFloor;
        double[] best = new double[lines];
        double[] prev = new double[lines];
        double[] h = new double[lines];
        Arrays.fill(best, Double.NEGATIVE_INFINITY);
        Arrays.fill(prev, Double.NEGATIVE_INFINITY);
        boolean thinFeatures = thin != null;
        ThinFeatures.Strips strips = thinFeatures ? thin.strips(lines - 1) : null;
        int rTop = Math.min(w.iTop(), g.nMaj - 1);
        if (block.iStart == g.nMaj - 1 && g.upstreamEdgeSample) {
            for (int q = 0; q < lines; q++) {
                prev[q] = g.edgeStart(kFrom + q, drop);
            }
        }
        float[] v = g.v;
        float[] out = w.out();
        int outStrideJ = block.outStrideJ;
        int sj = g.strideJ;
        int jTraced = g.jTraced;
        double[] zs = block.z;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            // The direct run is read in this walk's own loop, fused with the running maxima: reading all samples
            // first (LockstepBlock.sample) and then updating the lines was 15–17 % slower (JMH sweep, fractal and
            // mirrored 2048², sun 5°, three alternating single-fork runs). Exclusive bounds (q < d1) avoid C2's
            // loop-limit-check deoptimisations.
            block.sampleEdges(i);
            int d0 = block.direct0;
            int d1 = block.direct1;
            for (int q = 0; q < d0; q++) {
                SweepCell.advance(best, prev, h, q, zs[q], drop);
            }
            if (d0 < d1) {
                int at = block.at0;
                double fr = g.pr[i];
                if (fr == 0) {
                    for (int q = d0; q < d1; q++, at += sj) {
                        SweepCell.advance(best, prev, h, q, v[at], drop);
                    }
                } else {
                    double za = v[at];
                    for (int q = d0; q < d1; q++) {
                        at += sj;
                        double zb = v[at];
                        SweepCell.advance(best, prev, h, q, SweepGrid.mix(za, zb, fr), drop);
                        za = zb;
                    }
                }
            }
            for (int q = d1; q < lines; q++) {
                SweepCell.advance(best, prev, h, q, zs[q], drop);
            }
            if (thinFeatures && i + 2 <= rTop) {
                strips.take(i + 2, kFrom, drop);
            }
            if (!block.cells(i)) {
                continue;
            }
            int off = block.off;
            double phi = block.phi;
            int q0 = block.q0;
            int q1 = block.q1;
            int outBase = block.outBase;
            int base = block.base;
            boolean inner = block.inner;
            int up = block.up;
            // cells whose ray leaves through the file's exit edge within a few steps (j ≥ jTraced) are traced
            // in a loop of their own, so that the common loop holds no ray march
            int qEdge = jTraced == Integer.MAX_VALUE ? q1 : (int) Math.max(q0, Math.min(q1, (long) jTraced - off));
            // The cell's evaluation stays inline in these loops, built from SweepCell's small static pieces: as
            // one method per cell it was up to 25 % slower in JMH (RayTraceBenchmark.sweep). Exclusive bounds as
            // above.
            for (int q = q0; q < qEdge; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    boolean shadow = SweepCell.between(h[q], h[q + 1], phi, floor) > z0
                            || thinFeatures && strips.blocks(q, kFrom + q, i, phi, z0, drop)
                            || rule.firstStepBlocked(i, j, cell, z0, inner, up, dTan, tFirst, tan);
                    result = shadow ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
            for (int q = qEdge; q < q1; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    boolean shadow = rule.rayBlockedToEdge(i, j, z0, tan)
                            || rule.firstStepBlocked(i, j, cell, z0, inner, up, dTan, tFirst, tan);
                    result = shadow ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
        }
    }
}
