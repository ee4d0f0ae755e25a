package io.github.jdem846.shadow;

import io.github.jdem846.parallel.Cancellation;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.concurrent.ForkJoinPool;

/**
 * The shadow test of the ray march in O(cells): straight lines parallel to the sun direction, one cell apart across
 * it, are walked from the sun's side, each carrying the running shadow height max(z_upstream − d·tan(elevation)) of
 * its own samples (the DEM read bilinearly, or nearest, at exact positions on the line: shadow heights are never
 * re-interpolated from line to line, so nothing smears sideways). A cell lies between two adjacent lines; its shadow
 * height from two cells upstream on is interpolated between theirs, and the first cell of its own ray is tested
 * directly on the bilinear surface in eighth-cell steps, as {@code exact} does, where a steep slope shades itself.
 * A line whose shadow height is below a floor, the lowest terrain less {@link ShadowHalo#FLOOR_STEPS} steps' drop
 * (no terrain, or only terrain so far away that it could shade nothing), counts as no terrain and the other line
 * decides alone; a line with valid terrain two steps upstream is always above the floor. That rule makes the result
 * depend only on terrain within (zMax − zMin)/tan(elevation) + {@link ShadowHalo#FLOOR_STEPS} steps of the cell,
 * so a window computed with that halo ({@link ShadowHalo#sweepSteps}, {@link ShadowHalo#window}) equals the same
 * cells of the whole grid; interpolating toward a far, low line would not. For a grid read as a window of a file,
 * zMin is the file's ({@link ShadowOptions#terrainMinimum()}), so that the floor is the whole file's.
 *
 * <p>Edges (bilinear sampling): terrain ends at the outer cell edges of the file's grid, as for a marched ray (test
 * 2). On the side through which rays leave, line samples beyond the outer edge are no terrain, and a cell whose own
 * ray leaves through it within a few steps is marched along that ray in eighth steps instead of taking its lines'
 * heights (a line runs on up to a cell beyond where the cell's ray has left); at the upstream edge the lines also read
 * the outer half cell. The side of a window that is not the file's edge ({@link GridGeometry#placement()}) reads on
 * as before, so a window equals the whole grid.
 *
 * <p>Thin features (an option, {@link ShadowOptions#thinFeatures()}): each cell also tests one sample of its own
 * ray, at the row where the cells between its two lines have the steepest terrain bound as seen from the cell
 * ({@link StripHull}), so that a feature one cell wide, which the lines see only partly, shades its whole lee.
 *
 * <p>Work: one sample per line per column plus a constant per cell, whatever the sun elevation. Lines are split
 * into chunks across a ForkJoinPool; every line is computed the same way in any chunk, so the mask does not depend
 * on the thread count.
 *
 * <p>Frame: major index i runs along the sun's major grid axis with i increasing toward the sun; minor index j
 * across it, oriented so that the line slope m = dj/di is in [0, 1]. Line k is j = k + m·i.
 *
 * <p>Why one class of this size: the lockstep walks carry their own inlined copies of the cell rule, because the
 * hot loops lose speed when it is a call. A split into a frame, a shared cell rule and one class per walk passes
 * every consistency test with byte-identical masks but measured 10–20 % slower in {@code RayTraceBenchmark.sweep}
 * (2048², 5°, alternating jars); it lands once it is as fast. Until then the consistency tests
 * ({@code SunSweepConsistencyTest}, {@code SoftSweepOneWalkTest}) pin every walk to the reference walk cell for cell.
 */
final class SunSweep {

    private static final int LINES_PER_TASK = 48;
    private static final int SUB_STEPS = 8;
    /** Cells whose ray leaves through the file's side edge within this many major steps are traced directly. */
    private static final int EDGE_TRACE_STEPS = 4;

    private final float[] v;
    private final RayFrame f;
    private final boolean bilinear;
    private final boolean firstCellTest;
    private final int nMaj;
    private final int nMin;
    private final int c0;
    private final int ci;
    private final int cj;
    private final int r0;
    private final int ri;
    private final int rj;
    private final int gridW;
    private final double m;
    private final int[] pf;
    private final double[] pr;
    /** Flat index of frame cell (i, 0), and the index stride of one minor step. */
    private final int[] baseI;
    private final int strideJ;
    /** Metres of one major step when it is the same on every row (projected grids), else NaN. */
    private final double uniformStep;
    /** Per row: a line whose shadow height is below this counts as no terrain (see the class comment). */
    private final double[] floorOfRow;
    /** The floor of every row when the step is the same on all rows (NaN otherwise), and the lowest floor. */
    private final double uniformFloor;
    private final double lowestFloor;
    /** The lowest terrain the floors start from: the file's or the grid's minimum. */
    private final double lowestTerrain;

    /**
     * The last minor cell the lines read, min(nMin − 1, the root grid's last one in this frame). Rays leave the grid
     * through this side (j increases toward the sun): when it is the root's (the file's) edge, terrain ends half a
     * cell beyond it, at the outer cell edge, where a marched ray leaves the grid; a side of a window that is not
     * the file's edge keeps the one-cell clamp (terrain continues there in the file, and the halo bounds its effect).
     */
    private final int cellHi;
    private final boolean exitIsRootEdge;
    /**
     * True (bilinear sampling only) when this grid's last major index nMaj − 1 is the root's (the file's) upstream
     * edge: the lines then also read the outer half cell beyond it, at the edge itself, as the bilinear march does.
     */
    private final boolean upstreamEdgeSample;
    /**
     * Cells j ≥ jTraced have rays that leave the grid through the root's exit side before {@link #EDGE_TRACE_STEPS}
     * major steps: they are traced along their own ray up to the edge instead of from the lines' shadow heights,
     * which carry terrain the cell's ray never reaches (up to a cell beyond its exit). Integer.MAX_VALUE = none.
     */
    private final int jTraced;

