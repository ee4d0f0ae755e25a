package io.github.jdem846.shadow;

/**
 * The distances along the lines of a lockstep block on a grid whose step length changes from row to row (lat/lon
 * grids): per line its top on the whole grid (P = 0 there) and P at the current major index, summed step by step
 * in the order {@link ReferenceWalk} sums it, so that the lockstep walks ({@link LatLonLockstep}, {@link
 * LevelsWalk}) reproduce its numbers bit for bit.
 */
final class LatLonLines {

    private final SweepGrid g;
    private final int kFrom;
    /** Per line: P at the current major index, and its top. */
    final double[] pos;
    final int[] top;
    /**
     * Per line: the file's upstream outer edge sample half a step beyond its top ({@link SweepGrid#edgeSample}, NaN
     * = none) and its P; it joins the running maximum as a sample at i + 2.
     */
    final double[] edgeZ;
    final double[] edgeP;

    /** The lines kFrom … kFrom + lines − 1 of a walk that starts at major index iStart. */
    LatLonLines(SweepGrid g, int kFrom, int lines, int iStart) {
        this.g = g;
        this.kFrom = kFrom;
        pos = new double[lines];
        top = new int[lines];
        edgeZ = new double[lines];
        edgeP = new double[lines];
        double[] steps = g.f.metresPerStep;
        boolean edgeHalf = iStart == g.nMaj - 1 && g.upstreamEdgeSample;
        for (int q = 0; q < lines; q++) {
            int k = kFrom + q;
            int t = g.lineTop(k);
            double p = 0;
            for (int i = t - 1; i > iStart; i--) {           // a window's halo cuts the line below its top
                p += steps[g.rowOf(i, g.lineRow(k, i))];
            }
            top[q] = t;
            pos[q] = p;
            boolean half = edgeHalf && t == g.nMaj - 1;
            edgeZ[q] = half ? g.edgeSample(k) : Double.NaN;
            edgeP[q] = half ? g.edgeDistance(k) : 0;
        }
    }

    /** Moves every line to major index i, one step down from the last: P grows by the line's step there. */
    void moveTo(int i) {
        double[] steps = g.f.metresPerStep;
        int lines = pos.length;
        if (g.f.xMajor) {
            // the row of line kFrom + q is lineRow(kFrom + q, i) = clamp(near + q)
            int near = kFrom + g.pf[i] + (g.pr[i] >= 0.5 ? 1 : 0);
            int last = g.nMin - 1;
            for (int q = 0; q < lines; q++) {
                if (i < top[q]) {
                    pos[q] += steps[g.r0 + g.rj * Math.max(0, Math.min(last, near + q))];
                }
            }
        } else {
            double step = steps[g.r0 + g.ri * i];                   // the step of every line when y-major
            for (int q = 0; q < lines; q++) {
                if (i < top[q]) {
                    pos[q] += step;
                }
            }
        }
    }
}
