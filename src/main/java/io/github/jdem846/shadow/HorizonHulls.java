package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * The upper convex hulls of the terrain already walked on each line of a block ({@link HorizonSweep}), as points
 * (P, z) with the distance P growing in the walk's direction. From a point beyond every point of a line, the
 * steepest elevation angle to that line's terrain is the angle to the hull's tangent point: the line's horizon. A
 * point below a hull edge can never be a tangent point for any point farther on, so each sample is pushed and popped
 * at most once. A query searches the hull from the line's last tangent point, by steps doubling away from it and
 * then bisection: neighbouring cells mostly share their tangent point or have it a vertex or two apart, so a query
 * costs O(log distance moved), a few cross products, instead of a bisection of the whole hull.
 */
final class HorizonHulls implements LineHorizons {

    /** Per line: the hull's vertices interleaved, P at 2k and z at 2k + 1 (one cache line holds both). */
    private final double[][] h;
    private final int[] size;
    /** Per line: the vertex of its last tangent, where the next search starts. */
    private final int[] hint;

    /** @param lines the number of lines of the block */
    HorizonHulls(int lines) {
        h = new double[lines][16];
        size = new int[lines];
        hint = new int[lines];
    }

    @Override
    public void push(int q, double px, double pz) {
        double[] a = h[q];
        int n = size[q];
        // pop the last vertex while it lies on or below the segment from the one before it to the new point
        while (n >= 2) {
            int l = 2 * n - 2;
            double x1 = a[l];
            double z1 = a[l + 1];
            double x0 = a[l - 2];
            double z0 = a[l - 1];
            if ((x1 - x0) * (pz - z0) - (z1 - z0) * (px - x0) < 0) {
                break;
            }
            n--;
        }
        if (2 * n == a.length) {
            a = Arrays.copyOf(a, 4 * n);
            h[q] = a;
        }
        a[2 * n] = px;
        a[2 * n + 1] = pz;
        size[q] = n + 1;
    }

    /**
     * True when (px, pz) lies on or above the line through vertices k and k + 1: the tangent point is k or before.
     */
    private static boolean atOrBefore(double[] a, int k, double px, double pz) {
        int l = 2 * k;
        double x0 = a[l];
        double z0 = a[l + 1];
        return (a[l + 2] - x0) * (pz - z0) - (a[l + 3] - z0) * (px - x0) >= 0;
    }

    /**
     * The steepest slope (z − pz)/(px − x) from (px, pz) to line q's terrain, at least 0 (terrain beyond the grid,
     * or none, is a horizon at 0°): the slope to the hull's tangent point, the first vertex whose next edge's line
     * passes on or below (px, pz).
     *
     * @param px a distance beyond every sample of the line
     */
    @Override
    public double slope(int q, double px, double pz) {
        int n = size[q];
        if (n == 0) {
            return 0;
        }
        double[] a = h[q];
        int last = n - 1;
        int g = Math.min(hint[q], last);
        // the answer is the first k with atOrBefore(k) (vertex n − 1 when none): bracket it in [lo, hi] from g
        int lo;
        int hi;
        if (g == last || atOrBefore(a, g, px, pz)) {
            hi = g;
            int s = 1;
            while (true) {
                int k = hi - s;
                if (k < 0) {
                    lo = 0;
                    break;
                }
                if (!atOrBefore(a, k, px, pz)) {
                    lo = k + 1;
                    break;
                }
                hi = k;
                s <<= 1;
            }
        } else {
            lo = g + 1;
            int s = 1;
            while (true) {
                int k = lo + s - 1;
                if (k >= last) {
                    hi = last;
                    break;
                }
                if (atOrBefore(a, k, px, pz)) {
                    hi = k;
                    break;
                }
                lo = k + 1;
                s <<= 1;
            }
        }
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (atOrBefore(a, mid, px, pz)) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        hint[q] = lo;
        return Math.max((a[2 * lo + 1] - pz) / (px - a[2 * lo]), 0);
    }
}
