package io.github.jdem846.shadow;

import java.util.Arrays;

/**
 * {@link HorizonHulls} limited to a search radius: from a point at distance P along a line, only the line's samples
 * at P − radius or later count. The samples in reach form a queue (pushed at the near end, dropped at the far end as
 * the walk moves on), and the steepest slope over a union is the larger of the steepest slopes over its parts, so
 * each line keeps the queue as two parts, as a queue is built from two stacks:
 * <ul>
 * <li>the near part, the samples pushed since the last hand-over, with their upper hull as in {@link HorizonHulls};
 * <li>the far part, the older samples still in reach, with the upper hull of every one of its suffixes: built by
 * adding the far part's samples from the nearest to the farthest, each addition overwriting one slot and remembering what
 * it held, so dropping the farthest sample undoes its addition in O(1).
 * </ul>
 * When the far part is empty and the near part's farthest sample falls out of reach, the near part is handed over
 * to the far part. Every sample is added to each part once, in O(1) amortised, and a query searches two hulls, each
 * from its last tangent point. The
 * result is the steepest slope over exactly the samples in reach, whichever part holds them, so it does not depend
 * on where a walk started (a window with a halo of at least the radius sees what the whole grid sees).
 */
final class WindowedHulls implements LineHorizons {

    private final double radius;
    private final Line[] lines;

    /**
     * @param lines  the number of lines of the block
     * @param radius the search radius, in the unit of the distances P (ground metres)
     */
    WindowedHulls(int lines, double radius) {
        this.radius = radius;
        this.lines = new Line[lines];
        for (int q = 0; q < lines; q++) {
            this.lines[q] = new Line();
        }
    }

    @Override
    public void push(int q, double px, double pz) {
        lines[q].push(px, pz);
    }

    /**
     * The steepest slope (z − pz)/(px − x) from (px, pz) to line q's samples at x ≥ px − radius, at least 0 (none
     * in reach is a horizon at 0°). The distances px of successive queries on a line must not decrease.
     *
     * @param px a distance beyond every sample of the line
     */
    @Override
    public double slope(int q, double px, double pz) {
        Line l = lines[q];
        l.drop(px - radius);
        return Math.max(0, Math.max(l.nearSlope(px, pz), l.farSlope(px, pz)));
    }

    /** One line's samples in reach: the near part and the far part. */
    private static final class Line {
        // near part: every sample since the hand-over (nx, nz; n of them) and their upper hull (hx, hz; hn)
        private double[] nx = new double[16];
        private double[] nz = new double[16];
        private int n;
        private double[] hx = new double[16];
        private double[] hz = new double[16];
        private int hn;
        private int nearHint;
        // far part: samples fx, fz [head, fn) in reach, farthest first; the hull of fx[head ...] is the stack
        // sx, sz [0, top], its farthest vertex at top; adding sample k wrote one slot, whose old value and the old top
        // are kept in savedX, savedZ, savedTop [k]
        private double[] fx = new double[16];
        private double[] fz = new double[16];
        private int fn;
        private int head;
        private double[] sx = new double[16];
        private double[] sz = new double[16];
        private int top = -1;
        private int farHint;
        private int[] savedTop = new int[16];
        private double[] savedX = new double[16];
        private double[] savedZ = new double[16];

        void push(double px, double pz) {
            if (n == nx.length) {
                nx = Arrays.copyOf(nx, 2 * n);
                nz = Arrays.copyOf(nz, 2 * n);
            }
            nx[n] = px;
            nz[n] = pz;
            n++;
            int k = hn;
            while (k >= 2 && (hx[k - 1] - hx[k - 2]) * (pz - hz[k - 2]) - (hz[k - 1] - hz[k - 2]) * (px - hx[k - 2])
                    >= 0) {
                k--;
            }
            if (k == hx.length) {
                hx = Arrays.copyOf(hx, 2 * k);
                hz = Arrays.copyOf(hz, 2 * k);
            }
            hx[k] = px;
            hz[k] = pz;
            hn = k + 1;
        }

        /** Drops the samples before {@code from}: farthest first, handing the near part over when it is reached. */
        void drop(double from) {
            while (true) {
                if (head < fn) {
                    if (!(fx[head] < from)) {
                        return;
                    }
                    undo(head);
                    head++;
                } else if (n > 0 && nx[0] < from) {
                    handOver();
                } else {
                    return;
                }
            }
        }

        /** Moves the near part's samples to the far part, building its suffix hulls from the nearest sample on. */
        private void handOver() {
            double[] tx = fx;
            double[] tz = fz;
            fx = nx;
            fz = nz;
            fn = n;
            head = 0;
            nx = tx;
            nz = tz;
            n = 0;
            hn = 0;
            nearHint = 0;
            if (sx.length < fn) {
                sx = new double[fx.length];
                sz = new double[fx.length];
                savedTop = new int[fx.length];
                savedX = new double[fx.length];
                savedZ = new double[fx.length];
            }
            top = -1;
            for (int k = fn - 1; k >= 0; k--) {
                add(k);
            }
        }

