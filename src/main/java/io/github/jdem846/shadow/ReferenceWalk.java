package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The sweep's line-by-line walk, for every case and the reference of the lockstep walks' tests: each line is walked
 * on its own from the top of the window's halo down to the window ({@link #walkLine}), keeping its shadow height at
 * each window column, and then the cells between two lines are evaluated ({@link #band}). It alone handles Earth
 * curvature (an upper envelope of parabolas instead of a running maximum) and nearest sampling.
 */
final class ReferenceWalk {

    private final SweepGrid g;
    private final SweepCell rule;
    /** Null without thin features. */
    private final ThinFeatures thin;

    ReferenceWalk(SweepGrid g, SweepCell rule, ThinFeatures thin) {
        this.g = g;
        this.rule = rule;
        this.thin = thin;
    }

    /** Per-task scratch: the shadow height of one line at each window column, and its walk's distances and hull. */
    private static final class Line {
        final double[] height;
        final double[] pos;
        final double[] hullA;
        final double[] hullB;

        Line(int windowCols, int walkLen) {
            height = new double[windowCols];
            pos = new double[walkLen + 3];
            hullA = new double[walkLen + 3];
            hullB = new double[walkLen + 3];
        }
    }

    /** Computes the cells between lines kFrom … kTo + 1 into w's output. */
    void walk(SweepWindow w, int kFrom, int kTo) {
        int cols = w.wi1() - w.wi0() + 1;
        int walk = w.iTop() - w.wi0() + 1;
        Line a = new Line(cols, walk);
        Line b = new Line(cols, walk);
        boolean[] own = new boolean[cols];                              // stays false without thin features
        double[] stripPos = thin != null ? new double[walk] : null;
        walkLine(w, kFrom, a);
        for (int k = kFrom; k <= kTo; k++) {
            walkLine(w, k + 1, b);
            if (thin != null) {
                thin.walkStrip(w, k, own, stripPos);
            }
            band(w, k, a, b, own);
            Line t = a;
            a = b;
            b = t;
        }
    }

    /** Evaluates the cells between lines k and k + 1. */
    private void band(SweepWindow w, int k, Line a, Line b, boolean[] own) {
        int iLo = w.wi0();
        int iHi = w.wi1();
        double m = g.m;
        if (m > 0) {
            // cells j = k + floor(m·i + φ) (+1) with wj0 ≤ j ≤ wj1
            iHi = (int) Math.min(iHi, Math.floor((w.wj1() - k + 1) / m) + 1);
            iLo = (int) Math.max(iLo, Math.ceil((w.wj0() - k - 2) / m) - 1);
        }
        double tan = g.f.tanElevation;
        CellWindow win = w.win();
        for (int i = iLo; i <= iHi; i++) {
            double fr = g.pr[i];
            int j = g.stripCell(k, i);
            if (j < w.wj0() || j > w.wj1()) {
                continue;
            }
            double phi = fr > 0 ? 1 - fr : 0;
            int at = i - w.wi0();
            double z0 = g.v[g.idx(i, j)];
            float result;
            if (z0 != z0) {
                result = 0f;
            } else {
                boolean lines = j >= g.jTraced ? rule.rayBlockedToEdge(i, j, z0, tan)
                        : SweepCell.between(a.height[at], b.height[at], phi, g.floorOfRow[g.rowOf(i, j)]) > z0
                        || own[at];
                result = (lines || rule.localBlocked(i, j, z0, tan)) ? 1f : 0f;
            }
            int col = g.c0 + g.ci * i + g.cj * j;
            int row = g.r0 + g.ri * i + g.rj * j;
            w.out()[(row - win.row()) * win.width() + (col - win.col())] = result;
        }
    }

    /**
     * Walks line k from iTop down to the window, storing for each window column i the shadow height at i from the
     * line's samples at i + 2 and beyond ({@code −∞} when none), and the distance to the sample that sets it.
     */
    private void walkLine(SweepWindow w, int k, Line line) {
        double tan = g.f.tanElevation;
        double bc = g.f.curvature;
        double m = g.m;
        int nMin = g.nMin;
        int nMaj = g.nMaj;
        int wi0 = w.wi0();
        int iTop = w.iTop();
        // i range where the line is on (or within half a cell of) the grid: −1 < k + m·i + φ < nMin, φ in [0, 1)
        int iHi = iTop;
        int iLo = wi0;
        if (m > 0) {
            iHi = (int) Math.min(iTop, Math.floor((nMin - k) / m) + 1);
            iLo = (int) Math.max(wi0, Math.ceil((-2 - k) / m) - 1);
        } else if (k < -1 || k > nMin - 1) {
            iHi = iLo - 1;
        }
        // columns of the window the walk does not reach have no upstream terrain
        int wi1 = w.wi1();
        if (iHi < iLo) {
            Arrays.fill(line.height, Double.NEGATIVE_INFINITY);
            return;
        }
        Arrays.fill(line.height, 0, iLo - wi0, Double.NEGATIVE_INFINITY);
        if (iHi < wi1) {
            Arrays.fill(line.height, iHi + 1 - wi0, wi1 + 1 - wi0, Double.NEGATIVE_INFINITY);
        }
        boolean uniform = g.uniform();
        if (bc == 0 && uniform) {
            walkUniform(k, iLo, iHi, wi0, wi1, line.height);
            return;
        }
        double[] steps = g.f.metresPerStep;
        double[] pos = line.pos;
        double step = g.uniformStep;
        // pos[i - wi0] = distance downstream from the line's top on the whole grid, iHiAll: the same numbers
        // whatever window and halo cut the walk at iHi
        int iHiAll = g.lineTop(k);
        if (uniform) {
            pos[iHi - wi0] = (iHiAll - iHi) * step;
        } else {
            double top = 0;
            for (int i = iHiAll - 1; i >= iHi; i--) {
                top += steps[g.rowOf(i, g.lineRow(k, i))];
            }
            pos[iHi - wi0] = top;
        }
        double best = Double.NEGATIVE_INFINITY;   // max of z + tan·P (no curvature)
        int hullHead = 0;
        int hullSize = 0;
        double[] ha = line.hullA;
        double[] hb = line.hullB;
        for (int i = iHi; i >= iLo; i--) {
            if (i < iHi) {
                if (uniform) {
                    pos[i - wi0] = (iHiAll - i) * step;
                } else {
                    pos[i - wi0] = pos[i + 1 - wi0] + steps[g.rowOf(i, g.lineRow(k, i))];
                }
            }
            double p = pos[i - wi0];
            // the sample two steps upstream, or the one on the file's upstream outer edge half a step beyond the last
            // whole step (joins for i = nMaj − 2, as a sample at i + 2 would); its P is 0 there (the line's top)
            boolean half = i + 2 > iHi && i == nMaj - 2 && iHi == nMaj - 1 && g.upstreamEdgeSample;
            if (i + 2 <= iHi || half) {
                double z = half ? g.edgeSample(k) : g.lineSample(k, i + 2);
                double pz = half ? g.edgeDistance(k) : pos[i + 2 - wi0];
                if (bc == 0) {
                    best = SweepCell.higher(best, SweepCell.lifted(z, tan, pz));
                } else if (z == z) {
                    // line of the upper envelope: value(P) = A + B·P − tan·P − bc·P², slopes B increasing
                    double na = z + tan * pz - bc * pz * pz;
                    double nb = 2 * bc * pz;
                    while (hullSize - hullHead >= 2) {
                        int l1 = hullSize - 2;
                        int l2 = l1 + 1;
                        // l2 is useless if the intersection of l1 and new is left of that of l1 and l2
                        double x12 = (ha[l1] - ha[l2]) / (hb[l2] - hb[l1]);
                        double x1n = (ha[l1] - na) / (nb - hb[l1]);
                        if (x1n <= x12) {
                            hullSize--;
                        } else {
                            break;
                        }
                    }
                    if (hullSize > hullHead && nb == hb[hullSize - 1]) {
                        if (na > ha[hullSize - 1]) {
                            ha[hullSize - 1] = na;
                        }
                    } else {
                        ha[hullSize] = na;
                        hb[hullSize] = nb;
                        hullSize++;
                    }
                }
            }
            if (i <= wi1) {
                int at = i - wi0;
                if (bc == 0) {
                    line.height[at] = SweepCell.heightAt(best, tan, p);
                } else if (hullSize > hullHead) {
                    while (hullSize - hullHead >= 2
                            && ha[hullHead + 1] + hb[hullHead + 1] * p >= ha[hullHead] + hb[hullHead] * p) {
                        hullHead++;
                    }
                    line.height[at] = ha[hullHead] + hb[hullHead] * p - tan * p - bc * p * p;
                } else {
                    line.height[at] = Double.NEGATIVE_INFINITY;
                }
            }
        }
    }

    /** {@link #walkLine} on a grid with one step length and no curvature: a running maximum. */
    private void walkUniform(int k, int iLo, int iHi, int wi0, int wi1, double[] height) {
        double drop = g.f.tanElevation * g.uniformStep;
        // best = max over samples i' ≥ i + 2 of z(i') − (i' − i)·drop, kept relative to the current i
        double best = Double.NEGATIVE_INFINITY;
        double prev = Double.NEGATIVE_INFINITY;   // sample at i + 1 (joins best one step later)
        if (iHi == g.nMaj - 1 && g.upstreamEdgeSample) {
            prev = g.edgeStart(k, drop);
        }
        for (int i = iHi; i >= iLo; i--) {
            if (i <= wi1) {
                height[i - wi0] = best;
            }
            best = SweepCell.joined(best, prev, drop);
            prev = SweepCell.pending(g.lineSample(k, i), drop);
        }
    }
}
