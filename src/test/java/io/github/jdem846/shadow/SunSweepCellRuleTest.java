package io.github.jdem846.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The sweep's cell rule ({@link SweepCell}), which every walk builds on, against its definitions: the running
 * maximum in both of its forms against the maximum over a line's upstream samples, the first-step closed form
 * against the eighth-step samples of the bilinear cell, and the floor rule between two lines.
 */
class SunSweepCellRuleTest {

    private static final double NONE = Double.NEGATIVE_INFINITY;

    /**
     * A line's samples z(i) (NaN = none) walked from the top down with one step length: at each i the relative form
     * (joined, pending) and the absolute form (lifted, higher, heightAt) both give max(z(i') − (i' − i)·drop over
     * i' ≥ i + 2), computed here directly.
     */
    @Test
    void bothRunningMaximaAreTheHighestUpstreamSampleLessItsDrop() {
        SplittableRandom rnd = new SplittableRandom(846);
        int compared = 0;
        for (int t = 0; t < 200; t++) {
            int n = 2 + rnd.nextInt(60);
            double step = 1 + rnd.nextDouble() * 100;
            double tan = rnd.nextDouble() * 2;
            double drop = tan * step;
            double[] z = new double[n];
            for (int i = 0; i < n; i++) {
                z[i] = rnd.nextInt(5) == 0 ? Double.NaN : rnd.nextDouble() * 1000;
            }
            double best = NONE;
            double pending = NONE;
            double bestAbs = NONE;
            double twoUp = NONE;
            double oneUp = NONE;
            for (int i = n - 1; i >= 0; i--) {
                double p = (n - 1 - i) * step;                  // distance from the line's top
                double expected = NONE;
                for (int u = i + 2; u < n; u++) {
                    if (z[u] == z[u]) {
                        expected = Math.max(expected, z[u] - (u - i) * drop);
                    }
                }
                double relative = best;
                bestAbs = SweepCell.higher(bestAbs, twoUp);
                double absolute = SweepCell.heightAt(bestAbs, tan, p);
                if (expected == NONE) {
                    assertEquals(NONE, relative, "relative, trial " + t + " i " + i);
                    assertEquals(NONE, absolute, "absolute, trial " + t + " i " + i);
                } else {
                    assertEquals(expected, relative, 1e-9 * (1 + Math.abs(expected)), "relative, trial " + t);
                    assertEquals(expected, absolute, 1e-9 * (1 + Math.abs(expected) + tan * p), "absolute, trial " + t);
                    compared++;
                }
                best = SweepCell.joined(best, pending, drop);
                pending = SweepCell.pending(z[i], drop);
                twoUp = oneUp;
                oneUp = SweepCell.lifted(z[i], tan, p);
            }
        }
        assertTrue(compared > 2000, "the walks must include shaded positions, got " + compared);
    }

    /**
     * The closed form of the first step ({@link SweepCell#above}, {@link SweepCell#rises} on {@link
     * SweepCell#slope} and {@link SweepCell#bend}) decides as the samples t = first/8 … 1 of the bilinear cell do:
     * is terrain above the ray z0 + t·dTan at any of them.
     */
    @Test
    void firstStepClosedFormEqualsItsEighthSamples() {
        SplittableRandom rnd = new SplittableRandom(47);
        int blocked = 0;
        int lit = 0;
        for (int t = 0; t < 100_000; t++) {
            double z0 = rnd.nextDouble() * 100;
            double z10 = z0 + rnd.nextDouble(-20, 20);
            double z01 = z0 + rnd.nextDouble(-20, 20);
            double z11 = z0 + rnd.nextDouble(-20, 20);
            double m = rnd.nextInt(8) == 0 ? 0 : rnd.nextDouble();
            double dTan = rnd.nextDouble() * 30;
            int first = rnd.nextBoolean() ? 1 : SweepGrid.SUB_STEPS;
            double tFirst = (double) first / SweepGrid.SUB_STEPS;
            boolean sampled = false;
            double margin = Double.POSITIVE_INFINITY;
            for (int q = first; q <= SweepGrid.SUB_STEPS; q++) {
                double s = (double) q / SweepGrid.SUB_STEPS;
                double y = m * s;
                double terrain = (z0 + (z10 - z0) * s) * (1 - y) + (z01 + (z11 - z01) * s) * y;
                double excess = terrain - (z0 + s * dTan);
                sampled |= excess > 0;
                margin = Math.min(margin, Math.abs(excess));
            }
            if (margin < 1e-9) {
                continue;                                     // too close to call in floating point
            }
            boolean closed = SweepCell.above(z0, z10, z01, z11)
                    & SweepCell.rises(SweepCell.slope(z0, z10, z01, m) - dTan, SweepCell.bend(z0, z10, z01, z11, m),
                    tFirst);
            assertEquals(sampled, closed, "z " + z0 + " " + z10 + " " + z01 + " " + z11 + " m " + m + " dTan "
                    + dTan + " first " + first);
            if (sampled) {
                blocked++;
            } else {
                lit++;
            }
        }
        assertTrue(blocked > 10_000 && lit > 10_000, "both answers must occur: " + blocked + " blocked, " + lit
                + " lit");
    }

    /** Between two lines: interpolated when both are at or above the floor, else the other line's height whole. */
    @Test
    void aLineBelowTheFloorCountsAsNoTerrain() {
        assertEquals(12.5, SweepCell.between(10, 20, 0.25, 0), 1e-12);
        assertEquals(10, SweepCell.between(10, 20, 0, 0), 0);
        assertEquals(20, SweepCell.between(-5, 20, 0.25, 0), 0);
        assertEquals(10, SweepCell.between(10, -5, 0.25, 0), 0);
        assertEquals(10, SweepCell.between(10, NONE, 0.25, 0), 0);
        assertEquals(20, SweepCell.between(NONE, 20, 0.75, 0), 0);
        assertEquals(NONE, SweepCell.between(NONE, NONE, 0.5, 0), 0);
    }
}
