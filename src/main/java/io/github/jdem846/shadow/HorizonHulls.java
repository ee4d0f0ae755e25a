package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The upper convex hulls of the terrain already walked on each line of a block ({@link HorizonSweep}), as points
 * (P, z) with the distance P growing in the walk's direction. From a point beyond every point of a line, the
 * steepest elevation angle to that line's terrain is the angle to the hull's tangent point: the line's horizon. A
 * point below a hull edge can never be a tangent point for any point farther on, so each sample is pushed and popped
 * at most once, and a query bisects the hull: O(log hull size).
 */
final class HorizonHulls {

    private double[][] x;
    private double[][] z;
    private final int[] size;

    /** @param lines the number of lines of the block */
    HorizonHulls(int lines) {
        x = new double[lines][8];
        z = new double[lines][8];
        size = new int[lines];
    }

    /** Adds the sample (px, pz) to line q's hull; px must exceed every distance added to that line before. */
    void push(int q, double px, double pz) {
        double[] hx = x[q];
        double[] hz = z[q];
        int n = size[q];
        // pop the last vertex while it lies on or below the segment from the one before it to the new point
        while (n >= 2 && (hx[n - 1] - hx[n - 2]) * (pz - hz[n - 2]) - (hz[n - 1] - hz[n - 2]) * (px - hx[n - 2]) >= 0) {
            n--;
        }
        if (n == hx.length) {
            hx = Arrays.copyOf(hx, 2 * n);
            hz = Arrays.copyOf(hz, 2 * n);
            x[q] = hx;
            z[q] = hz;
        }
        hx[n] = px;
        hz[n] = pz;
        size[q] = n + 1;
    }

    /**
     * The steepest slope (z − pz)/(px − x) from (px, pz) to line q's terrain, at least 0 (terrain beyond the grid,
     * or none, is a horizon at 0°): the slope to the hull's tangent point, the first vertex whose next edge's line
     * passes on or below (px, pz), found by bisection.
     *
     * @param px a distance beyond every sample of the line
     */
    double slope(int q, double px, double pz) {
        int n = size[q];
        if (n == 0) {
            return 0;
        }
        double[] hx = x[q];
        double[] hz = z[q];
        int lo = 0;
        int hi = n - 1;
        // often the last vertex, the nearest terrain, is the tangent point: test its edge first
        if (hi > 0 && (hx[hi] - hx[hi - 1]) * (pz - hz[hi - 1]) - (hz[hi] - hz[hi - 1]) * (px - hx[hi - 1]) < 0) {
            lo = hi;
        }
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            // (px, pz) on or above the line through vertices mid and mid + 1: the tangent is at mid or before
            if ((hx[mid + 1] - hx[mid]) * (pz - hz[mid]) - (hz[mid + 1] - hz[mid]) * (px - hx[mid]) >= 0) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        double best = (hz[lo] - pz) / (px - hx[lo]);
        return best > 0 ? best : 0;
    }
}
