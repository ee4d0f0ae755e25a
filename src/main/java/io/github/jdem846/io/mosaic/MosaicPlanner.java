package io.github.jdem846.io.mosaic;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Plans a mosaic of a list of files from their headers: they must share one CRS, one cell size and one grid
 * (their edges on common cell boundaries, within {@link #ALIGNMENT_TOLERANCE} of a cell); the mosaic is the
 * smallest grid holding them all, gaps read as no-data and overlapping cells as the mean of the valid values
 * ({@link OverlapRule#MEAN}). A file given twice (also as its {@code .hdr}) is read once.
 */
public final class MosaicPlanner {

    /** Largest distance, in cells, between a file's edge and the mosaic's cell boundaries. */
    static final double ALIGNMENT_TOLERANCE = 0.01;

    private MosaicPlanner() {
    }

    /**
     * Plans the mosaic of {@code files}, reading their headers.
     *
     * @param files  the files, at least one
     * @param opener opens a file with the reader of its format
     * @return the plan
     * @throws DemFormatException naming the file and the fault when a file cannot be read or does not fit the
     *                            others
     * @throws IOException        when a file cannot be read
     */
    public static MosaicPlan plan(List<Path> files, MemberOpener opener) throws IOException {
        if (files.isEmpty()) {
            throw new IllegalArgumentException("a mosaic needs at least one file");
        }
        Map<Path, MemberHeader> headers = new LinkedHashMap<>();
        List<String> notices = new ArrayList<>();
        for (Path file : files) {
            MemberHeader h = MemberHeader.read(file, opener);
            Path key = h.data().toAbsolutePath().normalize();
            if (headers.containsKey(key)) {
                notices.add(h.data() + " is given more than once: it is read once");
            } else {
                headers.put(key, h);
            }
        }
        List<MemberHeader> list = new ArrayList<>(headers.values());
        MemberHeader ref = list.get(0);
        GridGeometry rg = ref.info().geometry();
        for (MemberHeader h : list) {
            requireSameCrs(ref, h);
            requireSameCellSize(ref, h, 10_000); // before placing them: a different size is not a misalignment
        }
        // offsets on the first file's grid, in cells, exactly (long: a far-away file must not wrap around)
        long[] cols = new long[list.size()];
        long[] rows = new long[list.size()];
        long minCol = Long.MAX_VALUE;
        long minRow = Long.MAX_VALUE;
        long maxCol = Long.MIN_VALUE;
        long maxRow = Long.MIN_VALUE;
        int west = 0;
        int north = 0;
        for (int i = 0; i < list.size(); i++) {
            GridGeometry g = list.get(i).info().geometry();
            cols[i] = offset(ref, list.get(i), (g.originX() - rg.originX()) / rg.cellWidth(), "west",
                    g.originX(), rg.originX(), rg.cellWidth());
            rows[i] = offset(ref, list.get(i), (rg.originY() - g.originY()) / rg.cellHeight(), "north",
                    g.originY(), rg.originY(), rg.cellHeight());
            if (cols[i] < minCol) {
                minCol = cols[i];
                west = i;
            }
            if (rows[i] < minRow) {
                minRow = rows[i];
                north = i;
            }
            maxCol = Math.max(maxCol, cols[i] + g.width());
            maxRow = Math.max(maxRow, rows[i] + g.height());
        }
        long width = maxCol - minCol;
        long height = maxRow - minRow;
        if (width > Integer.MAX_VALUE || height > Integer.MAX_VALUE) {
            throw new DemFormatException(ref.given(), "with the other " + (list.size() - 1) + " files it spans "
                    + width + " × " + height + " cells, more than " + Integer.MAX_VALUE + " on a side: are the"
                    + " files far apart, or is one's georeferencing wrong?");
        }
        long longest = Math.max(width, height);
        for (MemberHeader h : list) {
            requireSameCellSize(ref, h, longest);
        }
        List<Member> members = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            members.add(Member.whole(list.get(i), (int) (cols[i] - minCol), (int) (rows[i] - minRow)));
        }
        // the mosaic's edges are those of the westmost and northmost files as they declare them
        GridGeometry geometry = new GridGeometry((int) width, (int) height,
                list.get(west).info().geometry().originX(), list.get(north).info().geometry().originY(),
                rg.cellWidth(), rg.cellHeight(), rg.crs(), rg.declaredAnchor());
        return MosaicPlan.of(source(list), DemFormat.MOSAIC, geometry, members, OverlapRule.MEAN, opener,
                notices);
    }

    /** What the mosaic's header names as its input: the files, the first three and the count beyond. */
    private static String source(List<MemberHeader> list) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < Math.min(3, list.size()); i++) {
            names.add(list.get(i).data().toString());
        }
        String more = list.size() > 3 ? ", … (" + list.size() + " files)" : "";
        return "mosaic of " + String.join(", ", names) + more;
    }

    static void requireSameCrs(MemberHeader ref, MemberHeader h) throws DemFormatException {
        CrsInfo a = ref.info().geometry().crs();
        CrsInfo b = h.info().geometry().crs();
        if (!CrsMatch.same(a, b)) {
            throw new DemFormatException(h.given(), "has " + CrsMatch.describe(b) + ", but " + ref.given()
                    + " has " + CrsMatch.describe(a) + ": the files of a mosaic must share one CRS (reproject"
                    + " them first, e.g. gdalwarp -t_srs EPSG:code)");
        }
    }

    /**
     * The whole number of cells {@code cells} is, when it is one within {@link #ALIGNMENT_TOLERANCE}.
     *
     * @throws DemFormatException naming both files and the edges when it is not
     */
    private static long offset(MemberHeader ref, MemberHeader h, double cells, String edge, double value,
                               double refValue, double cell) throws DemFormatException {
        double k = Math.rint(cells);
        if (!Double.isFinite(cells) || Math.abs(k) >= 0x1p62) {
            throw new DemFormatException(h.given(), "lies " + cells + " cells from " + ref.given()
                    + ": its georeferencing cannot be placed on the same grid");
        }
        if (Math.abs(cells - k) > ALIGNMENT_TOLERANCE) {
            throw new DemFormatException(h.given(), "is not on the grid of " + ref.given() + ": its " + edge
                    + " edge " + fmt(value) + " is " + String.format(Locale.ROOT, "%.3f", Math.abs(cells - k))
                    + " cells off the cell boundaries of " + ref.given() + " (edge " + fmt(refValue) + ", cell "
                    + fmt(cell) + "); the files of a mosaic must share one grid (resample them onto it first,"
                    + " e.g. gdalwarp -tap -tr)");
        }
        return (long) k;
    }

    /**
     * Refuses a file whose cells differ in size from the first file's by so much that, across the mosaic, they
     * would drift by more than {@link #ALIGNMENT_TOLERANCE} of a cell.
     */
    static void requireSameCellSize(MemberHeader ref, MemberHeader h, long cellsAcross) throws DemFormatException {
        GridGeometry a = ref.info().geometry();
        GridGeometry b = h.info().geometry();
        double tolerance = ALIGNMENT_TOLERANCE / Math.max(1, cellsAcross);
        if (Math.abs(a.cellWidth() - b.cellWidth()) > tolerance * a.cellWidth()
                || Math.abs(a.cellHeight() - b.cellHeight()) > tolerance * a.cellHeight()) {
            throw new DemFormatException(h.given(), "has cells of " + fmt(b.cellWidth()) + " × "
                    + fmt(b.cellHeight()) + ", but " + ref.given() + " has cells of " + fmt(a.cellWidth()) + " × "
                    + fmt(a.cellHeight()) + ": the files of a mosaic must have one cell size (resample them"
                    + " first, e.g. gdalwarp -tr)");
        }
    }

    static String fmt(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return new java.math.BigDecimal(v).round(new java.math.MathContext(12)).stripTrailingZeros()
                .toPlainString();
    }
}
