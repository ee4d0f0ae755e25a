package io.github.jdem846.shadow;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.parallel.Cancellation;
import io.github.jdem846.raster.Dem;
import java.util.concurrent.ForkJoinPool;

/**
 * The horizon of every cell in one azimuth, in O(cells): the sun sweep's lines ({@link SweepGrid}, {@link
 * LockstepBlock}), laid parallel to the azimuth one cell apart and walked from the side the azimuth points to, each
 * carrying the upper convex hull of its own samples ({@link HorizonHulls}) instead of a running shadow height. A
 * cell lies between two lines; the tangent of its horizon is the steepest slope from the cell (its own elevation,
 * at its distance along each line) to each of the two lines' terrain, interpolated linearly across by the cell's
 * position between them, as the sweep interpolates shadow heights. On the axes and diagonals the lines pass through
 * the cell centres and the horizon is that of the cell's own line. Distances are ground metres per row ({@link
 * RayFrame}: lat/lon grids get the right length at every latitude); no-data samples are skipped; terrain beyond the
 * grid, and a horizon below 0°, count as 0°.
 */
final class HorizonSweep {

    private static final int LINES_PER_TASK = 48;

    private final SweepGrid g;
    private final double heightScale;
    private final double radius;

    /**
     * @param dem         the terrain
     * @param azimuth     the direction looked in, degrees clockwise from north
     * @param heightScale factor applied to heights (the z-factor)
     * @param radius      the search radius in ground metres ({@link SkyViewOptions#radius()})
     */
    HorizonSweep(Dem dem, double azimuth, double heightScale, double radius) {
        RayFrame frame = new RayFrame(dem, new LightDirection(azimuth, 45), ShadowOptions.DEFAULTS);
        this.g = new SweepGrid(dem, frame, true, false, Double.NaN);
        this.heightScale = heightScale;
        this.radius = radius;
    }

    /**
     * Adds sin(horizon angle) of each cell of {@code win} to {@code sum} (row-major, row length win.width()); no-data
     * cells are left alone.
     */
    void addSines(CellWindow win, float[] sum, ForkJoinPool pool) {
        int ia = g.frameI(win.col(), win.row());
        int ib = g.frameI(win.colEnd() - 1, win.rowEnd() - 1);
        int ja = g.frameJ(win.col(), win.row());
        int jb = g.frameJ(win.colEnd() - 1, win.rowEnd() - 1);
        int wi0 = Math.min(ia, ib);
        int wi1 = Math.max(ia, ib);
        int wj0 = Math.min(ja, jb);
        int wj1 = Math.max(ja, jb);
        int kMin = wj0 - g.pf[wi1] - 1;
        int kMax = wj1 - g.pf[wi0];
        SweepWindow w = new SweepWindow(win, wi0, wi1, wj0, wj1, g.nMaj - 1, sum);
        int blocks = (int) Math.max(0, ((long) kMax - kMin + LINES_PER_TASK) / LINES_PER_TASK);
        Cancellation.invokeAll(pool, blocks, (b, cancel) -> {
            int from = kMin + b * LINES_PER_TASK;
            LockstepBlock block = LockstepBlock.of(g, w, from, Math.min(kMax, from + LINES_PER_TASK - 1));
            if (block != null) {
                walk(block);
            }
        });
    }

    private void walk(LockstepBlock block) {
        int lines = block.lines;
        LineHorizons hulls = radius < SkyViewOptions.UNBOUNDED ? new WindowedHulls(lines, radius)
                : new HorizonHulls(lines);
        LatLonLines at = new LatLonLines(g, block.kFrom, lines, block.iStart);
        // on a grid with one step length P is anchored at the file's grid, −(i + i0)·step, so that a window (whose
        // lines start lower) measures every distance with the same numbers as the whole grid
        boolean anchored = g.uniform();
        double[] pos = anchored ? new double[lines] : at.pos;
        int[] top = at.top;
        double[] zs = block.z;
        float[] v = g.v;
        float[] out = block.w.out();
        int outStrideJ = block.outStrideJ;
        int sj = g.strideJ;
        double k = heightScale;
        double m = g.m;
        double[] steps = g.f.metresPerStep;
        int cellHi = g.cellHi;
        for (int i = block.iStart; i >= block.iEnd; i--) {
            if (anchored) {
                java.util.Arrays.fill(pos, -(double) (i + g.i0) * g.uniformStep);
            } else {
                at.moveTo(i);
            }
            block.sample(i);
            if (block.cells(i)) {
                int off = block.off;
                double phi = block.phi;
                int outBase = block.outBase;
                int base = block.base;
                boolean inner = block.inner;
                int up = block.up;
                for (int q = block.q0, qEnd = block.q1; q < qEnd; q++) {
                    int j = off + q;
                    int cell = base + sj * j;
                    double z0 = v[cell];
                    if (z0 != z0) {
                        continue;
                    }
                    double t;
                    if (phi == 0) {
                        t = hulls.slope(q, pos[q], z0);
                    } else {
                        // each line is seen from its own sample here, moved by the cell's departure from the
                        // lines' interpolation: on a plane both lines then see exactly the cell's own profile
                        double za = zs[q];
                        double zb = zs[q + 1];
                        double rest = za == za && zb == zb ? z0 - (za + phi * (zb - za)) : 0;
                        double qa = za == za ? za + rest : z0;
                        double qb = zb == zb ? zb + rest : z0;
                        double ta = hulls.slope(q, pos[q], qa);
                        t = ta + phi * (hulls.slope(q + 1, pos[q + 1], qb) - ta);
                    }
                    t = Math.max(t, firstStep(v, cell, inner ? up + sj * j : -1, sj, j < cellHi, z0, m,
                            steps[g.rowOf(i, j)]));
                    t *= k;
                    out[outBase + outStrideJ * j] += (float) (t / Math.sqrt(1 + t * t));
                }
            }
            for (int q = 0; q < lines; q++) {
                double z = zs[q];
                if (i <= top[q] && z == z) {
                    hulls.push(q, pos[q], z);
                }
            }
        }
    }

    /**
     * The steepest slope from a cell to its own ray over the first major step, on the bilinear patch the ray
     * crosses there (corners: the cell z0, the next cell along the major axis, the next across, and the diagonal
     * one; beyond the grid's last cells the patch is clamped, as bilinear sampling is; the ray leaves the grid there within
     * half a step, and the clamped patch is flat along the axis it leaves by): z(t) − z0 = b·t + c·t²
     * for t in (0, 1], so the steepest slope is b (as t → 0) or b + c (at t = 1). The lines sample only at cell
     * centres and miss the bulge of a saddle between them. NaN corners: none (−∞).
     */
    private static double firstStep(float[] v, int cell, int upCell, int sj, boolean across, double z0, double m,
                                    double metres) {
        double z01 = across ? v[cell + sj] : z0;
        double z10 = upCell >= 0 ? v[upCell] : z0;
        double z11 = upCell < 0 ? z01 : across ? v[upCell + sj] : z10;
        double b = (z10 - z0) + m * (z01 - z0);
        double c = m * (z0 - z10 - z01 + z11);
        // Math.max, not a branch: the sign of c is as good as random on rough terrain
        double s = (b + Math.max(c, 0)) / metres;
        return s == s ? s : Double.NEGATIVE_INFINITY;
    }
}
