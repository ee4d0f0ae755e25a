package io.github.jdem846.io.mosaic;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
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
 * Reads a GDAL virtual raster ({@code .vrt}) as a mosaic: the VRT's grid ({@code rasterXSize × rasterYSize},
 * {@code GeoTransform}, {@code SRS}), band 1's sources placed cell for cell as their {@code SrcRect} and
 * {@code DstRect} say (clipped to the file and to the grid), the last source with a valid value winning where
 * they overlap ({@link OverlapRule#LAST}, GDAL's rule). A cell is no-data when it is NaN, the file's own no-data,
 * the band's {@code NoDataValue} or the source's {@code NODATA}. The sources must share the VRT's CRS (see
 * {@link VrtParser} for what is refused).
 */
public final class VrtReader {

    private VrtReader() {
    }

    /**
     * The files a VRT names, resolved as it says, without opening them.
     *
     * @param vrt the {@code .vrt}
     * @return the source files, each once, in document order
     * @throws IOException naming the VRT when it cannot be read or is not supported
     */
    public static List<Path> sourceFiles(Path vrt) throws IOException {
        List<Path> files = new ArrayList<>();
        for (VrtDocument.Source s : VrtParser.parse(vrt).sources()) {
            if (!files.contains(s.file())) {
                files.add(s.file());
            }
        }
        return files;
    }

    /**
     * Plans the VRT, reading the headers of its files.
     *
     * @param vrt    the {@code .vrt}
     * @param opener opens a file with the reader of its format
     * @return the plan
     * @throws IOException naming the VRT, or the file at fault, when it cannot be read or is not supported
     */
    public static MosaicPlan plan(Path vrt, MemberOpener opener) throws IOException {
        VrtDocument doc = VrtParser.parse(vrt);
        List<String> notices = new ArrayList<>();
        if (doc.bands() > 1) {
            notices.add("the VRT has " + doc.bands() + " bands; band 1 is read");
        }
        Map<Path, MemberHeader> headers = new LinkedHashMap<>();
        for (VrtDocument.Source s : doc.sources()) {
            if (!headers.containsKey(s.file())) {
                headers.put(s.file(), MemberHeader.read(s.file(), opener));
            }
        }
        MemberHeader first = headers.values().iterator().next();
        for (MemberHeader h : headers.values()) {
            MosaicPlanner.requireSameCrs(first, h);
        }
        CrsInfo crs = crsOf(vrt, doc, first, notices);
        List<Member> members = new ArrayList<>();
        for (VrtDocument.Source s : doc.sources()) {
            Member m = place(vrt, doc, s, headers.get(s.file()), notices);
            if (m != null) {
                members.add(m);
            }
        }
        if (members.isEmpty()) {
            throw new DemFormatException(vrt, "none of its sources lies on its " + doc.width() + " × "
                    + doc.height() + " grid: there is nothing to read");
        }
        GridGeometry geometry = geometry(doc, members.get(0), crs);
        for (Member m : members) {
            checkPlacement(vrt, geometry, m, notices);
        }
        return MosaicPlan.of(vrt.toString(), DemFormat.VRT, geometry, members, OverlapRule.LAST, opener, notices);
    }

    /** The VRT's SRS when it has one its files agree with; else the files' CRS. */
    private static CrsInfo crsOf(Path vrt, VrtDocument doc, MemberHeader first, List<String> notices)
            throws DemFormatException {
        CrsInfo files = first.info().geometry().crs();
        if (doc.srs() == null || doc.srs().isEmpty()) {
            return files;
        }
        CrsInfo declared;
        try {
            String srs = doc.srs();
            String upper = srs.toUpperCase(Locale.ROOT);
            if (upper.startsWith("EPSG:") && upper.substring(5).strip().matches("\\d+")) {
                int code = Integer.parseInt(upper.substring(5).strip());
                declared = CrsResolver.fromEpsg(code).orElse(null);
                if (declared == null) {
                    notices.add("the VRT's SRS " + srs + " is not known offline; the files' CRS is used");
                    return files;
                }
            } else {
                declared = CrsResolver.fromWkt(srs);
            }
        } catch (IllegalArgumentException e) {
            notices.add("the VRT's SRS could not be read (" + e.getMessage() + "); the files' CRS is used");
            return files;
        }
        boolean filesKnown = files.kind() != CrsInfo.Kind.UNKNOWN || files.epsg() != null;
        if (filesKnown && !CrsMatch.same(declared, files)) {
            throw new DemFormatException(vrt, "declares " + CrsMatch.describe(declared) + ", but its source "
                    + first.given() + " has " + CrsMatch.describe(files) + ": a VRT must not reproject (rebuild it"
                    + " with gdalbuildvrt, or warp the files first)");
        }
        return filesKnown ? files : declared;
    }

    /**
     * Where a source's cells go: its SrcRect (the whole file by default) clipped to the file, its DstRect (the
     * SrcRect's size at the grid's origin by default) clipped to the grid; {@code null} when nothing is left.
     */
    private static Member place(Path vrt, VrtDocument doc, VrtDocument.Source s, MemberHeader h,
                                List<String> notices) throws DemFormatException {
        int fw = h.info().width();
        int fh = h.info().height();
        int[] src = s.src() != null ? s.src() : new int[] {0, 0, fw, fh};
        int[] dst = s.dst() != null ? s.dst() : new int[] {0, 0, src[2], src[3]};
        if (src[2] != dst[2] || src[3] != dst[3]) {
            throw VrtParser.unsupported(vrt, "the source " + s.file().getFileName() + " is resampled (" + src[2]
                    + " × " + src[3] + " cells to " + dst[2] + " × " + dst[3] + "; only 1:1 placement is read)");
        }
        // clip to the file, then to the grid, moving the other rectangle along
        long sx = src[0];
        long sy = src[1];
        long dx = dst[0];
        long dy = dst[1];
        long w = src[2];
        long hgt = src[3];
        long cut = Math.max(Math.max(0, -sx), -dx);
        sx += cut;
        dx += cut;
        w -= cut;
        cut = Math.max(Math.max(0, -sy), -dy);
        sy += cut;
        dy += cut;
        hgt -= cut;
        w = Math.min(w, Math.min(fw - sx, doc.width() - dx));
        hgt = Math.min(hgt, Math.min(fh - sy, doc.height() - dy));
        if (w <= 0 || hgt <= 0) {
            notices.add("the source " + s.file().getFileName() + " has no cell on the VRT's grid and is not read");
            return null;
        }
        List<Float> noData = new ArrayList<>();
        if (doc.noData() != null && !doc.noData().isNaN()) {
            noData.add(io.github.jdem846.raster.NoData.toFloat32(doc.noData()));
        }
        if (s.noData() != null && !s.noData().isNaN()) {
            noData.add(io.github.jdem846.raster.NoData.toFloat32(s.noData()));
        }
        float[] nd = new float[noData.size()];
        for (int i = 0; i < nd.length; i++) {
            nd[i] = noData.get(i);
        }
        return new Member(h, nd, (int) sx, (int) sy, (int) dx, (int) dy, (int) w, (int) hgt);
    }

    /** The VRT's GeoTransform, or, without one, the grid the first source's file gives. */
    private static GridGeometry geometry(VrtDocument doc, Member first, CrsInfo crs) {
        GridGeometry fg = first.header().info().geometry();
        double[] gt = doc.geoTransform();
        if (gt != null) {
            return new GridGeometry(doc.width(), doc.height(), gt[0], gt[3], gt[1], -gt[5], crs,
                    fg.declaredAnchor());
        }
        double originX = fg.originX() + (first.srcCol() - (double) first.col()) * fg.cellWidth();
        double originY = fg.originY() - (first.srcRow() - (double) first.row()) * fg.cellHeight();
        return new GridGeometry(doc.width(), doc.height(), originX, originY, fg.cellWidth(), fg.cellHeight(), crs,
                fg.declaredAnchor());
    }

    /**
     * A notice when a file's own georeferencing disagrees with where the VRT puts it, or its cells are of another
     * size: the VRT's placement is what is read, as in GDAL.
     */
    private static void checkPlacement(Path vrt, GridGeometry grid, Member m, List<String> notices) {
        GridGeometry fg = m.header().info().geometry();
        String name = m.file().getFileName().toString();
        double tolerance = MosaicPlanner.ALIGNMENT_TOLERANCE / Math.max(grid.width(), grid.height());
        if (Math.abs(fg.cellWidth() - grid.cellWidth()) > tolerance * grid.cellWidth()
                || Math.abs(fg.cellHeight() - grid.cellHeight()) > tolerance * grid.cellHeight()) {
            notices.add(name + " has cells of " + MosaicPlanner.fmt(fg.cellWidth()) + " × "
                    + MosaicPlanner.fmt(fg.cellHeight()) + ", the VRT's are " + MosaicPlanner.fmt(grid.cellWidth())
                    + " × " + MosaicPlanner.fmt(grid.cellHeight()) + ": its cells are placed one for one as the"
                    + " VRT says");
            return;
        }
        double fileX = fg.originX() + m.srcCol() * fg.cellWidth();
        double fileY = fg.originY() - m.srcRow() * fg.cellHeight();
        double vrtX = grid.originX() + m.col() * grid.cellWidth();
        double vrtY = grid.originY() - m.row() * grid.cellHeight();
        double off = Math.max(Math.abs(fileX - vrtX) / grid.cellWidth(), Math.abs(fileY - vrtY) / grid.cellHeight());
        if (off > MosaicPlanner.ALIGNMENT_TOLERANCE) {
            notices.add(name + "'s own georeferencing puts it " + String.format(Locale.ROOT, "%.2f", off)
                    + " cells from where the VRT places it; the VRT's placement is read");
        }
    }
}
