package io.github.jdem846.tiles;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * A part of the DEM read at one zoom's decimation, in the DEM's own CRS, and bilinear sampling of it at Web Mercator
 * pixel centres.
 *
 * <p>Sampling rule: a point outside the DEM's outer edges (at full resolution) is no-data; inside, the value is
 * interpolated between the four nearest cell centres (clamped at the edge cells), their weights renormalised over
 * those that hold data, and no-data when the nearest cell itself is no-data, so that coastlines and voids keep
 * their place instead of spreading.
 */
final class SourceWindow {

    private final Dem dem;
    private final SourceProjection projection;
    private final double ox;
    private final double oy;
    private final double cw;
    private final double ch;
    private final double west;
    private final double east;
    private final double south;
    private final double north;
    private final int latticeStep;

    /**
     * @param dem         the cells read (decimated or not), with their geometry in the DEM's CRS
     * @param projection  the DEM's projection and full-resolution grid
     * @param latticeStep pixels between the points carried exactly into the DEM's CRS ({@link
     *                    ZoomSource#latticeStepFor}); 1 = every pixel
     */
    SourceWindow(Dem dem, SourceProjection projection, int latticeStep) {
        this.dem = dem;
        this.projection = projection;
        this.latticeStep = latticeStep;
        GridGeometry g = dem.geometry();
        GridGeometry full = projection.grid();
        this.ox = g.originX();
        this.oy = g.originY();
        this.cw = g.cellWidth();
        this.ch = g.cellHeight();
        this.west = full.originX();
        this.east = full.eastX();
        this.south = full.southY();
        this.north = full.originY();
    }

    /**
     * The elevations at the centres of the cells of a {@code w × h} block of zoom grid {@code zoom} whose
     * north-west cell is global pixel ({@code col0}, {@code row0}).
     *
     * @return row-major elevations, NaN = no data
     */
    float[] sample(ZoomGrid zoom, int col0, int row0, int w, int h) {
        float[] out = new float[w * h];
        if (projection.isSeparable()) {
            double[] u = new double[w];
            double[] v = new double[h];
            for (int c = 0; c < w; c++) {
                u[c] = io.github.jdem846.geo.WebMercator.longitude(zoom.centerX(col0 + c));
            }
            for (int r = 0; r < h; r++) {
                v[r] = io.github.jdem846.geo.WebMercator.latitude(zoom.centerY(row0 + r));
            }
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    out[r * w + c] = at(u[c], v[r]);
                }
            }
            return out;
        }
        int step = latticeStep;
        if (step <= 1) {
            double[] p = new double[2 * w];
            for (int r = 0; r < h; r++) {
                double y = zoom.centerY(row0 + r);
                for (int c = 0; c < w; c++) {
                    p[2 * c] = zoom.centerX(col0 + c);
                    p[2 * c + 1] = y;
                }
                projection.toSource(p, w);
                for (int c = 0; c < w; c++) {
                    out[r * w + c] = at(p[2 * c], p[2 * c + 1]);
                }
            }
            return out;
        }
        // the DEM positions of the pixel centres on a lattice every `step` global pixels, exactly, and of the
        // pixels between by bilinear interpolation (ZoomGrid#latticeStep keeps its error far below a DEM cell); the
        // lattice is aligned to the world, so a pixel gets the same position in every tile
        long lc0 = Math.floorDiv(col0, step);
        long lr0 = Math.floorDiv(row0, step);
        int lw = (int) (Math.floorDiv(col0 + w - 1, step) - lc0 + 2);
        int lh = (int) (Math.floorDiv(row0 + h - 1, step) - lr0 + 2);
        double[] lattice = new double[2 * lw * lh];
        for (int j = 0; j < lh; j++) {
            for (int i = 0; i < lw; i++) {
                int k = 2 * (j * lw + i);
                lattice[k] = zoom.centerX((lc0 + i) * step);
                lattice[k + 1] = zoom.centerY((lr0 + j) * step);
            }
        }
        projection.toSource(lattice, lw * lh);
        for (int r = 0; r < h; r++) {
            long gr = row0 + r;
            int j = (int) (Math.floorDiv(gr, step) - lr0);
            double fv = (double) (gr - (lr0 + j) * step) / step;
            for (int c = 0; c < w; c++) {
                long gc = col0 + c;
                int i = (int) (Math.floorDiv(gc, step) - lc0);
                double fu = (double) (gc - (lc0 + i) * step) / step;
                int k00 = 2 * (j * lw + i);
                int k10 = k00 + 2;
                int k01 = k00 + 2 * lw;
                int k11 = k01 + 2;
                double x = (1 - fv) * ((1 - fu) * lattice[k00] + fu * lattice[k10])
                        + fv * ((1 - fu) * lattice[k01] + fu * lattice[k11]);
                double y = (1 - fv) * ((1 - fu) * lattice[k00 + 1] + fu * lattice[k10 + 1])
                        + fv * ((1 - fu) * lattice[k01 + 1] + fu * lattice[k11 + 1]);
                out[r * w + c] = at(x, y);
            }
        }
        return out;
    }

    /** The bilinear elevation at DEM-CRS position ({@code x}, {@code y}) (see the class comment). */
    float at(double x, double y) {
        if (!(x >= west && x <= east && y >= south && y <= north)) {
            return Float.NaN; // also NaN positions
        }
        int w = dem.width();
        int h = dem.height();
        double u = (x - ox) / cw - 0.5;
        double v = (oy - y) / ch - 0.5;
        u = Math.max(0, Math.min(w - 1, u));
        v = Math.max(0, Math.min(h - 1, v));
        int c0 = Math.min(w - 1, (int) u);
        int r0 = Math.min(h - 1, (int) v);
        int c1 = Math.min(w - 1, c0 + 1);
        int r1 = Math.min(h - 1, r0 + 1);
        double fu = u - c0;
        double fv = v - r0;
        float[] a = dem.backingArray();
        float z00 = a[r0 * w + c0];
        float z10 = a[r0 * w + c1];
        float z01 = a[r1 * w + c0];
        float z11 = a[r1 * w + c1];
        float nearest = fu < 0.5 ? (fv < 0.5 ? z00 : z01) : (fv < 0.5 ? z10 : z11);
        if (Float.isNaN(nearest)) {
            return Float.NaN;
        }
        double w00 = (1 - fu) * (1 - fv);
        double w10 = fu * (1 - fv);
        double w01 = (1 - fu) * fv;
        double w11 = fu * fv;
        if (!Float.isNaN(z00) && !Float.isNaN(z10) && !Float.isNaN(z01) && !Float.isNaN(z11)) {
            return (float) (w00 * z00 + w10 * z10 + w01 * z01 + w11 * z11);
        }
        double sum = 0;
        double weight = 0;
        if (!Float.isNaN(z00)) {
            sum += w00 * z00;
            weight += w00;
        }
        if (!Float.isNaN(z10)) {
            sum += w10 * z10;
            weight += w10;
        }
        if (!Float.isNaN(z01)) {
            sum += w01 * z01;
            weight += w01;
        }
        if (!Float.isNaN(z11)) {
            sum += w11 * z11;
            weight += w11;
        }
        return (float) (sum / weight);
    }
}
