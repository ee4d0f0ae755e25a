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
    private float[] piece = new float[0];
    private double[] sum = new double[0];
    private int[] count = new int[0];

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

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        int n = width * rows;
        Arrays.fill(dst, 0, n, Float.NaN);
        List<Integer> touched = new ArrayList<>();
        List<Member> members = plan.members();
        for (int i = 0; i < members.size(); i++) {
            if (members.get(i).meets(col, row, width, rows)) {
                touched.add(i);
            }
        }
        boolean mean = plan.rule() == OverlapRule.MEAN && overlapWithin(touched, col, row, width, rows);
        if (mean) {
            if (sum.length < n) {
                sum = new double[n];
                count = new int[n];
            }
            Arrays.fill(sum, 0, n, 0);
            Arrays.fill(count, 0, n, 0);
        }
        for (int i : touched) {
            Member m = members.get(i);
            int x0 = Math.max(col, m.col());
            int y0 = Math.max(row, m.row());
            int w = Math.min(col + width, m.col() + m.width()) - x0;
            int h = Math.min(row + rows, m.row() + m.height()) - y0;
            int cells = w * h;
            if (piece.length < cells) {
                piece = new float[cells];
            }
            pool.get(i).readRows(m.srcCol() + x0 - m.col(), m.srcRow() + y0 - m.row(), w, h, piece);
            toElevations(piece, cells, noData[i], m.header().scale());
            for (int r = 0; r < h; r++) {
                int at = (y0 - row + r) * width + (x0 - col);
                int from = r * w;
                if (mean) {
                    for (int c = 0; c < w; c++) {
                        float v = piece[from + c];
                        if (v == v) {
                            sum[at + c] += v;
                            count[at + c]++;
                        }
                    }
                } else {
                    // one file here, or the last valid value wins
                    for (int c = 0; c < w; c++) {
                        float v = piece[from + c];
                        if (v == v) {
                            dst[at + c] = v;
                        }
                    }
                }
            }
        }
        if (mean) {
            for (int i = 0; i < n; i++) {
                if (count[i] > 0) {
                    dst[i] = (float) (sum[i] / count[i]);
                }
            }
        }
    }

    /** True when two of the touched files share cells inside the rectangle. */
    private boolean overlapWithin(List<Integer> touched, int col, int row, int width, int rows) {
        List<Member> members = plan.members();
        for (int a = 0; a < touched.size(); a++) {
            if (!plan.overlapping(touched.get(a))) {
                continue;
            }
            Member ma = members.get(touched.get(a));
            for (int b = a + 1; b < touched.size(); b++) {
                Member mb = members.get(touched.get(b));
                if (plan.overlapping(touched.get(b)) && ma.overlaps(mb)) {
                    int x0 = Math.max(Math.max(ma.col(), mb.col()), col);
                    int x1 = Math.min(Math.min(ma.col() + ma.width(), mb.col() + mb.width()), col + width);
                    int y0 = Math.max(Math.max(ma.row(), mb.row()), row);
                    int y1 = Math.min(Math.min(ma.row() + ma.height(), mb.row() + mb.height()), row + rows);
                    if (x0 < x1 && y0 < y1) {
                        return true;
                    }
                }
            }
        }
        return false;
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

    /** One file's strips or tiles at a time, and the mosaic's own buffers for a band. */
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
