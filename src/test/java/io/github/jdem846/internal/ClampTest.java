package io.github.jdem846.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** {@link Clamp} against the {@code Math.min}/{@code Math.max} forms it replaces, bit for bit. */
class ClampTest {

    private static final double[][] BOUNDS = {{-1.0, 1.0}, {0.0, 1.0}, {0.0, 255.0}};

    private static double[] inputs() {
        double[] special = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0.0, -0.0, 1.0, -1.0,
            255.0, Math.nextUp(1.0), Math.nextDown(1.0), Math.nextUp(-1.0), Math.nextDown(-1.0), Math.nextUp(0.0),
            Math.nextDown(0.0), Math.nextUp(255.0), Math.nextDown(255.0), Double.MAX_VALUE, -Double.MAX_VALUE,
            Double.MIN_VALUE, -Double.MIN_VALUE, Double.longBitsToDouble(0x7ff8_0000_0000_1234L)};
        Random rnd = new Random(3);
        double[] all = new double[special.length + 20_000];
        System.arraycopy(special, 0, all, 0, special.length);
        for (int i = special.length; i < all.length; i++) {
            all[i] = i % 2 == 0 ? (rnd.nextDouble() - 0.5) * 600 : Double.longBitsToDouble(rnd.nextLong());
        }
        return all;
    }

    @Test
    void betweenEqualsMaxOfMinForEveryBoundPairInUse() {
        for (double[] b : BOUNDS) {
            for (double x : inputs()) {
                assertEquals(Double.doubleToRawLongBits(Math.max(b[0], Math.min(b[1], x))),
                        Double.doubleToRawLongBits(Clamp.between(x, b[0], b[1])), x + " in " + b[0] + "…" + b[1]);
                float f = (float) x;
                float lo = (float) b[0];
                float hi = (float) b[1];
                assertEquals(Float.floatToRawIntBits(Math.max(lo, Math.min(hi, f))),
                        Float.floatToRawIntBits(Clamp.between(f, lo, hi)), f + "f in " + lo + "…" + hi);
            }
        }
    }

    @Test
    void atLeastZeroEqualsMaxWithZero() {
        for (double x : inputs()) {
            assertEquals(Double.doubleToRawLongBits(Math.max(0.0, x)), Double.doubleToRawLongBits(Clamp.atLeastZero(x)),
                    Double.toString(x));
        }
    }
}