        /**
         * Adds far sample k, farther than every vertex of the stack, at its far end: the vertices from the farthest
         * on up to the first one that stays a vertex (the first whose line to its nearer neighbour passes strictly
         * above the new point) leave the hull; the slot the new point takes is remembered.
         */
        private void add(int k) {
            double px = fx[k];
            double pz = fz[k];
            // vertices in far-to-near order: v(t) = stack slot top − t, t = 0 … top; the last one always stays
            // a hand-over adds its samples one after the other with no undo in between, so walking from the far end
            // pops each vertex at most once over the hand-over: O(1) a sample, as for the near hull
            int lo = 0;
            while (lo < top && !staysAfter(top - lo, px, pz)) {
                lo++;
            }
            int slot = top - lo + 1;                  // top − lo is the first vertex kept (−1 + 1 = 0 when empty)
            // the slot may hold a vertex of an earlier stack (one popped by a later addition that is not undone
            // yet): always remember it
            savedTop[k] = top;
            savedX[k] = sx[slot];
            savedZ[k] = sz[slot];
            sx[slot] = px;
            sz[slot] = pz;
            top = slot;
        }

        /** True when stack vertex s stays a vertex with (px, pz) added beyond the far end: strictly above the line. */
        private boolean staysAfter(int s, double px, double pz) {
            if (s == 0) {
                return true;
            }
            // (px, pz) strictly below the line through vertex s and its nearer neighbour s − 1
            double ax = sx[s];
            double az = sz[s];
            return (sx[s - 1] - ax) * (pz - az) - (sz[s - 1] - az) * (px - ax) < 0;
        }

        /** Undoes the addition of far sample k, the farthest in the stack. */
        private void undo(int k) {
            sx[top] = savedX[k];
            sz[top] = savedZ[k];
            top = savedTop[k];
        }

        /** The steepest slope to the near part's hull (searched from its last tangent, as {@link HorizonHulls}). */
        double nearSlope(double px, double pz) {
            int n = hn;
            if (n == 0) {
                return 0;
            }
            int last = n - 1;
            int g = Math.min(nearHint, last);
            int lo;
            int hi;
            if (g == last || nearAtOrBefore(g, px, pz)) {
                hi = g;
                int s = 1;
                while (true) {
                    int k = hi - s;
                    if (k < 0) {
                        lo = 0;
                        break;
                    }
                    if (!nearAtOrBefore(k, px, pz)) {
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
                    if (nearAtOrBefore(k, px, pz)) {
                        hi = k;
                        break;
                    }
                    lo = k + 1;
                    s <<= 1;
                }
            }
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (nearAtOrBefore(mid, px, pz)) {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            nearHint = lo;
            return (hz[lo] - pz) / (px - hx[lo]);
        }

        /** True when (px, pz) lies on or above the line through near vertices k and k + 1. */
        private boolean nearAtOrBefore(int k, double px, double pz) {
            return (hx[k + 1] - hx[k]) * (pz - hz[k]) - (hz[k + 1] - hz[k]) * (px - hx[k]) >= 0;
        }

        /**
         * The steepest slope to the far part's hull: its vertices far to near are the slots top, top − 1, … 0; the
         * tangent is the first whose edge to the next passes on or below (px, pz), searched from the slot of the
         * last tangent (slots below the top do not move when the far end is dropped).
         */
        double farSlope(double px, double pz) {
            int t0 = top;
            if (t0 < 0) {
                return 0;
            }
            // in t = top − slot order the predicate runs false … false true … true, true at t = top (slot 0)
            int g = Math.max(0, t0 - Math.min(farHint, t0));
            int lo;
            int hi;
            if (g == t0 || farAtOrBefore(t0 - g, px, pz)) {
                hi = g;
                int s = 1;
                while (true) {
                    int k = hi - s;
                    if (k < 0) {
                        lo = 0;
                        break;
                    }
                    if (!farAtOrBefore(t0 - k, px, pz)) {
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
                    if (k >= t0) {
                        hi = t0;
                        break;
                    }
                    if (farAtOrBefore(t0 - k, px, pz)) {
                        hi = k;
                        break;
                    }
                    lo = k + 1;
                    s <<= 1;
                }
            }
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (farAtOrBefore(t0 - mid, px, pz)) {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            int slot = t0 - lo;
            farHint = slot;
            return (sz[slot] - pz) / (px - sx[slot]);
        }

        /** True when (px, pz) lies on or above the line through stack slot a (≥ 1) and its nearer neighbour a − 1. */
        private boolean farAtOrBefore(int a, double px, double pz) {
            int b = a - 1;
            return (sx[b] - sx[a]) * (pz - sz[a]) - (sz[b] - sz[a]) * (px - sx[a]) >= 0;
        }
    }
}
