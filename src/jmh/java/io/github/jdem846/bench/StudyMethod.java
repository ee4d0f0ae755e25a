package io.github.jdem846.bench;

import io.github.jdem846.shadow.Sampling;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.shadow.StepSize;

/**
 * The shadow methods and settings compared by the accuracy study, with the {@code exact} reference. Marches and the
 * reference are evaluated on the study's cells only ({@link ShadowAlgorithm#computeCells}); sweeps always on the
 * whole grid (that is how they work), their timing included.
 */
enum StudyMethod {

    EXACT("exact (reference, 1/8 cell, bilinear)", ShadowAlgorithm.EXACT, ShadowOptions.DEFAULTS),
    MARCH_ARTICLE("march, article step (eq. 9), nearest", ShadowAlgorithm.MARCH,
            march(StepSize.ARTICLE, Sampling.NEAREST)),
    MARCH_1_NEAREST("march 1 cell, nearest", ShadowAlgorithm.MARCH, march(StepSize.ONE_CELL, Sampling.NEAREST)),
    MARCH_HALF_NEAREST("march 1/2 cell, nearest", ShadowAlgorithm.MARCH,
            march(StepSize.HALF_CELL, Sampling.NEAREST)),
    MARCH_QUARTER_NEAREST("march 1/4 cell, nearest", ShadowAlgorithm.MARCH,
            march(StepSize.QUARTER_CELL, Sampling.NEAREST)),
    MARCH_1_BILINEAR("march 1 cell, bilinear", ShadowAlgorithm.MARCH, march(StepSize.ONE_CELL, Sampling.BILINEAR)),
    MARCH_HALF_BILINEAR("march 1/2 cell, bilinear", ShadowAlgorithm.MARCH,
            march(StepSize.HALF_CELL, Sampling.BILINEAR)),
    MARCH_QUARTER_BILINEAR("march 1/4 cell, bilinear", ShadowAlgorithm.MARCH,
            march(StepSize.QUARTER_CELL, Sampling.BILINEAR)),
    SWEEP("sweep, bilinear + first-cell test (default)", ShadowAlgorithm.SWEEP,
            ShadowOptions.DEFAULTS.withSampling(Sampling.BILINEAR)),
    SWEEP_NO_FIRST_CELL("sweep, bilinear, no first-cell test", ShadowAlgorithm.SWEEP,
            ShadowOptions.DEFAULTS.withSampling(Sampling.BILINEAR).withFirstCellTest(false)),
    SWEEP_NEAREST("sweep, nearest", ShadowAlgorithm.SWEEP, ShadowOptions.DEFAULTS.withSampling(Sampling.NEAREST));

    /** Human-readable name for tables and plot legends. */
    final String label;
    final ShadowAlgorithm algorithm;
    final ShadowOptions options;

    StudyMethod(String label, ShadowAlgorithm algorithm, ShadowOptions options) {
        this.label = label;
        this.algorithm = algorithm;
        this.options = options;
    }

    private static ShadowOptions march(StepSize step, Sampling sampling) {
        return ShadowOptions.DEFAULTS.withStep(step).withSampling(sampling);
    }

    /** True when the method is computed on the whole grid (sweeps), false when on the study's cells only. */
    boolean wholeGrid() {
        return algorithm == ShadowAlgorithm.SWEEP;
    }

    /** The CSV key: the constant's name in lower case with dashes. */
    String key() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }

    static StudyMethod ofKey(String key) {
        for (StudyMethod m : values()) {
            if (m.key().equals(key)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown method '" + key + "' in the CSV");
    }
}
