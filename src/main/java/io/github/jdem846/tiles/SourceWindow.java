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

    /**
     * @param dem        the cells read (decimated or not), with their geometry in the DEM's CRS
     * @param projection the DEM's projection and full-resolution grid
     */
    SourceWindow(Dem dem, SourceProjection projection) {
        this.dem = dem;
        this.projection = projection;
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
