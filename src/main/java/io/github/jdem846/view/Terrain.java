package io.github.jdem846.view;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.GeoLocator;
import io.github.jdem846.geo.LatLon;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * The terrain as a mesh: one vertex per cell centre, in metres in a local east–north–up frame whose origin is the
 * grid's centre at height 0, with the texture position (in pixels of the relief picture) of each. On a plane,
 * east–west and north–south distances are the cells' sizes on the ground ({@link GridGeometry#cellWidthMeters},
 * row by row for a latitude/longitude grid); on the globe, each vertex is placed on the body's ellipsoid at its
 * latitude and longitude. A no-data cell's vertex is NaN: the triangles touching it are holes.
 */
final class Terrain {

    final int width;
    final int height;
    final float[] x;
    final float[] y;
    final float[] z;
    final float[] u;
    final float[] v;
    /** The frame on the globe (null on a plane). */
    final GlobeFrame globe;
    /**
     * The grid's edge vertices in order around it (empty without a base); vertex {@code size() + j} is the base's
     * vertex under {@code perimeter[j]}.
     */
    final int[] perimeter;
    /** The grid the mesh was made of, for placing points given in its coordinates. */
    private final Dem dem;
    private final double exaggeration;

    private Terrain(Dem dem, double exaggeration, int width, int height, float[] x, float[] y, float[] z, float[] u,
                    float[] v, GlobeFrame globe, int[] perimeter) {
        this.dem = dem;
        this.exaggeration = exaggeration;
        this.width = width;
        this.height = height;
        this.x = x;
        this.y = y;
        this.z = z;
        this.u = u;
        this.v = v;
        this.globe = globe;
        this.perimeter = perimeter;
    }

    /**
     * The mesh of {@code dem} textured by a picture covering {@code texture}.
     *
     * @throws IllegalArgumentException in globe mode when the grid's CRS gives no latitude and longitude
     */
    static Terrain of(Dem dem, GridGeometry texture, ViewOptions options) {
        int w = dem.width();
        int h = dem.height();
        int n = w * h;
        float[] x = new float[n];
        float[] y = new float[n];
        float[] z = new float[n];
        float[] u = new float[n];
        float[] v = new float[n];
        GridGeometry g = dem.geometry();
        for (int r = 0; r < h; r++) {
            float vr = (float) ((texture.originY() - g.centerY(r)) / texture.cellHeight() - 0.5);
            for (int c = 0; c < w; c++) {
                u[r * w + c] = (float) ((g.centerX(c) - texture.originX()) / texture.cellWidth() - 0.5);
                v[r * w + c] = vr;
            }
        }
        GlobeFrame frame = null;
        if (options.globe()) {
            frame = placeOnGlobe(dem, options.exaggeration(), x, y, z);
        } else {
            placeOnPlane(dem, options.exaggeration(), x, y, z);
        }
        Terrain t = new Terrain(dem, options.exaggeration(), w, h, x, y, z, u, v, frame, new int[0]);
        return options.base() && !options.globe() && w >= 2 && h >= 2 ? t.withBase() : t;
    }

    /**
     * This terrain with base vertices under its edge vertices, a tenth of its height range (at least 1 m) below
     * its lowest point.
     */
    private Terrain withBase() {
        int n = size();
        float zMin = Float.POSITIVE_INFINITY;
        float zMax = Float.NEGATIVE_INFINITY;
        for (float value : z) {
            if (!Float.isNaN(value)) {
                zMin = Math.min(zMin, value);
                zMax = Math.max(zMax, value);
            }
        }
        if (!(zMin <= zMax)) {
            return this;
        }
        float base = zMin - Math.max(1, 0.1f * (zMax - zMin));
        int[] ring = new int[2 * width + 2 * height - 4];
        int k = 0;
        for (int c = 0; c < width; c++) {
            ring[k++] = c;
        }
        for (int r = 1; r < height; r++) {
            ring[k++] = r * width + width - 1;
        }
        for (int c = width - 2; c >= 0; c--) {
            ring[k++] = (height - 1) * width + c;
        }
        for (int r = height - 2; r >= 1; r--) {
            ring[k++] = r * width;
        }
        float[] bx = java.util.Arrays.copyOf(x, n + k);
        float[] by = java.util.Arrays.copyOf(y, n + k);
        float[] bz = java.util.Arrays.copyOf(z, n + k);
        float[] bu = java.util.Arrays.copyOf(u, n + k);
        float[] bv = java.util.Arrays.copyOf(v, n + k);
        for (int j = 0; j < k; j++) {
            int top = ring[j];
            bx[n + j] = x[top];
            by[n + j] = y[top];
            bz[n + j] = Float.isNaN(z[top]) ? Float.NaN : base;
            bu[n + j] = u[top];
            bv[n + j] = v[top];
        }
        return new Terrain(dem, exaggeration, width, height, bx, by, bz, bu, bv, globe, ring);
    }

