package io.github.jdem846.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class RoundingTest {

    @Test
    void equalsMathRoundForEveryFloatFromOneQuarterTo256() {
        // 84 million floats, every one of the byte range where the halfway cases and the float below 0.5 lie
        int end = Float.floatToIntBits(256f);
        for (int bits = Float.floatToIntBits(0.25f); bits <= end; bits++) {
            check(Float.intBitsToFloat(bits));
        }
    }

    @Test
    void equalsMathRoundOnSamplesFromMinusOneHalfToTheIntRange() {
        for (int bits = 0; bits < Float.floatToIntBits(0.25f); bits += 97) {
            check(Float.intBitsToFloat(bits));
        }
        for (int bits = Float.floatToIntBits(-0f); bits <= Float.floatToIntBits(-0.5f); bits += 97) {
            check(Float.intBitsToFloat(bits));
        }
        float[] edges = {-0.5f, Math.nextUp(-0.5f), Math.nextDown(0.5f), 0.5f,
            Math.nextUp(0.5f), 254.5f, Math.nextDown(254.5f), 255f, 8388607.5f, 8388608f, 16777216f,
            Math.nextDown((float) Integer.MAX_VALUE)};
        for (float v : edges) {
            check(v);
        }
        for (int bits = Float.floatToIntBits(256f); bits < Float.floatToIntBits((float) Integer.MAX_VALUE);
                bits += 1009) {
            check(Float.intBitsToFloat(bits));
        }
    }

    private static void check(float v) {
        if (Math.round(v) != Rounding.halfUp(v)) {
            assertEquals(Math.round(v), Rounding.halfUp(v), "at " + v);
        }
    }

    @Test
    void notANumberIsZero() {
        assertEquals(0, Rounding.halfUp(Float.NaN));
    }

    @Test
    void halfEvenEqualsMathRintForEveryFloatFromZeroTo256() {
        // every byte value a gray conversion rounds, with its ties (k + 0.5) and the floats beside them
        int end = Float.floatToIntBits(256f);
        for (int bits = 0; bits <= end; bits += bits < Float.floatToIntBits(0.25f) ? 101 : 1) {
            float v = Float.intBitsToFloat(bits);
            if (Math.rint(v) != Rounding.halfEven(v)) {
                assertEquals(Math.rint(v), Rounding.halfEven(v), "at " + v);
            }
        }
    }

    @Test
    void halfEvenEqualsMathRintForDoublesUpToTwoToThe52() {
        SplittableRandom random = new SplittableRandom(846);
        for (int i = 0; i < 1_000_000; i++) {
            double v = Math.scalb(random.nextDouble(), random.nextInt(-60, 53));
            assertEquals(Math.rint(v), Rounding.halfEven(v), "at " + v);
        }
        double[] edges = {0, 0.5, Math.nextDown(0.5), Math.nextUp(0.5), 1.5, 2.5, 254.5, 0x1p51 + 0.5, 0x1p52 - 0.5,
            0x1p52, Double.MIN_VALUE};
        for (double v : edges) {
            assertEquals(Math.rint(v), Rounding.halfEven(v), "at " + v);
        }
        assertEquals(Double.NaN, Rounding.halfEven(Double.NaN));
    }
}
