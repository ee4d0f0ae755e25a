package io.github.jdem846.shadow;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * The sweep's frame on one grid ({@link SunSweep}): where the lines run, how long a step is on each row, where the
 * edges are, and the terrain a line reads.
 *
 * <p>Major index i runs along the sun's major grid axis with i increasing toward the sun; minor index j across it,
 * oriented so that the line slope m = dj/di is in [0, 1]. Line k is j = k + m·i: at major index i it passes minor
 * position k + pf[i] + pr[i] (pr in [0, 1)), the same fraction for every line.
 */
final class SweepGrid {

    /** Eighth-cell steps of the first-cell test and of the edge trace. */
    static final int SUB_STEPS = 8;
    /** Cells whose ray leaves through the file's side edge within this many major steps are traced directly. */
    static final int EDGE_TRACE_STEPS = 4;

    final float[] v;
    final RayFrame f;
    final boolean bilinear;
    final boolean firstCellTest;
    final int nMaj;
    final int nMin;
    final int c0;
    final int ci;
    final int cj;
    final int r0;
    final int ri;
    final int rj;
    final int gridW;
    final double m;
    /** Per major index: the whole and the fractional part of the lines' minor offset (line k at k + pf + pr). */
    final int[] pf;
    final double[] pr;
    /** Flat index of frame cell (i, 0), and the index stride of one minor step. */
    final int[] baseI;
    final int strideJ;
    /** Where major index 0 lies in the frame of the grid this one was cut from: root major index = i + i0. */
    final long i0;
    /** Metres of one major step when it is the same on every row (projected grids), else NaN. */
    final double uniformStep;
    /** Per row: a line whose shadow height is below this counts as no terrain (see {@link SunSweep}). */
    final double[] floorOfRow;
    /** The floor of every row when the step is the same on all rows (NaN otherwise), and the lowest floor. */
    final double uniformFloor;
    final double lowestFloor;
    /** The lowest terrain the floors start from: the file's or the grid's minimum. */
    final double lowestTerrain;
    /**
     * The last minor cell the lines read, min(nMin − 1, the root grid's last one in this frame). Rays leave the grid
     * through this side (j increases toward the sun): when it is the root's (the file's) edge, terrain ends half a
     * cell beyond it, at the outer cell edge, where a marched ray leaves the grid; a side of a window that is not
     * the file's edge keeps the one-cell clamp (terrain continues there in the file, and the halo bounds its effect).
     */
    final int cellHi;
    final boolean exitIsRootEdge;
    /**
     * True (bilinear sampling only) when this grid's last major index nMaj − 1 is the root's (the file's) upstream
     * edge: the lines then also read the outer half cell beyond it, at the edge itself, as the bilinear march does.
     */
    final boolean upstreamEdgeSample;
    /**
     * Cells j ≥ jTraced have rays that leave the grid through the root's exit side before {@link #EDGE_TRACE_STEPS}
     * major steps: they are traced along their own ray up to the edge ({@link SweepCell#rayBlockedToEdge}) instead
     * of from the lines' shadow heights, which carry terrain the cell's ray never reaches (up to a cell beyond its
     * exit). Integer.MAX_VALUE = none.
     */
    final int jTraced;