    /**
     * A point given in the grid's coordinates, in the mesh's local frame: on a plane, placed as the cell centres are
     * (between them, linearly; beyond the edges, on by the edge cells' sizes); on the globe, on the ellipsoid.
     *
     * @param east   easting (or longitude) in the grid's CRS units
     * @param north  northing (or latitude)
     * @param elevation in the DEM's units, before the exaggeration
     * @return {x, y, z} in metres
     * @throws IllegalArgumentException on the globe, when the point cannot be turned into a latitude and longitude
     */
    double[] toLocal(double east, double north, double elevation) {
        GridGeometry g = dem.geometry();
        double up = elevation * exaggeration;
        if (globe != null) {
            GeoLocator locator = g.geoLocator().orElseThrow();
            LatLon at = locator.toLatLon(east, north);
            double[] p = new double[3];
            double[] local = new double[3];
            globe.ecef(at.latitude(), at.longitude(), up, p);
            globe.toLocal(p, local);
            return local;
        }
        double col = (east - g.originX()) / g.cellWidth() - 0.5;
        double row = (g.originY() - north) / g.cellHeight() - 0.5;
        int r0 = (int) Math.max(0, Math.min(height - 2, Math.floor(row)));
        int r1 = Math.min(height - 1, r0 + 1);
        double t = row - r0;
        double ya = y[r0 * width];
        double yb = r1 > r0 ? y[r1 * width] : ya - g.cellHeightMeters(r0);
        double cw = (1 - t) * g.cellWidthMeters(r0) + t * g.cellWidthMeters(r1);
        return new double[] {(col - (width - 1) / 2.0) * cw, ya + t * (yb - ya), up};
    }

    /**
     * The grid's height at a point given in its coordinates, bilinear between the cell centres.
     *
     * @param east  easting (or longitude)
     * @param north northing (or latitude)
     * @return the height in the DEM's units (not exaggerated), or NaN outside the grid's cell centres or next to
     *         no-data
     */
    double heightAt(double east, double north) {
        GridGeometry g = dem.geometry();
        double col = (east - g.originX()) / g.cellWidth() - 0.5;
        double row = (g.originY() - north) / g.cellHeight() - 0.5;
        if (!(col >= 0 && row >= 0 && col <= width - 1 && row <= height - 1)) {
            return Double.NaN;
        }
        int c0 = (int) Math.min(width - 2, Math.floor(col));
        int r0 = (int) Math.min(height - 2, Math.floor(row));
        c0 = Math.max(0, c0);
        r0 = Math.max(0, r0);
        int c1 = Math.min(width - 1, c0 + 1);
        int r1 = Math.min(height - 1, r0 + 1);
        double fc = col - c0;
        double fr = row - r0;
        return (1 - fr) * ((1 - fc) * dem.get(c0, r0) + fc * dem.get(c1, r0))
                + fr * ((1 - fc) * dem.get(c0, r1) + fc * dem.get(c1, r1));
    }

    /** {@return the height of the base's vertices, or NaN without a base} */
    float baseLevel() {
        for (int i = size(); i < vertexCount(); i++) {
            if (!Float.isNaN(z[i])) {
                return z[i];
            }
        }
        return Float.NaN;
    }

    /** {@return the middle of the grid's range of heights (DEM units, not exaggerated), 0 when all is no-data} */
    double middleHeight() {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                float value = dem.get(c, r);
                if (!Float.isNaN(value)) {
                    lo = Math.min(lo, value);
                    hi = Math.max(hi, value);
                }
            }
        }
        return lo <= hi ? 0.5 * (lo + hi) : 0;
    }

    /** Cell centres on a plane, ground metres from the grid's centre; heights times the exaggeration. */
    private static void placeOnPlane(Dem dem, double exaggeration, float[] x, float[] y, float[] z) {
        int w = dem.width();
        int h = dem.height();
        GridGeometry g = dem.geometry();
        double[] rowY = new double[h];
        double previous = g.cellHeightMeters(0);
        for (int r = 1; r < h; r++) {
            double here = g.cellHeightMeters(r);
            rowY[r] = rowY[r - 1] - 0.5 * (previous + here);
            previous = here;
        }
        double midY = 0.5 * (rowY[(h - 1) / 2] + rowY[h / 2]);
        double midCol = (w - 1) / 2.0;
        for (int r = 0; r < h; r++) {
            double cw = g.cellWidthMeters(r);
            for (int c = 0; c < w; c++) {
                int i = r * w + c;
                x[i] = (float) ((c - midCol) * cw);
                y[i] = (float) (rowY[r] - midY);
                z[i] = (float) (dem.get(c, r) * exaggeration);
            }
        }
    }

    /** Cell centres on the ellipsoid at radius + height × exaggeration, in the east–north–up frame of the centre. */
    private static GlobeFrame placeOnGlobe(Dem dem, double exaggeration, float[] x, float[] y, float[] z) {
        int w = dem.width();
        int h = dem.height();
        GridGeometry g = dem.geometry();
        GeoLocator locator = g.geoLocator().orElseThrow(() -> new IllegalArgumentException(
                "globe mode needs latitudes and longitudes, but the grid's CRS ("
                        + (g.crs().name() == null ? "unknown" : g.crs().name())
                        + ") cannot be turned into them; draw it without globe mode"));
        Ellipsoid e = g.ellipsoid();
        LatLon centre = locator.toLatLon(g.centerX((w - 1) / 2.0), g.centerY((h - 1) / 2.0));
        GlobeFrame frame = GlobeFrame.at(e, centre.latitude(), centre.longitude());
        double[] p = new double[3];
        double[] local = new double[3];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                int i = r * w + c;
                float elevation = dem.get(c, r);
                LatLon at;
                try {
                    at = locator.toLatLon(g.centerX(c), g.centerY(r));
                } catch (IllegalArgumentException outsideProjection) {
                    at = null;
                }
                if (Float.isNaN(elevation) || at == null) {
                    x[i] = Float.NaN;
                    y[i] = Float.NaN;
                    z[i] = Float.NaN;
                    continue;
                }
                frame.ecef(at.latitude(), at.longitude(), elevation * exaggeration, p);
                frame.toLocal(p, local);
                x[i] = (float) local[0];
                y[i] = (float) local[1];
                z[i] = (float) local[2];
            }
        }
        return frame;
    }

    /** @return the number of the grid's vertices (the base's follow them) */
    int size() {
        return width * height;
    }

    /** @return the number of vertices, the base's included */
    int vertexCount() {
        return x.length;
    }
}
