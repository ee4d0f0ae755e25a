package io.github.jdem846.internal;

/**
 * {@link Math#round(float)} and {@link Math#rint(double)} for per-cell loops that turn fractions into bytes.
 * {@code Math.round} must get the halfway cases of large floats and the float just below one half right, which keeps
 * HotSpot from vectorising the loop; here the sum {@code v + 0.5} is taken in double, where it is exact for every
 * float, so its floor is {@code Math.round}'s answer without the special cases: 3–10× faster on 16 million cells
 * (JDK 17 / 25). {@code Math.rint} is an intrinsic of the optimising JIT only: the first-tier JIT, which the launcher
 * chooses for small jobs, runs its Java code, a third of the Horn hillshade phase of 16 million cells in JFR.
 */
public final class Rounding {

    private static final double TWO_POW_52 = 0x1p52;

    private Rounding() {
    }

    /**
     * {@code Math.round(v)} for {@code v} from −0.5 to {@link Integer#MAX_VALUE} (where truncation is the floor),
     * and 0 for NaN, as {@code Math.round} gives.
     */
    public static int halfUp(float v) {
        return (int) (v + 0.5d);
    }

    /**
     * {@code Math.rint(v)}, the nearest integer with ties to even, for {@code v} from 0 to 2<sup>52</sup>, and NaN
     * for NaN: {@code v + 2^52} lies where doubles are whole numbers, so the addition rounds as {@code rint} does and
     * the subtraction is exact. Two additions that every JIT compiles inline.
     */
    public static double halfEven(double v) {
        return v + TWO_POW_52 - TWO_POW_52;
    }
}
