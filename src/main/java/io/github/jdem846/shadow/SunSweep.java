package io.github.jdem846.shadow;

import io.github.jdem846.parallel.Cancellation;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.concurrent.ForkJoinPool;
import java.util.function.Consumer;

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
 * ({@link ThinFeatures}), so that a feature one cell wide, which the lines see only partly, shades its whole lee.
 *
 * <p>Work: one sample per line per column plus a constant per cell, whatever the sun elevation. Lines are split
 * into chunks across a ForkJoinPool; every line is computed the same way in any chunk, so the mask does not depend
 * on the thread count.
 *
 * <p>The pieces: {@link SweepGrid} the frame (line k is j = k + m·i) and the terrain a line reads; {@link SweepCell}
 * the rule that decides a cell, shared by every walk; {@link ReferenceWalk} the line-by-line walk, for every case;
 * the lockstep walks, a block of lines at once ({@link LockstepBlock}) for the common cases: {@link
 * UniformLockstep} (projected grids), {@link LatLonLockstep} (a step length per row) and {@link LevelsWalk}
 * (several elevations in one walk, for soft shadows); {@link ThinFeatures} the own-ray test. This class chooses the
 * walk and splits the lines into blocks.
 */
final class SunSweep {

    private static final int LINES_PER_TASK = 48;

