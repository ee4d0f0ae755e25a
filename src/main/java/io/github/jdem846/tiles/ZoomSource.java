package io.github.jdem846.tiles;

import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;

/**
 * How one zoom reads the DEM: the decimation that gives at least one DEM cell (box-averaged by the reader) per tile
 * pixel everywhere on the DEM, and the cell window of the DEM that covers a group of tiles and their halos.
 * Windows are aligned to whole decimation blocks of the file, so every window averages the same blocks and
 * neighbouring groups sample the same elevations.
 */
final class ZoomSource {

    /** Points per side of the lattice along which a Web Mercator box is carried into the DEM's CRS. */
    private static final int LATTICE = 16;

    private final DemInput input;
    private final SourceProjection projection;
    private final ZoomGrid zoom;
    /** Largest error of a pixel's interpolated DEM position, in DEM cells (see {@link #latticeStepFor}). */
    static final double LATTICE_TOLERANCE = 0.01;

    private final int decimation;
    private final int latticeStep;
    private final Overview overview;

    /** Reads windows of the file at the zoom's own decimation ({@link #decimationFor}). */
    ZoomSource(DemInput input, SourceProjection projection, ZoomGrid zoom) {
        this(input, projection, zoom, null);
    }

    /**
     * Takes its cells from {@code overview} when given: at the largest multiple of the overview's blocks not above
     * the zoom's own decimation.
     */
    ZoomSource(DemInput input, SourceProjection projection, ZoomGrid zoom, Overview overview) {
        this.input = input;
        this.projection = projection;
        this.zoom = zoom;
        int own = decimationFor(projection, zoom);
        this.overview = overview;
        this.decimation = overview == null ? own
                : overview.decimation() * Math.max(1, own / overview.decimation());
        this.latticeStep = latticeStepFor(projection, zoom);
    }

    /**
     * How far apart, in pixels of this zoom, the points carried exactly into the DEM's CRS may be, the positions of
     * the pixels between them interpolated bilinearly (a projection such as UTM costs far more per point than the
     * rest of a pixel's sampling): the largest of 32, 16, … 2 whose interpolation error, checked at the middle of
     * lattice squares at 5 × 5 places over the DEM, stays within {@value #LATTICE_TOLERANCE} DEM cells; 1 (every
     * point exact) when none does; 1 too for a DEM in latitude/longitude, whose positions cost next to nothing.
     */
    static int latticeStepFor(SourceProjection projection, ZoomGrid zoom) {
        if (projection.isSeparable()) {
            return 1;
        }
        GridGeometry g = projection.grid();
        double cell = Math.min(g.cellWidth(), g.cellHeight());
        for (int s = 32; s >= 2; s /= 2) {
            if (latticeError(projection, zoom, s) <= LATTICE_TOLERANCE * cell) {
                return s;
            }
        }
        return 1;
    }

