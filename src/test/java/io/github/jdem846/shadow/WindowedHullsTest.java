package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The hulls with a search radius against the plain definition: the steepest slope from the query point to the
 * samples within the radius, at least 0, on random profiles (rough, smooth, flat, with long steps).
 */
class WindowedHullsTest {

    private static double bruteForce(double[] x, double[] z, int n, double px, double pz, double radius) {
        double best = 0;
        for (int k = 0; k < n; k++) {
            if (x[k] >= px - radius) {
                best = Math.max(best, (z[k] - pz) / (px - x[k]));
            }
        }
        return best;
    }

    @Test
    void everyQueryIsTheSteepestSlopeToTheSamplesInReach() {
        SplittableRandom random = new SplittableRandom(846);
        for (int run = 0; run < 300; run++) {
            int kind = run % 3;
            double radius = 1 + random.nextDouble() * (run % 5 == 0 ? 400 : 40);
            int lines = 3;
            WindowedHulls hulls = new WindowedHulls(lines, radius);
            HorizonHulls unbounded = new HorizonHulls(lines);
            int count = 50 + random.nextInt(400);
            double[][] x = new double[lines][count];
            double[][] z = new double[lines][count];
            int[] n = new int[lines];
            double[] pos = new double[lines];
            double[] walk = new double[lines];
            for (int i = 0; i < count; i++) {
                for (int q = 0; q < lines; q++) {
                    pos[q] += kind == 2 ? 1 : 0.2 + random.nextDouble() * 3;
                    // queries from points above, on and below the terrain around
                    for (int t = 0; t < 2; t++) {
                        double pz = walk[q] + (random.nextDouble() - 0.5) * 30;
                        double expected = bruteForce(x[q], z[q], n[q], pos[q], pz, radius);
                        assertEquals(expected, hulls.slope(q, pos[q], pz), 1e-12 * (1 + expected),
                                "run " + run + " line " + q + " sample " + i);
                        double all = bruteForce(x[q], z[q], n[q], pos[q], pz, Double.POSITIVE_INFINITY);
                        assertEquals(all, unbounded.slope(q, pos[q], pz), 1e-12 * (1 + all));
                    }
                    walk[q] = kind == 0 ? walk[q] + (random.nextDouble() - 0.5) * 20
                            : kind == 1 ? 50 * Math.sin(i * 0.05 + q) : 7;
                    x[q][n[q]] = pos[q];
                    z[q][n[q]] = walk[q];
                    n[q]++;
                    hulls.push(q, pos[q], walk[q]);
                    unbounded.push(q, pos[q], walk[q]);
                }
            }
        }
    }
}
