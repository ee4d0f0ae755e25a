package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The upper convex hulls of the terrain already walked on each line of a block ({@link HorizonSweep}), as points
 * (P, z) with the distance P growing in the walk's direction. From a point beyond every point of a line, the
 * steepest elevation angle to that line's terrain is the angle to the hull's tangent point: the line's horizon. A
 * point lies beyond every point on the hull when it is pushed, and a point below a hull edge can never be a tangent
 * point again, so each sample is pushed and popped at most once.
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
     * or none, is a horizon at 0°). The slopes to the hull's vertices, from the last one back, rise to the tangent
     * point and fall after it: the walk stops at the first fall.
     *
     * @param px a distance beyond every sample of the line
     */
    double slope(int q, double px, double pz) {
        int k = size[q] - 1;
        if (k < 0) {
            return 0;
        }
        double[] hx = x[q];
        double[] hz = z[q];
        double best = (hz[k] - pz) / (px - hx[k]);
        while (k > 0) {
            double s = (hz[k - 1] - pz) / (px - hx[k - 1]);
            if (s < best) {
                break;
            }
            best = s;
            k--;
        }
        return best > 0 ? best : 0;
    }
}