    /** Largest error, in DEM units, of the bilinear position at the middle of lattice squares of side {@code s}. */
    private static double latticeError(SourceProjection projection, ZoomGrid zoom, int s) {
        double west = projection.extent().west();
        double east = projection.extent().east();
        double south = projection.extent().south();
        double north = projection.extent().north();
        int n = 5;
        double worst = 0;
        double[] p = new double[10];
        double size = WebMercatorTile.pixelSize(zoom.zoom());
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double x = WebMercator.x(west + (east - west) * i / (n - 1));
                double y = WebMercator.y(south + (north - south) * j / (n - 1));
                long col = Math.floorDiv((long) Math.floor((x + WebMercator.HALF_WORLD) / size), s) * s;
                long row = Math.floorDiv((long) Math.floor((WebMercator.HALF_WORLD - y) / size), s) * s;
                p[0] = zoom.centerX(col);
                p[1] = zoom.centerY(row);
                p[2] = zoom.centerX(col + s);
                p[3] = zoom.centerY(row);
                p[4] = zoom.centerX(col);
                p[5] = zoom.centerY(row + s);
                p[6] = zoom.centerX(col + s);
                p[7] = zoom.centerY(row + s);
                p[8] = zoom.centerX(col + s / 2);
                p[9] = zoom.centerY(row + s / 2);
                projection.toSource(p, 5);
                double ix = (p[0] + p[2] + p[4] + p[6]) / 4;
                double iy = (p[1] + p[3] + p[5] + p[7]) / 4;
                double e = Math.hypot(ix - p[8], iy - p[9]);
                if (Double.isNaN(e)) {
                    continue; // outside the projection's domain: no pixel there samples the DEM
                }
                worst = Math.max(worst, e);
            }
        }
        return worst;
    }

    /** @return pixels between the points carried exactly into the DEM's CRS at this zoom */
    int latticeStep() {
        return latticeStep;
    }

    /** @return the block size the reader averages at this zoom */
    int decimation() {
        return decimation;
    }

    /**
     * The largest whole block size d such that d DEM cells are no longer than one tile pixel anywhere on the DEM,
     * along either axis: the pixel's size in DEM units, taken at a 5 × 5 lattice of points over the DEM, divided by
     * the cell size, its smallest value rounded down (at least 1).
     */
    static int decimationFor(SourceProjection projection, ZoomGrid zoom) {
        GridGeometry g = projection.grid();
        double west = projection.extent().west();
        double east = projection.extent().east();
        double south = projection.extent().south();
        double north = projection.extent().north();
        double half = WebMercatorTile.pixelSize(zoom.zoom()) / 2;
        double smallest = Double.POSITIVE_INFINITY;
        int n = 5;
        double[] p = new double[8];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double x = WebMercator.x(west + (east - west) * i / (n - 1));
                double y = WebMercator.y(south + (north - south) * j / (n - 1));
                p[0] = x - half;
                p[1] = y;
                p[2] = x + half;
                p[3] = y;
                p[4] = x;
                p[5] = y - half;
                p[6] = x;
                p[7] = y + half;
                projection.toSource(p, 4);
                double across = Math.hypot(p[2] - p[0], p[3] - p[1]) / g.cellWidth();
                double along = Math.hypot(p[6] - p[4], p[7] - p[5]) / g.cellHeight();
                if (Double.isFinite(across)) {
                    smallest = Math.min(smallest, across);
                }
                if (Double.isFinite(along)) {
                    smallest = Math.min(smallest, along);
                }
            }
        }
        if (!Double.isFinite(smallest)) {
            return 1;
        }
        long d = (long) Math.floor(smallest + 1e-9);
        return (int) Math.max(1, Math.min(d, Math.max(g.width(), g.height())));
    }

    /**
     * Reads the DEM cells the pixels of {@code need} (global pixels of this zoom) sample, with a margin for the
     * bilinear neighbours, at this zoom's decimation.
     *
     * @return the cells, or null when the pixels lie outside the DEM
     */
    SourceWindow read(CellWindow need) throws IOException {
        Window.Cells cells = cellsFor(need);
        if (cells == null) {
            return null;
        }
        if (overview != null) {
            return new SourceWindow(overview.cells(cells, decimation / overview.decimation()), projection,
                    latticeStep);
        }
        return new SourceWindow(DemReader.load(input, new ReadRequest(cells, decimation)).dem(), projection,
                latticeStep);
    }

    /** The aligned cell window of the DEM under {@code need}, or null when there is none. */
    Window.Cells cellsFor(CellWindow need) {
        GridGeometry g = projection.grid();
        double x0 = zoom.edgeX(need.col());
        double x1 = zoom.edgeX(need.colEnd());
        double y0 = zoom.edgeY(need.row());
        double y1 = zoom.edgeY(need.rowEnd());
        int count = (LATTICE + 1) * (LATTICE + 1);
        double[] p = new double[2 * count];
        int k = 0;
        for (int i = 0; i <= LATTICE; i++) {
            for (int j = 0; j <= LATTICE; j++) {
                p[k++] = x0 + (x1 - x0) * i / LATTICE;
                p[k++] = y0 + (y1 - y0) * j / LATTICE;
            }
        }
        projection.toSource(p, count);
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < 2 * count; i += 2) {
            if (Double.isFinite(p[i]) && Double.isFinite(p[i + 1])) {
                minX = Math.min(minX, p[i]);
                maxX = Math.max(maxX, p[i]);
                minY = Math.min(minY, p[i + 1]);
                maxY = Math.max(maxY, p[i + 1]);
            }
        }
        if (!(minX <= maxX)) {
            return null;
        }
        // a margin of a lattice cell's worth for edges that bulge between lattice points, and two blocks for the
        // bilinear neighbours
        double slackX = (maxX - minX) / LATTICE;
        double slackY = (maxY - minY) / LATTICE;
        int d = decimation;
        long c0 = (long) Math.floor((minX - slackX - g.originX()) / g.cellWidth()) - 2L * d;
        long c1 = (long) Math.ceil((maxX + slackX - g.originX()) / g.cellWidth()) + 2L * d;
        long r0 = (long) Math.floor((g.originY() - maxY - slackY) / g.cellHeight()) - 2L * d;
        long r1 = (long) Math.ceil((g.originY() - minY + slackY) / g.cellHeight()) + 2L * d;
        c0 = Math.max(0, Math.floorDiv(c0, d) * d);
        r0 = Math.max(0, Math.floorDiv(r0, d) * d);
        c1 = Math.min(g.width(), ceilTo(c1, d));
        r1 = Math.min(g.height(), ceilTo(r1, d));
        if (c0 >= c1 || r0 >= r1) {
            return null;
        }
        return Window.cells((int) c0, (int) r0, (int) (c1 - c0), (int) (r1 - r0));
    }

    private static long ceilTo(long v, int d) {
        return -Math.floorDiv(-v, d) * d;
    }
}
