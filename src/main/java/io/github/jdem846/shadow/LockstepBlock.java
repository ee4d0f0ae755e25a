package io.github.jdem846.shadow;

/**
 * A block of lines kFrom … kTo + 1 walked in lockstep, one major index at a time from the sun's side (the lockstep
 * walks {@link UniformLockstep}, {@link LatLonLockstep}, {@link LevelsWalk}): the major indices it walks, its lines'
 * samples at the current one ({@link #sample}; or {@link #sampleEdges} for a walk that reads the direct run in its
 * own loop) and the cells between its lines there ({@link #cells}). At one major
 * index every line samples the same fraction between the same two minor cells, so the samples of all lines (and the
 * cells between them) are neighbours in memory: one contiguous run of the row when the sun is north or south
 * (y-major), a few cache lines reused for 16 columns otherwise.
 */
final class LockstepBlock {

    private final SweepGrid g;
    /** The window whose cells the block computes. */
    final SweepWindow w;
    final int kFrom;
    /** The number of lines, kTo − kFrom + 2; cells lie between lines q and q + 1, q = 0 … lines − 2. */
    final int lines;
    /** The walk runs from major index iStart down to iEnd. */
    final int iStart;
    final int iEnd;
    /** The samples of the lines at the current major index ({@link SweepGrid#lineSample}; NaN = none). */
    final double[] z;
    /** The index stride of one minor step in the window's output. */
    final int outStrideJ;

    /** The direct run at the current major index, set by {@link #sampleEdges}. */
    int direct0;
    int direct1;
    int at0;

    // the cells between the lines at the current major index, set by cells(i)
    /** Minor index of the cell between lines q and q + 1 is off + q; it lies phi of the way from q to q + 1. */
    int off;
    double phi;
    /** The cells q0 … q1 − 1 are in the window (exclusive end). */
    int q0;
    int q1;
    /** Output index of frame cell (i, 0), and the flat index of terrain cell (i, 0). */
    int outBase;
    int base;
    /** True when major index i + 1 is on the grid; then up = the flat index of frame cell (i + 1, 0). */
    boolean inner;
    int up;

    private LockstepBlock(SweepGrid g, SweepWindow w, int kFrom, int kTo, int iStart, int iEnd) {
        this.g = g;
        this.w = w;
        this.kFrom = kFrom;
        this.lines = kTo - kFrom + 2;
        this.iStart = iStart;
        this.iEnd = iEnd;
        this.z = new double[lines];
        this.outStrideJ = g.rj * w.win().width() + g.cj;
    }

    /** The block of lines kFrom … kTo + 1 of window w, or null when it meets no cell of the window. */
    static LockstepBlock of(SweepGrid g, SweepWindow w, int kFrom, int kTo) {
        int iStart = w.iTop();
        int iEnd = w.wi0();
        double m = g.m;
        if (m > 0) {
            iStart = (int) Math.min(iStart, Math.floor((g.nMin - kFrom) / m) + 1);
            iEnd = (int) Math.max(iEnd, Math.ceil((w.wj0() - kTo - 2) / m) - 1);
        } else if (kTo + 1 < -1 || kFrom > g.nMin - 1) {
            return null;
        }
        return iStart < iEnd ? null : new LockstepBlock(g, w, kFrom, kTo, iStart, iEnd);
    }

    /**
     * Reads every line's sample at major index i into {@link #z}: {@link #sampleEdges} and then the direct run
     * straight from the array. For the multi-elevation walk, whose per-line work (a loop over the elevations)
     * outweighs the extra pass; the single-elevation walks read the direct run in their own loops (see {@link
     * UniformLockstep}).
     */
    void sample(int i) {
        sampleEdges(i);
        if (direct0 >= direct1) {
            return;
        }
        double[] zs = z;
        float[] v = g.v;
        int sj = g.strideJ;
        int at = at0;
        double fr = g.pr[i];
        // exclusive bounds (q < qEnd) avoid C2's loop-limit-check deoptimisations
        if (fr == 0) {
            for (int q = direct0, qEnd = direct1; q < qEnd; q++, at += sj) {
                zs[q] = v[at];
            }
        } else {
            double za = v[at];
            for (int q = direct0, qEnd = direct1; q < qEnd; q++) {
                at += sj;
                double zb = v[at];
                zs[q] = SweepGrid.mix(za, zb, fr);
                za = zb;
            }
        }
    }

    /**
     * Sets the direct run at major index i, the lines {@link #direct0} … {@link #direct1} − 1 whose two minor cells
     * are both on the grid (line direct0 reads from flat index {@link #at0} on, one minor stride per line), and reads
     * the samples of the other lines, near the grid's minor edges, into {@link #z} ({@link SweepGrid#lineSample}).
     */
    void sampleEdges(int i) {
        int pfi = g.pf[i];
        int qa = Math.max(0, -kFrom - pfi);
        int qb = Math.min(lines - 1, g.cellHi - 1 - kFrom - pfi);
        int d0 = Math.min(qa, lines);
        int d1 = Math.max(qb + 1, d0);
        double[] zs = z;
        for (int q = 0; q < d0; q++) {
            zs[q] = g.lineSample(kFrom + q, i);
        }
        for (int q = d1; q < lines; q++) {
            zs[q] = g.lineSample(kFrom + q, i);
        }
        direct0 = d0;
        direct1 = d1;
        at0 = g.baseI[i] + g.strideJ * (kFrom + qa + pfi);
    }

    /**
     * Sets the fields that place the cells between the lines at major index i; false when none of them is in the
     * window. Each walk copies them into locals and runs its own loop over the cells, so that the cell's evaluation
     * stays inline in that loop: as one method per cell it was up to 25 % slower (see {@link UniformLockstep}).
     */
    boolean cells(int i) {
        if (i > w.wi1()) {
            return false;
        }
        double fr = g.pr[i];
        phi = fr > 0 ? 1 - fr : 0;
        off = kFrom + g.pf[i] + (fr > 0 ? 1 : 0);
        q0 = Math.max(0, w.wj0() - off);
        q1 = Math.min(lines - 2, w.wj1() - off) + 1;
        if (q0 >= q1) {
            return false;
        }
        CellWindow win = w.win();
        outBase = (g.r0 + g.ri * i - win.row()) * win.width() + (g.c0 + g.ci * i - win.col());
        base = g.baseI[i];
        inner = i + 1 < g.nMaj;
        up = inner ? g.baseI[i + 1] : 0;
        return true;
    }
}
