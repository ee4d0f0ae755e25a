package io.github.jdem846.shade;

/**
 * The loop shape of the hillshade row kernels ({@link HornRows}, {@link JDem846Rows}); both give the same floats.
 * {@link #SPLIT}, the default, runs one step for a chunk of cells per loop, which the optimising JIT (C2) turns into
 * SIMD code; {@link #FUSED} runs every step for one cell in a single loop, which the first-tier JIT (C1,
 * {@code -XX:TieredStopAtLevel=1}) runs 1.1 (Horn) and 1.5 (jdem846) times as fast as its split loops, and C2 at
 * 0.45 and 0.4 times the speed of its own split loops (bench.HillshadeKernelTiming, 4000², docs/performance.md). The
 * launcher runs small jobs with the first-tier JIT and the system property {@code jdem846.kernels=fused}, which
 * chooses {@link #FUSED}.
 */
enum KernelShape {
    SPLIT,
    FUSED;

    /** {@link #FUSED} when the system property {@code jdem846.kernels} is {@code fused}, else {@link #SPLIT}. */
    static final KernelShape CHOSEN = "fused".equals(System.getProperty("jdem846.kernels")) ? FUSED : SPLIT;
}