    private final SweepGrid g;
    /** When false, every case takes the line-by-line walk ({@link ReferenceWalk}): the reference of the tests. */
    private final boolean lockstepAllowed;
    /** Each cell also tests one sample of its own ray ({@link ThinFeatures}). */
    private final boolean thinFeatures;
    private final ReferenceWalk reference;
    private final UniformLockstep uniform;
    private final LatLonLockstep latLon;
    private final SweepCell rule;

    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest) {
        this(dem, frame, bilinear, firstCellTest, true);
    }

    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest, boolean lockstepAllowed) {
        this(dem, frame, bilinear, firstCellTest, lockstepAllowed, Double.NaN, false);
    }

    /**
     * @param terrainMinimum the lowest elevation of the file {@code dem} was read from (NaN = the grid's own): the
     *                       floor below which a line counts as no terrain starts there
     * @param thinFeatures   also test each cell's own ray at its strip's steepest terrain ({@link ThinFeatures})
     */
    SunSweep(Dem dem, RayFrame frame, boolean bilinear, boolean firstCellTest, boolean lockstepAllowed,
             double terrainMinimum, boolean thinFeatures) {
        if (frame.soft()) {
            throw new IllegalArgumentException("the sweep traces hard shadows; soft shadows are built from hard sweeps"
                    + " at angles across the sun's disk (ShadowAlgorithm)");
        }
        this.thinFeatures = thinFeatures;
        this.lockstepAllowed = lockstepAllowed;
        this.g = new SweepGrid(dem, frame, bilinear, firstCellTest, terrainMinimum);
        this.rule = new SweepCell(g);
        ThinFeatures thin = thinFeatures ? new ThinFeatures(g) : null;
        this.reference = new ReferenceWalk(g, rule, thin);
        this.uniform = new UniformLockstep(g, rule, thin);
        this.latLon = new LatLonLockstep(g, rule);
    }

    /** The lowest floor of all rows: no line height below it is ever used (see the class comment). */
    double lowestFloor() {
        return g.lowestFloor;
    }

    /**
     * Computes the shadow of the cells of {@code win} into {@code out} (row-major, row length win.width()), reading
     * terrain up to {@code haloSteps} major steps upstream of the window (Integer.MAX_VALUE = the whole grid).
     */
    void run(CellWindow win, int haloSteps, float[] out, ForkJoinPool pool) {
        run(win, haloSteps, out, pool, ShadowProgress.NONE);
    }

    /** {@link #run(CellWindow, int, float[], ForkJoinPool)}, telling {@code progress} the blocks of lines done. */
    void run(CellWindow win, int haloSteps, float[] out, ForkJoinPool pool, ShadowProgress progress) {
        boolean lockstep = lockstepAllowed && g.bilinear && g.f.curvature == 0;
        BlockWork work;
        if (lockstep && g.uniform()) {
            work = inLockstep(uniform::walk);
        } else if (lockstep && !thinFeatures) {
            work = inLockstep(latLon::walk);
        } else {
            work = reference::walk;
        }
        forEachBlock(win, haloSteps, out, pool, work, progress);
    }

    /** True when {@link #runLevels} can walk several sun elevations at once (the lockstep cases of {@link #run}). */
    boolean canRunLevels() {
        return lockstepAllowed && g.bilinear && g.f.curvature == 0 && !thinFeatures;
    }

    /**
     * For the sun elevations whose tangents are {@code tans} (at most 31, same azimuth as this sweep's frame), sets
     * bit k of {@code bits[c]} when cell c of {@code win} (row-major, row length win.width()) is in shadow at
     * elevation k, exactly as {@link #run} with a frame at that elevation would find it, in one walk: the lines'
     * samples do not depend on the elevation, only the running maxima do. {@code haloSteps} must cover the lowest
     * elevation. Only when {@link #canRunLevels()}.
     */
    void runLevels(CellWindow win, int haloSteps, double[] tans, int[] bits, ForkJoinPool pool,
                   ShadowProgress progress) {
        if (!canRunLevels() || tans.length > 31) {
            throw new IllegalStateException("runLevels needs the lockstep case and at most 31 elevations");
        }
        LevelsWalk levels = new LevelsWalk(g, rule, tans);
        forEachBlock(win, haloSteps, null, pool, inLockstep(block -> levels.walk(block, bits)), progress);
    }

    /** The lockstep walk {@code walk} of each block of lines that meets the window ({@link LockstepBlock}). */
    private BlockWork inLockstep(Consumer<LockstepBlock> walk) {
        return (w, kFrom, kTo) -> {
            LockstepBlock block = LockstepBlock.of(g, w, kFrom, kTo);
            if (block != null) {
                walk.accept(block);
            }
        };
    }

    /** One block of lines kFrom … kTo + 1 of a window. */
    @FunctionalInterface
    private interface BlockWork {
        void run(SweepWindow w, int kFrom, int kTo);
    }

    /**
     * Splits the lines that reach {@code win} into blocks of {@link #LINES_PER_TASK} and runs them on the pool; once
     * the caller is interrupted no further block starts ({@link Cancellation}; a block takes milliseconds, tens on
     * the widest grids, so the walks themselves, the hot loops, test nothing).
     */
    private void forEachBlock(CellWindow win, int haloSteps, float[] out, ForkJoinPool pool, BlockWork work,
                              ShadowProgress progress) {
        int ia = g.frameI(win.col(), win.row());
        int ib = g.frameI(win.colEnd() - 1, win.rowEnd() - 1);
        int ja = g.frameJ(win.col(), win.row());
        int jb = g.frameJ(win.colEnd() - 1, win.rowEnd() - 1);
        int wi0 = Math.min(ia, ib);
        int wi1 = Math.max(ia, ib);
        int wj0 = Math.min(ja, jb);
        int wj1 = Math.max(ja, jb);
        int iTop = (int) Math.min(g.nMaj - 1L, (long) wi1 + haloSteps);
        int kMin = wj0 - g.pf[wi1] - 1;
        int kMax = wj1 - g.pf[wi0];
        SweepWindow w = new SweepWindow(win, wi0, wi1, wj0, wj1, iTop, out);
        int blocks = (int) Math.max(0, ((long) kMax - kMin + LINES_PER_TASK) / LINES_PER_TASK);
        Cancellation.invokeAll(pool, blocks, (b, cancel) -> {
            int from = kMin + b * LINES_PER_TASK;
            work.run(w, from, Math.min(kMax, from + LINES_PER_TASK - 1));
        }, done -> progress.update(done, blocks));
    }
}
