package io.github.jdem846.tiles;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.Dem;
import java.io.IOException;

/**
 * The whole DEM read once, box-averaged in blocks of {@code decimation} cells, for the zooms at which the whole DEM
 * is small (at most {@value #MAX_CELLS} cells at their own decimation): each of them takes its cells from here,
 * averaged again in blocks of a whole number of these cells, instead of reading the whole file once per zoom.
 * (A block of blocks is the mean of its blocks' means: the mean of its cells, except where no-data leaves blocks
 * unequally filled.)
 *
 * <p>Read on first use ({@link #lazy}), so that a plan whose groups run elsewhere reads it only where a group of
 * such a zoom is rendered; safe for use by several threads.
 */
final class Overview {

    /** Most cells of the whole DEM at a zoom's decimation for the zoom to take its cells from an overview. */
    static final long MAX_CELLS = 1L << 22;

    private final DemInput input;
    private final int decimation;
    /** Guarded by this; null until first read. */
    private Dem grid;

    private Overview(DemInput input, int decimation) {
        this.input = input;
        this.decimation = decimation;
    }

    /** The whole of {@code input} in blocks of {@code decimation} cells, read when its cells are first asked for. */
    static Overview lazy(DemInput input, int decimation) {
        return new Overview(input, decimation);
    }

    /** Reads the whole of {@code input} in blocks of {@code decimation} cells now. */
    static Overview read(DemInput input, int decimation) throws IOException {
        Overview o = new Overview(input, decimation);
        o.grid();
        return o;
    }

    private synchronized Dem grid() throws IOException {
        if (grid == null) {
            grid = DemReader.load(input, new ReadRequest(null, decimation)).dem();
        }
        return grid;
    }

    /** @return the size of its blocks in DEM cells */
    int decimation() {
        return decimation;
    }

    /** True when the whole DEM, {@code width × height} cells, is small at decimation {@code d}. */
    static boolean isSmall(long width, long height, int d) {
        return ((width + d - 1) / d) * ((height + d - 1) / d) <= MAX_CELLS;
    }

    /**
     * The cells of {@code window} (DEM cells, starting on whole blocks of {@code factor} × {@link #decimation()}
     * cells) averaged in blocks of {@code factor × factor} of this overview's cells.
     */
    Dem cells(Window.Cells window, int factor) throws IOException {
        Dem grid = grid();
        int c0 = window.col() / decimation;
        int r0 = window.row() / decimation;
        int c1 = Math.min(grid.width(), (window.col() + window.width() + decimation - 1) / decimation);
        int r1 = Math.min(grid.height(), (window.row() + window.height() + decimation - 1) / decimation);
        Dem crop = grid.crop(c0, r0, c1 - c0, r1 - r0);
        return factor == 1 ? crop : average(crop, factor);
    }

    /** Means of the valid cells of each {@code f × f} block (the last ones partial), NaN when none is valid. */
    static Dem average(Dem dem, int f) {
        int w = dem.width();
        int h = dem.height();
        int ow = (w + f - 1) / f;
        int oh = (h + f - 1) / f;
        float[] in = dem.backingArray();
        float[] out = new float[ow * oh];
        for (int r = 0; r < oh; r++) {
            for (int c = 0; c < ow; c++) {
                double sum = 0;
                int n = 0;
                for (int rr = r * f; rr < Math.min(h, (r + 1) * f); rr++) {
                    for (int cc = c * f; cc < Math.min(w, (c + 1) * f); cc++) {
                        float v = in[rr * w + cc];
                        if (!Float.isNaN(v)) {
                            sum += v;
                            n++;
                        }
                    }
                }
                out[r * ow + c] = n == 0 ? Float.NaN : (float) (sum / n);
            }
        }
        return Dem.ofNormalized(out, dem.geometry().decimate(f, f), dem.declaredNoData());
    }
}
