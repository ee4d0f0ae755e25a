package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.io.source.ValueScale;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Reads a {@link MosaicPlan} as one raster: each read asks only the files it touches for their cells (opening
 * them then, at most {@link #MAX_OPEN} at once), applies each file's own no-data rule and value scale, and writes
 * elevations, NaN for no-data and for the gaps between files. Where files overlap, the plan's
 * {@link OverlapRule} decides. The header it gives ({@link #info()}) declares NaN as no-data and no value scale,
 * so the block reader's decimation and statistics work on it as on one file. Not thread-safe: parallel reads use
 * one {@link #reopen()} each.
 */
public final class MosaicSource implements RasterSource {

    /** Most files open at once. */
    static final int MAX_OPEN = 16;

    private final MosaicPlan plan;
    private final MemberPool pool;
    private final float[][] noData;
    private float[][] pieces = new float[0][];

    private MosaicSource(MosaicPlan plan, int maxOpen) {
        this.plan = plan;
        this.pool = new MemberPool(plan, maxOpen);
        this.noData = new float[plan.members().size()][];
        for (int i = 0; i < noData.length; i++) {
            noData[i] = plan.members().get(i).allNoData();
        }
    }

    /**
     * Opens the plan for reading; no file is opened until a read touches it.
     *
     * @param plan the mosaic
     * @return the source
     */
    public static MosaicSource open(MosaicPlan plan) {
        return new MosaicSource(plan, MAX_OPEN);
    }

    /** As {@link #open(MosaicPlan)} with at most {@code maxOpen} files open at once (tests). */
    static MosaicSource open(MosaicPlan plan, int maxOpen) {
        return new MosaicSource(plan, maxOpen);
    }

    /** @return another source of the same plan, with files of its own (for a read on another thread) */
    public MosaicSource reopen() {
        return new MosaicSource(plan, MAX_OPEN);
    }

    @Override
    public DemInfo info() {
        return plan.info();
    }

    /**
     * Reads each file under the rectangle into a piece of its own and writes its valid values in file order (so the
     * last valid value wins); under {@link OverlapRule#MEAN}, the cells two files share are then written again as
     * the mean of every valid value there, summed in double.
     */
    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        Arrays.fill(dst, 0, width * rows, Float.NaN);
        List<Member> members = plan.members();
        List<Integer> touched = new ArrayList<>();
        for (int i = 0; i < members.size(); i++) {
            if (members.get(i).meets(col, row, width, rows)) {
                touched.add(i);
            }
        }
        if (pieces.length < touched.size()) {
            pieces = Arrays.copyOf(pieces, touched.size());
        }
        int[][] rects = new int[touched.size()][];
        for (int k = 0; k < touched.size(); k++) {
            int i = touched.get(k);
            Member m = members.get(i);
            int x0 = Math.max(col, m.col());
            int y0 = Math.max(row, m.row());
            int w = Math.min(col + width, m.col() + m.width()) - x0;
            int h = Math.min(row + rows, m.row() + m.height()) - y0;
            rects[k] = new int[] {x0, y0, w, h};
            if (pieces[k] == null || pieces[k].length < w * h) {
                pieces[k] = new float[w * h];
            }
            float[] piece = pieces[k];
            pool.get(i).readRows(m.srcCol() + x0 - m.col(), m.srcRow() + y0 - m.row(), w, h, piece);
            toElevations(piece, w * h, noData[i], m.header().scale());
            for (int r = 0; r < h; r++) {
                int at = (y0 - row + r) * width + (x0 - col);
                int from = r * w;
                for (int c = 0; c < w; c++) {
                    float v = piece[from + c];
                    if (v == v) {
                        dst[at + c] = v;
                    }
                }
            }
        }
        if (plan.rule() == OverlapRule.MEAN) {
            averageOverlaps(touched, rects, col, row, width, dst);
        }
    }

    /** Writes the cells each pair of touched files shares as the mean of the valid values of every file there. */
    private void averageOverlaps(List<Integer> touched, int[][] rects, int col, int row, int width, float[] dst) {
        for (int a = 0; a < touched.size(); a++) {
            if (!plan.overlapping(touched.get(a))) {
                continue;
            }
            for (int b = a + 1; b < touched.size(); b++) {
                if (!plan.overlapping(touched.get(b))) {
                    continue;
                }
                int x0 = Math.max(rects[a][0], rects[b][0]);
                int x1 = Math.min(rects[a][0] + rects[a][2], rects[b][0] + rects[b][2]);
                int y0 = Math.max(rects[a][1], rects[b][1]);
                int y1 = Math.min(rects[a][1] + rects[a][3], rects[b][1] + rects[b][3]);
                for (int y = y0; y < y1; y++) {
                    for (int x = x0; x < x1; x++) {
                        double sum = 0;
                        int count = 0;
                        for (int k = 0; k < touched.size(); k++) {
                            int[] r = rects[k];
                            if (x >= r[0] && x < r[0] + r[2] && y >= r[1] && y < r[1] + r[3]) {
                                float v = pieces[k][(y - r[1]) * r[2] + (x - r[0])];
                                if (v == v) {
                                    sum += v;
                                    count++;
                                }
                            }
                        }
                        dst[(y - row) * width + (x - col)] = count > 0 ? (float) (sum / count) : Float.NaN;
                    }
                }
            }
        }
    }

    /** The file's no-data values to NaN, then its value scale, in place. */
    private static void toElevations(float[] values, int n, float[] noData, ValueScale scale) {
        for (float nd : noData) {
            if (nd == nd) {
                for (int i = 0; i < n; i++) {
                    if (values[i] == nd) {
                        values[i] = Float.NaN;
                    }
                }
            }
        }
        if (!scale.isIdentity()) {
            scale.apply(values, n);
        }
    }

    /** Row blocks common to every file when they line up on the grid (else 1). */
    @Override
    public int naturalRowBlock() {
        return plan.traits().rowBlock();
    }

    @Override
    public long bandCells() {
        return plan.traits().bandCells();
    }

    /** One file's strips or tiles at a time, and the cells of every file under a band. */
    @Override
    public long blockBytes() {
        return plan.traits().blockBytes();
    }

    /** When every file's rows can be read independently. */
    @Override
    public boolean readsRowsIndependently() {
        return plan.traits().independent();
    }

    /** How many times a file was opened for its cells (tests). */
    int opens() {
        return pool.opens();
    }

    /** How many files are open now (tests). */
    int openCount() {
        return pool.openCount();
    }

    @Override
    public void close() throws IOException {
        pool.close();
    }
}