    /**
     * @param terrainMinimum the lowest elevation of the file {@code dem} was read from (NaN = the grid's own): the
     *                       floor below which a line counts as no terrain starts there
     */
    SweepGrid(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest, double terrainMinimum) {
        this.v = dem.backingArray();
        this.f = frame;
        this.bilinear = bilinear;
        this.firstCellTest = firstCellTest;
        double own = dem.statistics().min();
        double lowest = Double.isNaN(terrainMinimum) ? own : Math.min(terrainMinimum, own);
        this.lowestTerrain = lowest;
        this.floorOfRow = new double[frame.metresPerStep.length];
        double lowestF = Double.POSITIVE_INFINITY;
        for (int r = 0; r < floorOfRow.length; r++) {
            floorOfRow[r] = floor(frame.metresPerStep[r], frame.tanElevation);
            lowestF = Math.min(lowestF, floorOfRow[r]);
        }
        this.lowestFloor = floorOfRow.length > 0 ? lowestF : lowest;
        int w = dem.width();
        int h = dem.height();
        this.gridW = w;
        if (frame.xMajor) {
            nMaj = w;
            nMin = h;
            ci = frame.ux > 0 ? 1 : -1;
            c0 = ci > 0 ? 0 : w - 1;
            cj = 0;
            ri = 0;
            rj = frame.uy >= 0 ? 1 : -1;
            r0 = rj > 0 ? 0 : h - 1;
            m = Math.abs(frame.uy);
        } else {
            nMaj = h;
            nMin = w;
            ri = frame.uy > 0 ? 1 : -1;
            r0 = ri > 0 ? 0 : h - 1;
            rj = 0;
            ci = 0;
            cj = frame.ux >= 0 ? 1 : -1;
            c0 = cj > 0 ? 0 : w - 1;
            m = Math.abs(frame.ux);
        }
        // Lines are laid from the downstream edge of the grid this one was cut from (GridGeometry.placement):
        // position m·(i + i0), i0 = where frame column 0 lies in that grid's frame, so a window samples exactly the
        // same positions, bit for bit, as the whole grid (phase φ = frac(m·i0) in [0, 1); 0 for a whole grid).
        GridGeometry.Placement at = dem.geometry().placement();
        long i0 = frame.xMajor ? (ci > 0 ? at.col() : (long) at.rootWidth() - w - at.col())
                : (ri > 0 ? at.row() : (long) at.rootHeight() - h - at.row());
        this.i0 = i0;
        // the root's last minor cell in this grid's frame: j = (cell − start) · direction, the larger of the ends
        int rootFirst = frame.xMajor ? -at.row() : -at.col();
        int rootLast = frame.xMajor ? at.rootHeight() - 1 - at.row() : at.rootWidth() - 1 - at.col();
        int start = frame.xMajor ? r0 : c0;
        int dir = frame.xMajor ? rj : cj;
        int rootHi = Math.max((rootFirst - start) * dir, (rootLast - start) * dir);
        exitIsRootEdge = rootHi <= nMin - 1;
        int rootFirstMaj = frame.xMajor ? -at.col() : -at.row();
        int rootLastMaj = frame.xMajor ? at.rootWidth() - 1 - at.col() : at.rootHeight() - 1 - at.row();
        int startMaj = frame.xMajor ? c0 : r0;
        int dirMaj = frame.xMajor ? ci : ri;
        int rootHiMaj = Math.max((rootFirstMaj - startMaj) * dirMaj, (rootLastMaj - startMaj) * dirMaj);
        upstreamEdgeSample = bilinear && rootHiMaj == nMaj - 1;
        cellHi = Math.min(nMin - 1, rootHi);
        // d = cellHi − j: the ray leaves before step S when m·S > d + ½, i.e. d ≤ ceil(m·S − ½) − 1
        int dTraced = (int) Math.ceil(m * EDGE_TRACE_STEPS - 0.5) - 1;
        jTraced = bilinear && exitIsRootEdge && dTraced >= 0 ? cellHi - dTraced : Integer.MAX_VALUE;
        double base = Math.floor(m * i0);
        pf = new int[nMaj];
        pr = new double[nMaj];
        for (int i = 0; i < nMaj; i++) {
            double p = m * (double) (i + i0);
            double fl = Math.floor(p);
            pf[i] = (int) (fl - base);
            pr[i] = p - fl;
        }
        baseI = new int[nMaj];
        for (int i = 0; i < nMaj; i++) {
            baseI[i] = (r0 + ri * i) * w + c0 + ci * i;
        }
        strideJ = rj * w + cj;
        double first = frame.metresPerStep[0];
        boolean same = true;
        for (double d : frame.metresPerStep) {
            same &= d == first;
        }
        uniformStep = same ? first : Double.NaN;
        uniformFloor = same ? floorOfRow[0] : Double.NaN;
    }

    /**
     * The floor of a row whose step is {@code step} metres, for a sun whose elevation has the tangent {@code tan}:
     * the lowest terrain less {@link ShadowHalo#FLOOR_STEPS} steps' drop.
     */
    double floor(double step, double tan) {
        return lowestTerrain - ShadowHalo.FLOOR_STEPS * step * tan;
    }

    /** True when every row has the same step length (projected grids). */
    boolean uniform() {
        return uniformStep == uniformStep;
    }

    int idx(int i, int j) {
        return baseI[i] + strideJ * j;
    }

    int rowOf(int i, int j) {
        return r0 + ri * i + rj * j;
    }

    int frameI(int col, int row) {
        return f.xMajor ? (col - c0) * ci : (row - r0) * ri;
    }

    int frameJ(int col, int row) {
        return f.xMajor ? (row - r0) * rj : (col - c0) * cj;
    }

    /** The cell of the strip between lines k and k + 1 at major index i (on line k when it passes a centre). */
    int stripCell(int k, int i) {
        return k + pf[i] + (pr[i] > 0 ? 1 : 0);
    }

