package io.github.jdem846.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