    /** When false, every case takes the line-by-line path ({@link #bands}): the reference of the tests. */
    private final boolean lockstepAllowed;
    /** Each cell also tests one sample of its own ray ({@link StripHull}). */
    private final boolean thinFeatures;

    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest) {
        this(dem, frame, bilinear, firstCellTest, true);
    }

    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest, boolean lockstepAllowed) {
        this(dem, frame, bilinear, firstCellTest, lockstepAllowed, Double.NaN, false);
    }

    /**
     * @param terrainMinimum the lowest elevation of the file {@code dem} was read from (NaN = the grid's own): the
     *                       floor below which a line counts as no terrain starts there
     * @param thinFeatures   also test each cell's own ray at its strip's steepest terrain ({@link StripHull})
     */
    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest, boolean lockstepAllowed,
             double terrainMinimum, boolean thinFeatures) {
        this.thinFeatures = thinFeatures;
        if (frame.soft()) {
            throw new IllegalArgumentException("the sweep traces hard shadows; soft shadows are built from hard sweeps"
                    + " at angles across the sun's disk (ShadowAlgorithm)");
        }
        this.lockstepAllowed = lockstepAllowed;
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
            floorOfRow[r] = lowest - ShadowHalo.FLOOR_STEPS * frame.metresPerStep[r] * frame.tanElevation;
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

    /** The lowest floor of all rows: no line height below it is ever used (see the class comment). */
    double lowestFloor() {
        return lowestFloor;
    }

    private int idx(int i, int j) {
        return baseI[i] + strideJ * j;
    }

    private int rowOf(int i, int j) {
        return r0 + ri * i + rj * j;
    }

    private int frameI(int col, int row) {
        return f.xMajor ? (col - c0) * ci : (row - r0) * ri;
    }

    private int frameJ(int col, int row) {
        return f.xMajor ? (row - r0) * rj : (col - c0) * cj;
    }

    /**
     * Computes the shadow of the cells of {@code win} into {@code out} (row-major, row length win.width()), reading
     * terrain up to {@code haloSteps} major steps upstream of the window (Integer.MAX_VALUE = the whole grid).
     */
    void run(CellWindow win, int haloSteps, float[] out, ForkJoinPool pool) {
        boolean lockstep = lockstepAllowed && bilinear && f.curvature == 0 && uniformStep == uniformStep;
        boolean varying = lockstepAllowed && bilinear && f.curvature == 0 && uniformStep != uniformStep
                && !thinFeatures;
        forEachBlock(win, haloSteps, out, pool, (w, from, to) -> {
            if (lockstep) {
                bandsUniformHard(w, from, to);
            } else if (varying) {
                bandsVaryingHard(w, from, to);
            } else {
                bands(w, from, to);
            }
        });
    }

    /** True when {@link #runLevels} can walk several sun elevations at once (the lockstep cases of {@link #run}). */
    boolean canRunLevels() {
        return lockstepAllowed && bilinear && f.curvature == 0 && !thinFeatures;
    }

    /**
     * For the sun elevations whose tangents are {@code tans} (at most 31, same azimuth as this sweep's frame), sets
     * bit k of {@code bits[c]} when cell c of {@code win} (row-major, row length win.width()) is in shadow at
     * elevation k, exactly as {@link #run} with a frame at that elevation would find it, in one walk: the lines'
     * samples do not depend on the elevation, only the running maxima do. {@code haloSteps} must cover the lowest
     * elevation. Only when {@link #canRunLevels()}.
     */
    void runLevels(CellWindow win, int haloSteps, double[] tans, int[] bits, ForkJoinPool pool) {
        if (!canRunLevels() || tans.length > 31) {
            throw new IllegalStateException("runLevels needs the lockstep case and at most 31 elevations");
        }
        boolean uniform = uniformStep == uniformStep;
        forEachBlock(win, haloSteps, null, pool, (w, from, to) -> {
            if (uniform) {
                bandsLevels(w, from, to, tans, bits);
            } else {
                bandsLevelsVarying(w, from, to, tans, bits);
            }
        });
    }

    /** One block of lines kFrom … kTo + 1 of a window. */
    @FunctionalInterface
    private interface BlockWork {
        void run(Window w, int kFrom, int kTo);
    }

    /**
     * Splits the lines that reach {@code win} into blocks of {@link #LINES_PER_TASK} and runs them on the pool; once
     * the caller is interrupted no further block starts ({@link Cancellation}; a block takes milliseconds, tens on
     * the widest grids, so the walks themselves, the hot loops, test nothing).
     */
    private void forEachBlock(CellWindow win, int haloSteps, float[] out, ForkJoinPool pool, BlockWork work) {
        int ia = frameI(win.col(), win.row());
        int ib = frameI(win.colEnd() - 1, win.rowEnd() - 1);
        int ja = frameJ(win.col(), win.row());
        int jb = frameJ(win.colEnd() - 1, win.rowEnd() - 1);
        int wi0 = Math.min(ia, ib);
        int wi1 = Math.max(ia, ib);
        int wj0 = Math.min(ja, jb);
        int wj1 = Math.max(ja, jb);
        int iTop = (int) Math.min(nMaj - 1L, (long) wi1 + haloSteps);
        int kMin = wj0 - pf[wi1] - 1;
        int kMax = wj1 - pf[wi0];
        Window w = new Window(win, wi0, wi1, wj0, wj1, iTop, out);
        int blocks = (int) Math.max(0, ((long) kMax - kMin + LINES_PER_TASK) / LINES_PER_TASK);
        Cancellation.invokeAll(pool, blocks, (b, cancel) -> {
            int from = kMin + b * LINES_PER_TASK;
            work.run(w, from, Math.min(kMax, from + LINES_PER_TASK - 1));
        });
    }

    private record Window(CellWindow win, int wi0, int wi1, int wj0, int wj1, int iTop, float[] out) {
    }

    /** Per-task scratch: the shadow height of one line at each window column. */
    private final class Line {
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

    private void bands(Window w, int kFrom, int kTo) {
        int cols = w.wi1 - w.wi0 + 1;
        int walk = w.iTop - w.wi0 + 1;
        Line a = new Line(cols, walk);
        Line b = new Line(cols, walk);
        boolean[] own = new boolean[cols];                              // stays false without thin features
        double[] stripPos = thinFeatures ? new double[walk] : null;
        walkLine(w, kFrom, a);
        for (int k = kFrom; k <= kTo; k++) {
            walkLine(w, k + 1, b);
            if (thinFeatures) {
                walkStrip(w, k, own, stripPos);
            }
            band(w, k, a, b, own);
            Line t = a;
            a = b;
            b = t;
        }
    }

    /**
     * Walks the strip between lines k and k + 1 from iTop down to the window and stores in {@code blocked}, per
     * window column, whether the strip's cell there is shaded by its own-ray sample ({@link StripHull}, {@link
     * Strips}): with one step length and no curvature by exactly the lockstep path's arithmetic; otherwise with x =
     * the distance along the strip (summed row by row along its cells), the rise tan·d and curvature.
     */
    private void walkStrip(Window w, int k, boolean[] blocked, double[] pos) {
        int wi0 = w.wi0;
        int wi1 = w.wi1;
        if (f.curvature == 0 && uniformStep == uniformStep) {
            double drop = f.tanElevation * uniformStep;
            Strips one = new Strips(1);
            int rTop = Math.min(w.iTop, nMaj - 1);
            for (int i = w.iTop; i >= wi0; i--) {
                int r = i + 2;
                if (r <= rTop) {
                    one.take(0, r, around(r, stripCell(k, r)), drop);
                }
                if (i <= wi1) {
                    int j = stripCell(k, i);
                    double z0 = j >= 0 && j < nMin ? v[idx(i, j)] : Double.NaN;
                    double phi = pr[i] > 0 ? 1 - pr[i] : 0;
                    blocked[i - wi0] = z0 == z0 && one.blocks(this, 0, k, i, phi, z0, drop);
                }
            }
            return;
        }
        double tan = f.tanElevation;
        double bc = f.curvature;
        StripHull hull = new StripHull();
        double best = Double.NEGATIVE_INFINITY;     // max of bound + tan·x over the hull's points
        double prevVal = Double.NEGATIVE_INFINITY;
        double prevAround = Double.NEGATIVE_INFINITY;
        for (int i = w.iTop; i >= wi0; i--) {
            int j = stripCell(k, i);
            int at = i - wi0;
            pos[at] = i == w.iTop ? 0 : pos[at + 1] + f.metresPerStep[rowOf(i, Math.max(0, Math.min(nMin - 1, j)))];
            double x = pos[at];
            if (i <= wi1) {
                double z0 = j >= 0 && j < nMin ? v[idx(i, j)] : Double.NaN;
                boolean b = false;
                if (z0 == z0 && best - tan * x > z0) {
                    int iStar = hull.tangent(x, z0);
                    double phi = pr[i] > 0 ? 1 - pr[i] : 0;
                    double t = pr[iStar] + phi;
                    int ft = t >= 1 ? 1 : 0;
                    double z = sampleAt(iStar, k + pf[iStar] + ft, t - ft);
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

    /** The cell of the strip between lines k and k + 1 at major index i (on line k when it passes a centre). */
    private int stripCell(int k, int i) {
        return k + pf[i] + (pr[i] > 0 ? 1 : 0);
    }

    /** The terrain on line k at major index i (NaN = no-data or off the grid). */
    private double lineSample(int k, int i) {
        return sampleAt(i, k + pf[i], pr[i]);
    }

    /**
     * The terrain at major index i, minor position jj + fr (fr in [0, 1)), NaN = no-data or off the grid. The
     * position is compared with the edges in that integer-and-fraction form, so a window decides exactly as the
     * whole grid does. Bilinear: linear between cells jj and jj + 1; below the first cell the first one is read up
     * to a cell beyond it (no ray leaves the grid there: the lines beyond are only interpolation partners of the
     * first cells); beyond the last cell, up to the outer cell edge at the file's edge, else a cell beyond.
     */
    private double sampleAt(int i, int jj, double fr) {
        if (bilinear) {
            if (jj >= 0 && jj < cellHi) {
                int at = baseI[i] + strideJ * jj;
                double za = v[at];
                if (fr == 0) {
                    return za;
                }
                double zb = v[at + strideJ];
                if (za == za && zb == zb) {
                    return za + (zb - za) * fr;
                }
                return za == za ? za : zb;
            }
            if (jj < -1 || (jj == -1 && fr == 0) || jj > cellHi || (exitIsRootEdge && jj == cellHi && fr > 0.5)) {
                return Double.NaN;
            }
            if (fr == 0) {
                return v[idx(i, jj)];
            }
            int ja = Math.max(jj, 0);
            int jb = Math.min(jj + 1, cellHi);
            double za = v[idx(i, ja)];
            double zb = v[idx(i, jb)];
            if (za == za && zb == zb) {
                return za + (zb - za) * fr;
            }
            return za == za ? za : zb;
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
     * For a cell j ≥ {@link #jTraced}: true when its own ray, after the first step ({@link #localBlocked}), meets
     * the bilinear surface before it leaves the grid through the file's side edge. It is marched as {@code exact}
     * marches, in eighth steps, so these cells get the reference's answer; there are at most about m·S + 1 of them
     * per major index, each at most 8·S samples.
     */
    private boolean rayBlockedToEdge(int i, int j, double z0) {
        return rayBlockedToEdge(i, j, z0, f.tanElevation);
    }

    /** {@link #rayBlockedToEdge(int, int, double)} for a sun whose elevation has the tangent {@code tan}. */
    private boolean rayBlockedToEdge(int i, int j, double z0, double tan) {
        double d = f.metresPerStep[rowOf(i, j)];
        double bc = f.curvature;
        double room = cellHi - j + 0.5;
        for (int q = SUB_STEPS + 1; ; q++) {
            double t = (double) q / SUB_STEPS;
            double y = m * t;
            if (y > room || i + t > nMaj - 0.5) {
                return false;
            }
            // bilinear in the frame: major cells ia, ia + 1 (clamped at the last), minor cells ja, ja + 1 (clamped
            // at the last, the outer half cell); a no-data corner falls back to the renormalising sampler
            int ia = i + q / SUB_STEPS;
            double wa = (double) (q % SUB_STEPS) / SUB_STEPS;
            int ib = Math.min(ia + 1, nMaj - 1);
            int jo = (int) y;
            double wb = y - jo;
            int ja = j + jo;
            int jb = Math.min(ja + 1, cellHi);
            double z00 = v[idx(ia, ja)];
            double z10 = v[idx(ib, ja)];
            double z01 = v[idx(ia, jb)];
            double z11 = v[idx(ib, jb)];
            double z = (z00 + (z10 - z00) * wa) * (1 - wb) + (z01 + (z11 - z01) * wa) * wb;
            if (z != z) {
                z = frameSample(i, j, t);
            }
            double dist = t * d;
            if (z == z && z - bc * dist * dist > z0 + dist * tan) {
                return true;
            }
        }
    }

    /**
     * Walks line k from iTop down to the window, storing for each window column i the shadow height at i from the
     * line's samples at i + 2 and beyond ({@code −∞} when none), and the distance to the sample that sets it.
     */
    private void walkLine(Window w, int k, Line line) {
        double tan = f.tanElevation;
        double bc = f.curvature;
        int wi0 = w.wi0;
        int iTop = w.iTop;
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
        int wi1 = w.wi1;
        if (iHi < iLo) {
            java.util.Arrays.fill(line.height, Double.NEGATIVE_INFINITY);
            return;
        }
        java.util.Arrays.fill(line.height, 0, iLo - wi0, Double.NEGATIVE_INFINITY);
        if (iHi < wi1) {
            java.util.Arrays.fill(line.height, iHi + 1 - wi0, wi1 + 1 - wi0, Double.NEGATIVE_INFINITY);
        }
        if (bc == 0 && uniformStep == uniformStep) {
            walkUniform(k, iLo, iHi, wi0, wi1, line.height);
            return;
        }
        double[] pos = line.pos;
        boolean uniform = uniformStep == uniformStep;
        double step = uniformStep;
        // pos[i - wi0] = distance downstream from the line's top on the whole grid, iHiAll: the same numbers
        // whatever window and halo cut the walk at iHi
        int iHiAll = m > 0 ? (int) Math.min(nMaj - 1, Math.floor((nMin - k) / m) + 1) : nMaj - 1;
        if (uniform) {
            pos[iHi - wi0] = (iHiAll - iHi) * step;
        } else {
            double top = 0;
            for (int i = iHiAll - 1; i >= iHi; i--) {
                top += f.metresPerStep[rowOf(i, lineRow(k, i))];
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
                    pos[i - wi0] = pos[i + 1 - wi0] + f.metresPerStep[rowOf(i, lineRow(k, i))];
                }
            }
            double p = pos[i - wi0];
            // the sample two steps upstream, or the one on the file's upstream outer edge half a step beyond the last
            // whole step (joins for i = nMaj − 2, as a sample at i + 2 would)
            boolean half = i + 2 > iHi && i == nMaj - 2 && iHi == nMaj - 1 && upstreamEdgeSample;
            if (i + 2 <= iHi || half) {
                double z = half ? edgeSample(k) : lineSample(k, i + 2);
                if (z == z) {
                    double pz = half ? pos[iHi - wi0] - 0.5 * f.metresPerStep[rowOf(iHi, lineRow(k, iHi))]
                            : pos[i + 2 - wi0];
                    if (bc == 0) {
                        double val = z + tan * pz;
                        if (val > best) {
                            best = val;
                        }
                    } else {
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
            }
            if (i <= wi1) {
                int at = i - wi0;
                if (bc == 0) {
                    line.height[at] = best - tan * p;
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

    /** The minor cell nearest to line k at major index i, clamped into the grid. */
    private int lineRow(int k, int i) {
        return Math.max(0, Math.min(nMin - 1, k + pf[i] + (pr[i] >= 0.5 ? 1 : 0)));
    }

    /**
     * Line k on the file's upstream outer cell edge, half a major step beyond its last whole step nMaj − 1 (read
     * from the edge row, as the bilinear march reads the outer half cell), NaN when off the grid or no-data.
     */
    private double edgeSample(int k) {
        int i = nMaj - 1;
        double t = pr[i] + 0.5 * m;
        double ft = Math.floor(t);
        return sampleAt(i, k + pf[i] + (int) ft, t - ft);
    }

    /**
     * The running maximum's "sample at i + 1" before a walk that starts at the file's upstream edge (i = nMaj − 1):
     * the edge sample, half a step farther, so that it joins the shadow height from i = nMaj − 2 on.
     */
    private double edgeStart(int k, double drop) {
        double z = edgeSample(k);
        return z == z ? z - 0.5 * drop : Double.NEGATIVE_INFINITY;
    }

    /** {@link #walkLine} for hard shadows on a grid with one step length and no curvature: a running maximum. */
    private void walkUniform(int k, int iLo, int iHi, int wi0, int wi1, double[] height) {
        double drop = f.tanElevation * uniformStep;
        // best = max over samples i' ≥ i + 2 of z(i') − (i' − i)·drop, kept relative to the current i
        double best = Double.NEGATIVE_INFINITY;
        double prev = Double.NEGATIVE_INFINITY;   // sample at i + 1 (joins best one step later)
        if (iHi == nMaj - 1 && upstreamEdgeSample) {
            prev = edgeStart(k, drop);
        }
        for (int i = iHi; i >= iLo; i--) {
            if (i <= wi1) {
                height[i - wi0] = best;
            }
            double z = lineSample(k, i);
            best = (best >= prev ? best : prev) - drop;   // never NaN: a comparison, not Math.max (see Clamp)
            prev = z == z ? z - drop : Double.NEGATIVE_INFINITY;
        }
    }

    /**
     * The major indices a block of lines kFrom … kTo + 1 walks in lockstep, {iStart, iEnd} (from iStart down to
     * iEnd), or null when the block meets no cell of the window.
     */
    private int[] blockRange(Window w, int kFrom, int kTo) {
        int iStart = w.iTop;
        int iEnd = w.wi0;
        if (m > 0) {
            iStart = (int) Math.min(iStart, Math.floor((nMin - kFrom) / m) + 1);
            iEnd = (int) Math.max(iEnd, Math.ceil((w.wj0 - kTo - 2) / m) - 1);
        } else if (kTo + 1 < -1 || kFrom > nMin - 1) {
            return null;
        }
        return iStart < iEnd ? null : new int[] {iStart, iEnd};
    }

    /**
     * {@link #bands} for hard shadows on the bilinear surface of a grid with one step length and no curvature: the
     * lines kFrom … kTo + 1 are walked in lockstep, one major index at a time from the sun's side, each carrying the
     * running maximum of {@link #walkUniform}, and the cells between them are evaluated as soon as both of their
     * lines have reached them. At one major index every line samples the same fraction between the same two minor
     * cells, so the samples of all lines (and the cells between them) are neighbours in memory: one contiguous run
     * of the row when the sun is north or south (y-major), a few cache lines reused for 16 columns otherwise.
     */
    private void bandsUniformHard(Window w, int kFrom, int kTo) {
        int lines = kTo - kFrom + 2;
        double drop = f.tanElevation * uniformStep;
        double dTan = uniformStep * f.tanElevation;
        double tFirst = (double) firstSample() / SUB_STEPS;
        int[] range = blockRange(w, kFrom, kTo);
        if (range == null) {
            return;
        }
        int iStart = range[0];
        int iEnd = range[1];
        double[] best = new double[lines];
        double[] prev = new double[lines];
        double[] h = new double[lines];
        java.util.Arrays.fill(best, Double.NEGATIVE_INFINITY);
        java.util.Arrays.fill(prev, Double.NEGATIVE_INFINITY);
        Strips strips = new Strips(thinFeatures ? lines - 1 : 0);
        int rTop = Math.min(w.iTop, nMaj - 1);
        if (iStart == nMaj - 1 && upstreamEdgeSample) {
            for (int q = 0; q < lines; q++) {
                prev[q] = edgeStart(kFrom + q, drop);
            }
        }
        float[] out = w.out;
        CellWindow win = w.win;
        int outStrideJ = rj * win.width() + cj;
        int wi1 = w.wi1;
        int wj0 = w.wj0;
        int wj1 = w.wj1;
        int sj = strideJ;
        for (int i = iStart; i >= iEnd; i--) {
            int pfi = pf[i];
            double fr = pr[i];
            int base = baseI[i];
            // lines kFrom + q whose two minor cells jj, jj + 1 are both on the grid
            int qa = Math.max(0, -kFrom - pfi);
            int qb = Math.min(lines - 1, cellHi - 1 - kFrom - pfi);
            for (int q = 0; q < Math.min(qa, lines); q++) {
                advance(best, prev, h, q, lineSample(kFrom + q, i), drop);
            }
            if (qa <= qb) {
                int at = base + sj * (kFrom + qa + pfi);
                if (fr == 0) {
                    for (int q = qa, qEnd = qb + 1; q < qEnd; q++, at += sj) {
                        double b = best[q];
                        double p = prev[q];
                        double z = v[at];
                        h[q] = b;
                        best[q] = (b >= p ? b : p) - drop;
                        prev[q] = z == z ? z - drop : Double.NEGATIVE_INFINITY;
                    }
                } else {
                    double za = v[at];
                    for (int q = qa, qEnd = qb + 1; q < qEnd; q++) {
                        at += sj;
                        double zb = v[at];
                        double z;
                        if (za == za && zb == zb) {
                            z = za + (zb - za) * fr;
                        } else {
                            z = za == za ? za : zb;
                        }
                        double b = best[q];
                        double p = prev[q];
                        h[q] = b;
                        best[q] = (b >= p ? b : p) - drop;
                        prev[q] = z == z ? z - drop : Double.NEGATIVE_INFINITY;
                        za = zb;
                    }
                }
            }
            for (int q = Math.max(qb + 1, Math.max(qa, 0)); q < lines; q++) {
                advance(best, prev, h, q, lineSample(kFrom + q, i), drop);
            }
            // cells j = kFrom + q + pfi + c between lines q and q + 1, q = 0 … lines − 2
            int c = fr > 0 ? 1 : 0;
            double phi = fr > 0 ? 1 - fr : 0;
            int off = kFrom + pfi + c;
            if (thinFeatures && i + 2 <= rTop) {
                strips.take(this, i + 2, kFrom, drop);
            }
            if (i > wi1) {
                continue;
            }
            int q0 = Math.max(0, wj0 - off);
            int q1 = Math.min(lines - 2, wj1 - off);
            if (q0 > q1) {
                continue;
            }
            int outBase = (r0 + ri * i - win.row()) * win.width() + (c0 + ci * i - win.col());
            boolean inner = i + 1 < nMaj;
            int up = inner ? baseI[i + 1] : 0;
            // cells whose ray leaves through the file's exit edge within a few steps (j ≥ jTraced) are traced
            // in a loop of their own, so that the common loop holds no ray march
            int qEdge = jTraced == Integer.MAX_VALUE ? q1 + 1
                    : (int) Math.max(q0, Math.min(q1 + 1L, (long) jTraced - off));
            for (int q = q0; q < qEdge; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    boolean shadow = between(h[q], h[q + 1], phi, uniformFloor) > z0
                            || thinFeatures && strips.blocks(this, q, kFrom + q, i, phi, z0, drop)
                            || firstStepBlocked(i, j, cell, z0, inner, up, dTan, tFirst, f.tanElevation);
                    result = shadow ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
            for (int q = qEdge, qEnd = q1 + 1; q < qEnd; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    boolean shadow = rayBlockedToEdge(i, j, z0)
                            || firstStepBlocked(i, j, cell, z0, inner, up, dTan, tFirst, f.tanElevation);
                    result = shadow ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
        }
    }

    /**
     * {@link #bandsUniformHard} for several sun elevations at once ({@link #runLevels}): each line's sample is read
     * once and feeds one running maximum per elevation, and each cell gets one bit per elevation, decided by exactly
     * the arithmetic of a single-elevation walk (its drop, floor and first-cell test).
     */
    private void bandsLevels(Window w, int kFrom, int kTo, double[] tans, int[] bits) {
        int lines = kTo - kFrom + 2;
        int n = tans.length;
        double[] drop = new double[n];
        double[] dTan = new double[n];
        double[] floor = new double[n];
        for (int e = 0; e < n; e++) {
            drop[e] = tans[e] * uniformStep;
            dTan[e] = uniformStep * tans[e];
            floor[e] = lowestTerrain - ShadowHalo.FLOOR_STEPS * uniformStep * tans[e];
        }
        double tFirst = (double) firstSample() / SUB_STEPS;
        int[] range = blockRange(w, kFrom, kTo);
        if (range == null) {
            return;
        }
        int iStart = range[0];
        int iEnd = range[1];
        // per line q, elevation e at q·n + e
        double[] best = new double[lines * n];
        double[] prev = new double[lines * n];
        double[] h = new double[lines * n];
        java.util.Arrays.fill(best, Double.NEGATIVE_INFINITY);
        java.util.Arrays.fill(prev, Double.NEGATIVE_INFINITY);
        if (iStart == nMaj - 1 && upstreamEdgeSample) {
            for (int q = 0; q < lines; q++) {
                for (int e = 0; e < n; e++) {
                    prev[q * n + e] = edgeStart(kFrom + q, drop[e]);
                }
            }
        }
        CellWindow win = w.win;
        int outStrideJ = rj * win.width() + cj;
        int sj = strideJ;
        for (int i = iStart; i >= iEnd; i--) {
            int pfi = pf[i];
            double fr = pr[i];
            int base = baseI[i];
            int qa = Math.max(0, -kFrom - pfi);
            int qb = Math.min(lines - 1, cellHi - 1 - kFrom - pfi);
            int before = Math.min(qa, lines);
            for (int q = 0; q < before; q++) {
                advanceLevels(best, prev, h, q * n, n, lineSample(kFrom + q, i), drop);
            }
            if (qa <= qb) {
                int at = base + sj * (kFrom + qa + pfi);
                double za = v[at];
                for (int q = qa, qEnd = qb + 1; q < qEnd; q++) {
                    at += sj;
                    double zb = v[at];
                    double z = fr == 0 ? za : za == za && zb == zb ? za + (zb - za) * fr : za == za ? za : zb;
                    advanceLevels(best, prev, h, q * n, n, z, drop);
                    za = zb;
                }
            }
            for (int q = Math.max(qb + 1, before); q < lines; q++) {
                advanceLevels(best, prev, h, q * n, n, lineSample(kFrom + q, i), drop);
            }
            if (i > w.wi1) {
                continue;
            }
            int c = fr > 0 ? 1 : 0;
            double phi = fr > 0 ? 1 - fr : 0;
            int off = kFrom + pfi + c;
            int q0 = Math.max(0, w.wj0 - off);
            int q1 = Math.min(lines - 2, w.wj1 - off);
            if (q0 > q1) {
                continue;
            }
            int outBase = (r0 + ri * i - win.row()) * win.width() + (c0 + ci * i - win.col());
            boolean inner = i + 1 < nMaj;
            int up = inner ? baseI[i + 1] : 0;
            for (int q = q0, qEnd = q1 + 1; q < qEnd; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                int blocked = 0;
                if (z0 == z0) {
                    boolean edge = j >= jTraced;
                    // the first-cell test of firstStepBlocked, its terms that do not depend on the elevation once
                    boolean closed = inner && j + 1 < nMin;
                    boolean above = false;
                    double lin0 = 0;
                    double quad = 0;
                    if (closed) {
                        int u = up + sj * j;
                        double z10 = v[u];
                        double z01 = v[cell + sj];
                        double z11 = v[u + sj];
                        lin0 = (z10 - z0) + (z01 - z0) * m;
                        quad = (z11 - z10 - z01 + z0) * m;
                        closed = lin0 + quad == lin0 + quad;       // no no-data corner
                        above = z10 > z0 | z01 > z0 | z11 > z0;
                    }
                    for (int e = 0; e < n; e++) {
                        boolean lineShadow = edge ? rayBlockedToEdge(i, j, z0, tans[e])
                                : between(h[q * n + e], h[(q + 1) * n + e], phi, floor[e]) > z0;
                        double lin = lin0 - dTan[e];
                        boolean first = closed ? above & (lin + quad * tFirst > 0 | lin + quad > 0)
                                : firstStepBlocked(i, j, cell, z0, inner, up, dTan[e], tFirst, tans[e]);
                        if (lineShadow || first) {
                            blocked |= 1 << e;
                        }
                    }
                }
                bits[outBase + outStrideJ * j] = blocked;
            }
        }
    }

    /**
     * Starts the lines kFrom … kFrom + top.length − 1 of a lat/lon lockstep walk at major index iStart: each line's
     * top on the whole grid (P = 0 there) and P at iStart, summed as {@link #walkLine} sums it. Returns per line q the
     * file's upstream outer edge sample, half a step beyond the top, at [2q] (NaN = none) and its P at [2q + 1]: it
     * joins the running maximum as a sample at i + 2.
     */
    private double[] startVaryingLines(int kFrom, int iStart, int[] top, double[] pos) {
        double[] steps = f.metresPerStep;
        boolean edgeHalf = iStart == nMaj - 1 && upstreamEdgeSample;
        double[] edge = new double[2 * top.length];
        for (int q = 0; q < top.length; q++) {
            int k = kFrom + q;
            int t = m > 0 ? (int) Math.min(nMaj - 1, Math.floor((nMin - k) / m) + 1) : nMaj - 1;
            double p = 0;
            for (int i = t - 1; i > iStart; i--) {           // a window's halo cuts the line below its top
                p += steps[rowOf(i, lineRow(k, i))];
            }
            top[q] = t;
            pos[q] = p;
            boolean half = edgeHalf && t == nMaj - 1;
            edge[2 * q] = half ? edgeSample(k) : Double.NaN;
            edge[2 * q + 1] = half ? 0.0 - 0.5 * steps[rowOf(nMaj - 1, lineRow(k, nMaj - 1))] : 0;
        }
        return edge;
    }

    /**
     * {@link #bandsLevels} on a grid whose step length changes from row to row: {@link #bandsVaryingHard}'s walk with
     * one running maximum per elevation (the distance P along each line is the same for all of them). The line walk
     * repeats {@link #bandsVaryingHard}'s on purpose: shared through methods and an interface for the two kinds of
     * line state, it cost the single-elevation walk 12–22 % (JMH, three alternating pairs).
     */
    private void bandsLevelsVarying(Window w, int kFrom, int kTo, double[] tans, int[] bits) {
        int lines = kTo - kFrom + 2;
        int n = tans.length;
        double[] steps = f.metresPerStep;
        double tFirst = (double) firstSample() / SUB_STEPS;
        int[] range = blockRange(w, kFrom, kTo);
        if (range == null) {
            return;
        }
        int iStart = range[0];
        int iEnd = range[1];
        VaryingLevels walk = new VaryingLevels(lines, tans);
        double[] upstreamEdge = startVaryingLines(kFrom, iStart, walk.top, walk.pos);
        for (int q = 0; q < lines; q++) {
            double ze = upstreamEdge[2 * q];
            for (int e = 0; ze == ze && e < n; e++) {
                walk.oneUp[q * n + e] = ze + tans[e] * upstreamEdge[2 * q + 1];
            }
        }
        double[] h = walk.h;
        CellWindow win = w.win;
        int outStrideJ = rj * win.width() + cj;
        int sj = strideJ;
        for (int i = iStart; i >= iEnd; i--) {
            int pfi = pf[i];
            double fr = pr[i];
            int qa = Math.max(0, -kFrom - pfi);
            int qb = Math.min(lines - 1, cellHi - 1 - kFrom - pfi);
            int near = kFrom + pfi + (fr >= 0.5 ? 1 : 0);    // lineRow(kFrom + q, i) = clamp(near + q)
            boolean xMajor = f.xMajor;
            double rowStep = xMajor ? Double.NaN : steps[r0 + ri * i];
            int before = Math.min(qa, lines);
            for (int q = 0; q < before; q++) {
                double st = xMajor ? steps[r0 + rj * Math.max(0, Math.min(nMin - 1, near + q))] : rowStep;
                walk.advance(q, i, lineSample(kFrom + q, i), st);
            }
            if (qa <= qb) {
                int at = baseI[i] + sj * (kFrom + qa + pfi);
                double za = v[at];
                for (int q = qa, qEnd = qb + 1; q < qEnd; q++) {
                    at += sj;
                    double zb = v[at];
                    double zq = fr == 0 ? za : za == za && zb == zb ? za + (zb - za) * fr : za == za ? za : zb;
                    walk.advance(q, i, zq, xMajor ? steps[r0 + rj * (near + q)] : rowStep);
                    za = zb;
                }
            }
            for (int q = Math.max(qb + 1, before); q < lines; q++) {
                double st = xMajor ? steps[r0 + rj * Math.max(0, Math.min(nMin - 1, near + q))] : rowStep;
                walk.advance(q, i, lineSample(kFrom + q, i), st);
            }
            if (i > w.wi1) {
                continue;
            }
            int c = fr > 0 ? 1 : 0;
            double phi = fr > 0 ? 1 - fr : 0;
            int off = kFrom + pfi + c;
            int q0 = Math.max(0, w.wj0 - off);
            int q1 = Math.min(lines - 2, w.wj1 - off);
            if (q0 > q1) {
                continue;
            }
            int outBase = (r0 + ri * i - win.row()) * win.width() + (c0 + ci * i - win.col());
            boolean inner = i + 1 < nMaj;
            int up = inner ? baseI[i + 1] : 0;
            int base = baseI[i];
            for (int q = q0, qEnd = q1 + 1; q < qEnd; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                int blocked = 0;
                if (z0 == z0) {
                    int row = rowOf(i, j);
                    double step = steps[row];
                    boolean edge = j >= jTraced;
                    for (int e = 0; e < n; e++) {
                        double tan = tans[e];
                        double floor = lowestTerrain - ShadowHalo.FLOOR_STEPS * step * tan;
                        boolean lineShadow = edge ? rayBlockedToEdge(i, j, z0, tan)
                                : between(h[q * n + e], h[(q + 1) * n + e], phi, floor) > z0;
                        if (lineShadow || firstStepBlocked(i, j, cell, z0, inner, up, step * tan, tFirst, tan)) {
                            blocked |= 1 << e;
                        }
                    }
                }
                bits[outBase + outStrideJ * j] = blocked;
            }
        }
    }

    /** {@link VaryingWalk} with one running maximum per elevation: line q, elevation e at q·n + e. */
    private static final class VaryingLevels {
        final double[] best;
        final double[] twoUp;
        final double[] oneUp;
        final double[] h;
        final double[] pos;
        final int[] top;
        final double[] tans;

        VaryingLevels(int lines, double[] tans) {
            int n = tans.length;
            best = new double[lines * n];
            twoUp = new double[lines * n];
            oneUp = new double[lines * n];
            h = new double[lines * n];
            pos = new double[lines];
            top = new int[lines];
            this.tans = tans;
            java.util.Arrays.fill(best, Double.NEGATIVE_INFINITY);
            java.util.Arrays.fill(twoUp, Double.NEGATIVE_INFINITY);
            java.util.Arrays.fill(oneUp, Double.NEGATIVE_INFINITY);
        }

        /** {@link VaryingWalk#advance} of line q for every elevation. */
        void advance(int q, int i, double z, double step) {
            int t = top[q];
            if (i < t) {
                pos[q] += step;
            }
            double p = pos[q];
            boolean sample = i <= t && z == z;
            int n = tans.length;
            for (int e = 0, at = q * n; e < n; e++, at++) {
                double tan = tans[e];
                double b = best[at];
                double joining = twoUp[at];
                if (joining > b) {
                    b = joining;
                }
                best[at] = b;
                h[at] = b - tan * p;
                twoUp[at] = oneUp[at];
                oneUp[at] = sample ? z + tan * p : Double.NEGATIVE_INFINITY;
            }
        }
    }

    /** {@link #advance} of one line for each elevation: its values at {@code off} … {@code off + n − 1}. */
    private static void advanceLevels(double[] best, double[] prev, double[] h, int off, int n, double z,
                                      double[] drop) {
        for (int e = 0; e < n; e++) {
            int at = off + e;
            double b = best[at];
            double p = prev[at];
            h[at] = b;
            best[at] = (b >= p ? b : p) - drop[e];
            prev[at] = z == z ? z - drop[e] : Double.NEGATIVE_INFINITY;
        }
    }

    /**
     * {@link #bandsUniformHard} for a grid whose step length changes from row to row (lat/lon grids): the lines
     * kFrom … kTo + 1 are walked in lockstep with the arithmetic of {@link #walkLine} for such grids, a running
     * maximum of z + tan·P over each line's samples from two steps upstream on (P = the distance from the line's top,
     * summed step by step in the same order), and the cells between them evaluated with their own row's step and
     * floor, so the mask is bit-identical to the line-by-line path. Hard shadows without curvature or thin features.
     */
    private void bandsVaryingHard(Window w, int kFrom, int kTo) {
        int lines = kTo - kFrom + 2;
        double tan = f.tanElevation;
        double[] steps = f.metresPerStep;
        double tFirst = (double) firstSample() / SUB_STEPS;
        int[] range = blockRange(w, kFrom, kTo);
        if (range == null) {
            return;
        }
        int iStart = range[0];
        int iEnd = range[1];
        VaryingWalk walk = new VaryingWalk(lines, tan);
        double[] upstreamEdge = startVaryingLines(kFrom, iStart, walk.top, walk.pos);
        for (int q = 0; q < lines; q++) {
            double ze = upstreamEdge[2 * q];
            if (ze == ze) {
                walk.oneUp[q] = ze + tan * upstreamEdge[2 * q + 1];
            }
        }
        double[] h = walk.h;
        float[] out = w.out;
        CellWindow win = w.win;
        int outStrideJ = rj * win.width() + cj;
        int sj = strideJ;
        for (int i = iStart; i >= iEnd; i--) {
            int pfi = pf[i];
            double fr = pr[i];
            int qa = Math.max(0, -kFrom - pfi);
            int qb = Math.min(lines - 1, cellHi - 1 - kFrom - pfi);
            int near = kFrom + pfi + (fr >= 0.5 ? 1 : 0);    // lineRow(kFrom + q, i) = clamp(near + q)
            boolean xMajor = f.xMajor;
            double rowStep = xMajor ? Double.NaN : steps[r0 + ri * i];   // the step of every line when y-major
            int before = Math.min(qa, lines);
            for (int q = 0; q < before; q++) {
                double st = xMajor ? steps[r0 + rj * Math.max(0, Math.min(nMin - 1, near + q))] : rowStep;
                walk.advance(q, i, lineSample(kFrom + q, i), st);
            }
            if (qa <= qb) {
                // the lines whose two minor cells are on the grid: read straight from the array
                int at = baseI[i] + sj * (kFrom + qa + pfi);
                double za = v[at];
                for (int q = qa, qEnd = qb + 1; q < qEnd; q++) {
                    at += sj;
                    double zb = v[at];
                    double zq = fr == 0 ? za : za == za && zb == zb ? za + (zb - za) * fr : za == za ? za : zb;
                    walk.advance(q, i, zq, xMajor ? steps[r0 + rj * (near + q)] : rowStep);
                    za = zb;
                }
            }
            for (int q = Math.max(qb + 1, before); q < lines; q++) {
                double st = xMajor ? steps[r0 + rj * Math.max(0, Math.min(nMin - 1, near + q))] : rowStep;
                walk.advance(q, i, lineSample(kFrom + q, i), st);
            }
            if (i > w.wi1) {
                continue;
            }
            int c = fr > 0 ? 1 : 0;
            double phi = fr > 0 ? 1 - fr : 0;
            int off = kFrom + pfi + c;
            int q0 = Math.max(0, w.wj0 - off);
            int q1 = Math.min(lines - 2, w.wj1 - off);
            if (q0 > q1) {
                continue;
            }
            int outBase = (r0 + ri * i - win.row()) * win.width() + (c0 + ci * i - win.col());
            boolean inner = i + 1 < nMaj;
            int up = inner ? baseI[i + 1] : 0;
            int base = baseI[i];
            for (int q = q0, qEnd = q1 + 1; q < qEnd; q++) {
                int j = off + q;
                int cell = base + sj * j;
                double z0 = v[cell];
                float result = 0f;
                if (z0 == z0) {
                    int row = rowOf(i, j);
                    boolean shadow = j >= jTraced ? rayBlockedToEdge(i, j, z0)
                            : between(h[q], h[q + 1], phi, floorOfRow[row]) > z0;
                    result = shadow || firstStepBlocked(i, j, cell, z0, inner, up, steps[row] * tan, tFirst, tan)
                            ? 1f : 0f;
                }
                out[outBase + outStrideJ * j] = result;
            }
        }
    }

    /**
     * The lines of {@link #bandsVaryingHard}: per line, the running maximum of z + tan·P over its samples from two
     * steps upstream on, the two samples still to join, P at the current major index and the line's top (P = 0).
     */
    private static final class VaryingWalk {
        final double[] best;
        final double[] twoUp;
        final double[] oneUp;
        final double[] pos;
        final double[] h;
        final int[] top;
        final double tan;

        VaryingWalk(int lines, double tan) {
            best = new double[lines];
            twoUp = new double[lines];
            oneUp = new double[lines];
            pos = new double[lines];
            h = new double[lines];
            top = new int[lines];
            this.tan = tan;
            java.util.Arrays.fill(best, Double.NEGATIVE_INFINITY);
            java.util.Arrays.fill(twoUp, Double.NEGATIVE_INFINITY);
            java.util.Arrays.fill(oneUp, Double.NEGATIVE_INFINITY);
        }

        /**
         * Line q at major index i, whose sample there is z (NaN = none) and whose step from i + 1 is {@code step}:
         * its shadow height h[q] = max(z + tan·P over samples two or more steps upstream) − tan·P(i).
         */
        void advance(int q, int i, double z, double step) {
            int t = top[q];
            if (i < t) {
                pos[q] += step;
            }
            double p = pos[q];
            double b = best[q];
            double joining = twoUp[q];
            if (joining > b) {
                b = joining;
            }
            best[q] = b;
            h[q] = b - tan * p;
            twoUp[q] = oneUp[q];
            oneUp[q] = i <= t && z == z ? z + tan * p : Double.NEGATIVE_INFINITY;
        }
    }

    /**
     * The terrain a cell's own ray meets at major index {@code iStar}, on the line position k + φ (φ = the cell's
     * fraction between lines k and k + 1, its offset across the sun direction, the same at every major index),
     * less the ray's rise over the {@code iStar − i} steps: one sample of the cell's own march, read as the lines
     * read theirs. {@code −∞} when there is none (no index, off the grid, no-data).
     */
    private double ownSample(int k, int i, double phi, int iStar, double drop) {
        if (iStar < 0) {
            return Double.NEGATIVE_INFINITY;
        }
        double t = pr[iStar] + phi;
        int ft = t >= 1 ? 1 : 0;
        double z = sampleAt(iStar, k + pf[iStar] + ft, t - ft);
        return z == z ? z - (iStar - i) * drop : Double.NEGATIVE_INFINITY;
    }

    /** Cell j at major index i, {@code −∞} when outside [0, cellHi] or no-data ({@link #around}'s terms). */
    private double cellOrNone(int i, int j) {
        if (j < 0 || j > cellHi) {
            return Double.NEGATIVE_INFINITY;
        }
        double z = v[baseI[i] + strideJ * j];
        return z == z ? z : Double.NEGATIVE_INFINITY;
    }

    /**
     * The strip's terrain bound at major index i, whose strip cell is s: the highest of cells s − 1, s and s + 1
     * ({@link #cellOrNone}), a bound on every sample {@link #sampleAt} takes between positions s − 1 and s + 1; or
     * {@code −∞} when no own-ray sample there can be above the lines' estimate. The lines pass the row at s − 1 + p
     * and s + p (p = the row's fraction); a cell between them samples the two segments through s, whose excess over
     * the chord between the lines' samples is at most p·(1 − p)·(2·z(s) − z(s − 1) − z(s + 1)): nothing when the
     * lines pass through cell centres (p = 0) or when cell s is not above the mean of its neighbours (then the
     * cell's own samples lie on or below the chord, and the interpolated shadow height at least as high). A row
     * with a missing cell is kept.
     */
    private double around(int i, int s) {
        return pr[i] > 0 ? bound(cellOrNone(i, s - 1), cellOrNone(i, s), cellOrNone(i, s + 1))
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
     * The upper convex hull of a strip's terrain bounds ({@link #around}) upstream of the current cell, as points
     * (x, bound) with x growing downstream: −i on a grid with one step length, else the distance along the strip.
     * For a cell at x its tangent point is the sample of the steepest bound as seen from the cell, (bound −
     * z₀)/(x − xᵢ): the cell's own ray is tested there ({@link #ownSample}). The lines, which pass up to a cell to
     * either side, see a thin feature (a one-cell spike, a narrow ridge across the sun) only partly, and their
     * interpolated shadow height then falls short of it; the own-ray sample is one the cell's own march takes, so
     * it never shades a cell that march leaves lit. The choice does not depend on the sun's elevation, so raising
     * the sun never adds shadow; and a window whose halo holds every sample above the cell's ray chooses the same
     * point as the whole grid (a steeper point beyond the halo is below the ray, and then so is everything else).
     */
    private static final class StripHull {
        private double[] x = new double[16];
        private double[] z = new double[16];
        private int[] at = new int[16];
        private int size;

        /** Adds point (px, pz) of major index i; px must exceed every x added before. */
        void push(double px, double pz, int i) {
            while (size >= 2 && cross(size - 2, size - 1, px, pz) >= 0) {
                size--;
            }
            if (size == x.length) {
                x = java.util.Arrays.copyOf(x, 2 * size);
                z = java.util.Arrays.copyOf(z, 2 * size);
                at = java.util.Arrays.copyOf(at, 2 * size);
            }
            x[size] = px;
            z[size] = pz;
            at[size] = i;
            size++;
        }

        /** (b − a) × (q − a) for hull points a, b: ≥ 0 when q is on or above the line through them. */
        private double cross(int a, int b, double qx, double qz) {
            return (x[b] - x[a]) * (qz - z[a]) - (z[b] - z[a]) * (qx - x[a]);
        }

        /**
         * The major index of the point that maximises (bound − qz)/(qx − x) for qx beyond every point, −1 when the
         * hull is empty: the first point whose next edge's line passes on or below (qx, qz).
         */
        int tangent(double qx, double qz) {
            if (size == 0) {
                return -1;
            }
            int lo = 0;
            int hi = size - 1;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (cross(mid, mid + 1, qx, qz) >= 0) {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            return at[lo];
        }
    }

    /**
     * Per strip (the cells between two adjacent lines): the hull of its terrain bounds ({@link #around}) two or
     * more major steps upstream, and the highest of bound − i·drop over them: a cell at i below that plus i·drop
     * cannot be shaded by any sample of its own ray, so the hull is not asked. Rows whose bound is {@code −∞} cost
     * one test and nothing else.
     */
    private static final class Strips {
        final double[] best;
        final StripHull[] hull;

        Strips(int n) {
            best = new double[Math.max(n, 0)];
            hull = new StripHull[best.length];
            java.util.Arrays.fill(best, Double.NEGATIVE_INFINITY);
            for (int q = 0; q < hull.length; q++) {
                hull[q] = new StripHull();
            }
        }

        /** Takes row r of every strip of a lockstep block whose first line is kFrom. */
        void take(SunSweep sweep, int r, int kFrom, double drop) {
            int n = best.length;
            if (n == 0 || !(sweep.pr[r] > 0)) {
                return;   // the lines pass through cell centres: no bound (see around)
            }
            int off = kFrom + sweep.pf[r] + 1;
            double left = sweep.cellOrNone(r, off - 1);
            double centre = sweep.cellOrNone(r, off);
            for (int q = 0; q < n; q++) {
                double right = sweep.cellOrNone(r, off + q + 1);
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
        boolean blocks(SunSweep sweep, int q, int k, int i, double phi, double z0, double drop) {
            if (!(best[q] + drop * i > z0)) {
                return false;
            }
            int iStar = hull[q].tangent(-i, z0);
            return sweep.ownSample(k, i, phi, iStar, drop) > z0;
        }
    }

    /**
     * {@link #localBlocked} for the lockstep loop: the bilinear surface never exceeds its highest corner; else
     * terrain − ray along the first step is t·(lin + quad·t), decided at the first and the last sample; a no-data
     * corner makes lin + quad NaN (also when m = 0), and then, or at the last row or column, localBlocked decides.
     *
     * @param up  the flat index of frame cell (i + 1, 0) when {@code inner}
     * @param tan the tangent of the sun's elevation (dTan = the step's length × tan)
     */
    private boolean firstStepBlocked(int i, int j, int cell, double z0, boolean inner, int up, double dTan,
                                     double tFirst, double tan) {
        if (!inner || j + 1 >= nMin) {
            return localBlocked(i, j, z0, tan);
        }
        int sj = strideJ;
        int u = up + sj * j;
        double z10 = v[u];
        double z01 = v[cell + sj];
        double z11 = v[u + sj];
        double lin = (z10 - z0) + (z01 - z0) * m - dTan;
        double quad = (z11 - z10 - z01 + z0) * m;
        double end = lin + quad;
        if (end == end) {
            return (z10 > z0 | z01 > z0 | z11 > z0) & (lin + quad * tFirst > 0 | end > 0);
        }
        return localBlocked(i, j, z0, tan);
    }

    private static void advance(double[] best, double[] prev, double[] h, int q, double z, double drop) {
        double b = best[q];
        h[q] = b;
        double p = prev[q];
        best[q] = (b >= p ? b : p) - drop;
        prev[q] = z == z ? z - drop : Double.NEGATIVE_INFINITY;
    }

    /** Evaluates the cells between lines k and k + 1. */
    private void band(Window w, int k, Line a, Line b, boolean[] own) {
        int iLo = w.wi0;
        int iHi = w.wi1;
        if (m > 0) {
            // cells j = k + floor(m·i + φ) (+1) with wj0 ≤ j ≤ wj1
            iHi = (int) Math.min(iHi, Math.floor((w.wj1 - k + 1) / m) + 1);
            iLo = (int) Math.max(iLo, Math.ceil((w.wj0 - k - 2) / m) - 1);
        }
        for (int i = iLo; i <= iHi; i++) {
            double fr = pr[i];
            int j = k + pf[i] + (fr > 0 ? 1 : 0);
            if (j < w.wj0 || j > w.wj1) {
                continue;
            }
            double phi = fr > 0 ? 1 - fr : 0;
            int at = i - w.wi0;
            int cell = idx(i, j);
            double z0 = v[cell];
            float result;
            if (z0 != z0) {
                result = 0f;
            } else {
                double ha = a.height[at];
                double hb = b.height[at];
                boolean lines = j >= jTraced ? rayBlockedToEdge(i, j, z0)
                        : between(ha, hb, phi, floorOfRow[rowOf(i, j)]) > z0 || own[at];
                result = (lines || localBlocked(i, j, z0)) ? 1f : 0f;
            }
            int col = c0 + ci * i + cj * j;
            int row = r0 + ri * i + rj * j;
            w.out[(row - w.win.row()) * w.win.width() + (col - w.win.col())] = result;
        }
    }

    /**
     * A cell's shadow height between its two lines, {@code phi} of the way from line a to line b. A line below
     * {@code floor} counts as having no terrain, so the other line's height is taken whole: the same answer
     * whether or not a window's halo reaches that line's distant samples.
     */
    private static double between(double ha, double hb, double phi, double floor) {
        if (phi == 0 || !(hb >= floor)) {
            return ha;
        }
        if (!(ha >= floor)) {
            return hb;
        }
        return ha + (hb - ha) * phi;
    }

    /** Terrain at fractional frame position (i + t, j + m·t), or NaN off the grid or no-data. */
    private double frameSample(int i, int j, double t) {
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

    /**
     * Offsets t of the first-cell samples: eighths up to one cell on the bilinear surface, else just the one-cell
     * sample. With nearest sampling the eighths would meet the next cell's block from t = ½ on while the ray is
     * still only half a step up, shading cells that the nearest march leaves lit (notes/sweep-bugs.md item 1).
     */
    private int firstSample() {
        return firstCellTest && bilinear ? 1 : SUB_STEPS;
    }

    /** True when the ray from cell (i, j) is blocked within its first major step. */
    private boolean localBlocked(int i, int j, double z0) {
        return localBlocked(i, j, z0, f.tanElevation);
    }

    /** {@link #localBlocked(int, int, double)} for a sun whose elevation has the tangent {@code tan}. */
    private boolean localBlocked(int i, int j, double z0, double tan) {
        double d = f.metresPerStep[rowOf(i, j)];
        double bc = f.curvature;
        if (bilinear && i + 1 < nMaj && j + 1 < nMin) {
            double z10 = v[idx(i + 1, j)];
            double z01 = v[idx(i, j + 1)];
            double z11 = v[idx(i + 1, j + 1)];
            if (z10 == z10 && z01 == z01 && z11 == z11) {
                if (z10 <= z0 && z01 <= z0 && z11 <= z0) {
                    return false;   // the bilinear surface never exceeds its highest corner
                }
                // terrain − ray along the first step is t·(A + B·t): linear in t after dividing by t > 0, so
                // its sign over the samples t = q/8 is decided at the first and the last sample
                double lin = (z10 - z0) + (z01 - z0) * m - d * tan;
                double quad = (z11 - z10 - z01 + z0) * m - bc * d * d;
                double tFirst = (double) firstSample() / SUB_STEPS;
                return lin + quad * tFirst > 0 || lin + quad > 0;
            }
        }
        for (int q = firstSample(); q <= SUB_STEPS; q++) {
            double t = (double) q / SUB_STEPS;
            double fi = i + t;
            double fj = j + m * t;
            if (fi > nMaj - 0.5 || fj > nMin - 0.5) {
                return false;
            }
            double z = frameSample(i, j, t);
            double dist = t * d;
            if (z == z && z - bc * dist * dist > z0 + dist * tan) {
                return true;
            }
        }
        return false;
    }
}