    /** The minor cell nearest to line k at major index i, clamped into the grid. */
    int lineRow(int k, int i) {
        return Math.max(0, Math.min(nMin - 1, k + pf[i] + (pr[i] >= 0.5 ? 1 : 0)));
    }

    /** The last major index at which line k is on (or within half a cell of) the whole grid: its top (P = 0). */
    int lineTop(int k) {
        return m > 0 ? (int) Math.min(nMaj - 1, Math.floor((nMin - k) / m) + 1) : nMaj - 1;
    }

    /** The terrain on line k at major index i (NaN = no-data or off the grid). */
    double lineSample(int k, int i) {
        return sampleAt(i, k + pf[i], pr[i]);
    }

    /**
     * Between two neighbouring cells za and zb at fraction fr in (0, 1): linear when both are valid, else the valid
     * one (NaN when neither is). Every line sample on the bilinear surface goes through here.
     */
    static double mix(double za, double zb, double fr) {
        return za == za && zb == zb ? za + (zb - za) * fr : za == za ? za : zb;
    }

    /**
     * The terrain at major index i, minor position jj + fr (fr in [0, 1)), NaN = no-data or off the grid. The
     * position is compared with the edges in that integer-and-fraction form, so a window decides exactly as the
     * whole grid does. Bilinear: linear between cells jj and jj + 1; below the first cell the first one is read up
     * to a cell beyond it (no ray leaves the grid there: the lines beyond are only interpolation partners of the
     * first cells); beyond the last cell, up to the outer cell edge at the file's edge, else a cell beyond.
     */
    double sampleAt(int i, int jj, double fr) {
        if (bilinear) {
            if (jj >= 0 && jj < cellHi) {
                int at = baseI[i] + strideJ * jj;
                double za = v[at];
                return fr == 0 ? za : mix(za, v[at + strideJ], fr);
            }
            if (jj < -1 || (jj == -1 && fr == 0) || jj > cellHi || (exitIsRootEdge && jj == cellHi && fr > 0.5)) {
                return Double.NaN;
            }
            if (fr == 0) {
                return v[idx(i, jj)];
            }
            int ja = Math.max(jj, 0);
            int jb = Math.min(jj + 1, cellHi);
            return mix(v[idx(i, ja)], v[idx(i, jb)], fr);
        }
        double pos = jj + fr;
        if (pos < -0.5 || pos > cellHi + 0.5) {
            return Double.NaN;
        }
        int jn = (int) Math.floor(pos + 0.5);
        jn = Math.max(0, Math.min(cellHi, jn));
        return v[idx(i, jn)];
    }

    /**
     * Line k on the file's upstream outer cell edge, half a major step beyond its last whole step nMaj − 1 (read
     * from the edge row, as the bilinear march reads the outer half cell), NaN when off the grid or no-data.
     */
    double edgeSample(int k) {
        int i = nMaj - 1;
        double t = pr[i] + 0.5 * m;
        double ft = Math.floor(t);
        return sampleAt(i, k + pf[i] + (int) ft, t - ft);
    }

    /**
     * The running maximum's "sample at i + 1" before a walk on a grid with one step length that starts at the file's
     * upstream edge (i = nMaj − 1): the edge sample, half a step farther, so that it joins the shadow height from
     * i = nMaj − 2 on.
     */
    double edgeStart(int k, double drop) {
        return SweepCell.pending(edgeSample(k), 0.5 * drop);
    }

    /**
     * The distance P of {@link #edgeSample} on line k, whose top is the upstream edge row (P = 0 there): half that
     * row's step upstream of it.
     */
    double edgeDistance(int k) {
        return 0.0 - 0.5 * f.metresPerStep[rowOf(nMaj - 1, lineRow(k, nMaj - 1))];
    }

    /** Terrain at fractional frame position (i + t, j + m·t), or NaN off the grid or no-data. */
    double frameSample(int i, int j, double t) {
        double fi = i + t;
        double fj = j + m * t;
        double x = c0 + ci * fi + cj * fj;
        double y = r0 + ri * fi + rj * fj;
        int w = gridW;
        int h = v.length / w;
        if (TerrainSampler.isOutside(x, y, w, h)) {
            return Double.NaN;
        }
        return bilinear ? TerrainSampler.bilinear(v, w, h, x, y) : TerrainSampler.nearest(v, w, h, x, y);
    }

    /** Cell j at major index i, {@code −∞} when outside [0, cellHi] or no-data. */
    double cellOrNone(int i, int j) {
        if (j < 0 || j > cellHi) {
            return Double.NEGATIVE_INFINITY;
        }
        double z = v[baseI[i] + strideJ * j];
        return z == z ? z : Double.NEGATIVE_INFINITY;
    }
}
