package io.github.jdem846.testing;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * The brute-force sky-view factor, independent of the sweep: from each cell centre, a ray marched in each azimuth
 * in small steps over the bilinear surface (cell sizes in ground metres of the row a step is on), the horizon the
 * steepest elevation angle seen, at least 0°; SVF = 1 − mean(sin φ). O(cells × length × directions): for checks.
 */
public final class HorizonReference {

    private final Dem dem;
    private final float[] v;
    private final int w;
    private final int h;
    private final double step;
    private final double heightScale;
    private final double[] cw;
    private final double[] ch;
    private final double wRef;
    private final double hRef;
    private final double maxDistance;
    /**
     * The highest valid elevation (+∞ for {@link #exhaustive}): a ray whose rise to it is no steeper than its
     * horizon so far can stop.
     */
    private final double zMax;

    /**
     * @param dem         the terrain
     * @param step        the ray step in cells along the ray's major grid axis, e.g. 0.125
     * @param heightScale factor on heights (z-factor)
     */
    public HorizonReference(Dem dem, double step, double heightScale) {
        this(dem, step, heightScale, Double.POSITIVE_INFINITY);
    }

    /**
     * @param dem         the terrain
     * @param step        the ray step in cells along the ray's major grid axis, e.g. 0.125
     * @param heightScale factor on heights (z-factor)
     * @param maxDistance the search radius in ground metres: samples farther along the ray do not count
     */
    public HorizonReference(Dem dem, double step, double heightScale, double maxDistance) {
        this(dem, step, heightScale, maxDistance, true);
    }

    /**
     * A reference that marches every ray to the grid's edge (or the radius), without stopping when the highest
     * terrain can no longer be steeper than the horizon found: the same answers, more slowly (for the test that
     * they are the same).
     */
    public static HorizonReference exhaustive(Dem dem, double step, double heightScale) {
        return new HorizonReference(dem, step, heightScale, Double.POSITIVE_INFINITY, false);
    }

    private HorizonReference(Dem dem, double step, double heightScale, double maxDistance, boolean stopEarly) {
        this.maxDistance = maxDistance;
        this.dem = dem;
        this.v = dem.backingArray();
        this.w = dem.width();
        this.h = dem.height();
        this.step = step;
        this.heightScale = heightScale;
        GridGeometry g = dem.geometry();
        cw = new double[h];
        ch = new double[h];
        for (int r = 0; r < h; r++) {
            cw[r] = g.cellWidthMeters(r);
            ch[r] = g.cellHeightMeters(r);
        }
        int mid = g.placement().rootHeight() / 2 - g.placement().row();
        wRef = g.cellWidthMeters(mid);
        hRef = g.cellHeightMeters(mid);
        double top = Double.NEGATIVE_INFINITY;
        for (float z : v) {
            if (z > top) {
                top = z;
            }
        }
        zMax = stopEarly ? top : Double.POSITIVE_INFINITY;
    }

    /** The tangent of the horizon of cell (col, row) in {@code azimuth} degrees, at least 0; NaN for no-data. */
    public double horizonTangent(int col, int row, double azimuth) {
        double z0 = v[row * w + col];
        if (z0 != z0) {
            return Double.NaN;
        }
        double a = Math.toRadians(azimuth);
        double gx = Math.sin(a) / wRef;
        double gy = -Math.cos(a) / hRef;
        double s = step / Math.max(Math.abs(gx), Math.abs(gy));
        double dx = gx * s;
        double dy = gy * s;
        double best = 0;
        double dist = 0;
        double x = col;
        double y = row;
        while (true) {
            int rowHere = (int) Math.max(0, Math.min(h - 1, Math.floor(y + 0.5)));
            double xn = x + dx;
            double yn = y + dy;
            if (!(xn >= -0.5 && xn <= w - 0.5 && yn >= -0.5 && yn <= h - 0.5)) {
                return best;
            }
            dist += Math.hypot(dx * cw[rowHere], dy * ch[rowHere]);
            if (dist > maxDistance || heightScale > 0 && (zMax - z0) * heightScale / dist <= best) {
                return best;            // (no sample from here on can be steeper than the highest terrain)
            }
            x = xn;
            y = yn;
            double z = bilinear(x, y);
            if (z == z) {
                best = Math.max(best, (z - z0) * heightScale / dist);
            }
        }
    }

    /** The sky-view factor of cell (col, row) from {@code directions} azimuths 0, 360/D, …; NaN for no-data. */
    public double skyView(int col, int row, int directions) {
        double sum = 0;
        for (int d = 0; d < directions; d++) {
            double t = horizonTangent(col, row, 360.0 * d / directions);
            sum += t / Math.sqrt(1 + t * t);
        }
        return 1 - sum / directions;
    }

    /** The bilinear surface at (x, y), clamped at the edges; NaN when a corner used is no-data. */
    private double bilinear(double x, double y) {
        double cx = Math.max(0, Math.min(w - 1, x));
        double cy = Math.max(0, Math.min(h - 1, y));
        int c0 = (int) Math.floor(cx);
        int r0 = (int) Math.floor(cy);
        int c1 = Math.min(c0 + 1, w - 1);
        int r1 = Math.min(r0 + 1, h - 1);
        double fx = cx - c0;
        double fy = cy - r0;
        double top = v[r0 * w + c0] * (1 - fx) + v[r0 * w + c1] * fx;
        double bottom = v[r1 * w + c0] * (1 - fx) + v[r1 * w + c1] * fx;
        return top * (1 - fy) + bottom * fy;
    }

    /** @return the terrain */
    public Dem dem() {
        return dem;
    }
}
