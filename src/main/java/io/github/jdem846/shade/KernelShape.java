package io.github.jdem846.shade;

/**
 * The loop shape of the hillshade row kernels ({@link HornRows}, {@link JDem846Rows}); both give the same floats.
 * {@link #SPLIT}, the default, runs one step for a chunk of cells per loop, which the optimising JIT (C2) turns into
 * SIMD code; {@link #FUSED} runs every step for one cell in a single loop, which the first-tier JIT (C1,
 * {@code -XX:TieredStopAtLevel=1}) compiles to code 1.4 (Horn) to 1.8 (jdem846) times as fast as its split loops,
 * and C2 to code half as fast as its own split loops (4000², one thread). The launcher runs small jobs with the
 * first-tier JIT and the system property {@code jdem846.kernels=fused}, which chooses {@link #FUSED}.
 */
enum KernelShape {
    SPLIT,
    FUSED;

    /** {@link #FUSED} when the system property {@code jdem846.kernels} is {@code fused}, else {@link #SPLIT}. */
    static final KernelShape CHOSEN = "fused".equals(System.getProperty("jdem846.kernels")) ? FUSED : SPLIT;
}
