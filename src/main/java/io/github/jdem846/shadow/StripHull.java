package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The upper convex hull of a strip's terrain bounds ({@link ThinFeatures#around}) upstream of the current cell, as
 * points (x, bound) with x growing downstream: −i on a grid with one step length, else the distance along the strip.
 * For a cell at x its tangent point is the sample of the steepest bound as seen from the cell, (bound − z₀)/(x −
 * xᵢ): the cell's own ray is tested there ({@link ThinFeatures#ownSample}). The lines, which pass up to a cell to
 * either side, see a thin feature (a one-cell spike, a narrow ridge across the sun) only partly, and their
 * interpolated shadow height then falls short of it; the own-ray sample is one the cell's own march takes, so it
 * never shades a cell that march leaves lit. The choice does not depend on the sun's elevation, so raising the sun
 * never adds shadow; and a window whose halo holds every sample above the cell's ray chooses the same point as the
 * whole grid (a steeper point beyond the halo is below the ray, and then so is everything else).
 */
final class StripHull {
    private double[] x = new double[16];
    private double[] z = new double[16];
    private int[] at = new int[16];
    private int size;

    /** Adds point (px, pz) of major index i; px must exceed every x added before. */
    void push(double px, double pz, int i) {
        while (size >= 2 && cross(size - 2, size - 1, px, pz) >= 0) {
            size--;
        }
        if (size == x.length) {
            x = Arrays.copyOf(x, 2 * size);
            z = Arrays.copyOf(z, 2 * size);
            at = Arrays.copyOf(at, 2 * size);
        }
        x[size] = px;
        z[size] = pz;
        at[size] = i;
        size++;
    }

    /** (b − a) × (q − a) for hull points a, b: ≥ 0 when q is on or above the line through them. */
    private double cross(int a, int b, double qx, double qz) {
        return (x[b] - x[a]) * (qz - z[a]) - (z[b] - z[a]) * (qx - x[a]);
    }

    /**
     * The major index of the point that maximises (bound − qz)/(qx − x) for qx beyond every point, −1 when the hull
     * is empty: the first point whose next edge's line passes on or below (qx, qz).
     */
    int tangent(double qx, double qz) {
        if (size == 0) {
            return -1;
        }
        int lo = 0;
        int hi = size - 1;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (cross(mid, mid + 1, qx, qz) >= 0) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return at[lo];
    }
}
