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

    private Terrain(int width, int height, float[] x, float[] y, float[] z, float[] u, float[] v, GlobeFrame globe) {
        this.width = width;
        this.height = height;
        this.x = x;
        this.y = y;
        this.z = z;
        this.u = u;
        this.v = v;
        this.globe = globe;
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
        return new Terrain(w, h, x, y, z, u, v, frame);
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

    /** @return the number of vertices */
    int size() {
        return width * height;
    }
}
