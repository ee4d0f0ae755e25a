package io.github.jdem846.shadow;

/**
 * The cells a sweep computes, in its frame ({@link SweepGrid}): major indices wi0 … wi1, minor wj0 … wj1, terrain
 * read up to major index iTop; {@code out} is row-major over {@code win} (null for the multi-elevation walk).
 */
record SweepWindow(CellWindow win, int wi0, int wi1, int wj0, int wj1, int iTop, float[] out) {
}
