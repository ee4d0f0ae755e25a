package io.github.jdem846.shadow;

import io.github.jdem846.internal.Rounding;
/**
 * The result of a shadow computation: for each cell the shadowed fraction of the sun, 0 = fully lit, 1 = fully in
 * shadow (hard shadows give only 0 and 1). Row 0 is north, row-major, the size of the DEM or window it was computed
 * for. No-data cells are 0.
 */
public final class ShadowMask {

    private final int width;
    private final int height;
    private final float[] shadow;

    /**
     * Wraps {@code shadow} (not copied), row-major with row length {@code width}.
     *
     * @param width number of columns, ≥ 1
     * @param height number of rows, ≥ 1
     * @param shadow shadowed fractions, {@code width × height} values
     */
    public ShadowMask(int width, int height, float[] shadow) {
        if (width < 1 || height < 1 || shadow.length != (long) width * height) {
            throw new IllegalArgumentException("a " + width + "×" + height + " mask needs " + (long) width * height
                    + " values, got " + shadow.length);
        }
        this.width = width;
        this.height = height;
        this.shadow = shadow;
    }

    /** A mask with every cell at {@code value}. */
    static ShadowMask filled(int width, int height, float value) {
        float[] a = new float[width * height];
        if (value != 0) {
            java.util.Arrays.fill(a, value);
        }
        return new ShadowMask(width, height, a);
    }

    /** {@return number of columns} */
    public int width() {
        return width;
    }

    /** {@return number of rows} */
    public int height() {
        return height;
    }

    /**
     * Shadowed fraction of cell ({@code col}, {@code row}), in [0, 1].
     *
     * @param col column, from 0 at the left
     * @param row row, from 0 at the top
     * @return the fraction
     */
    public float get(int col, int row) {
        return shadow[row * width + col];
    }

    /**
     * The backing array (row-major, not a copy); callers must not modify it.
     *
     * @return the shadowed fractions, row-major
     */
    public float[] backingArray() {
        return shadow;
    }

    /**
     * The mask as bytes, 0 = lit, 255 = shadow, rounded.
     *
     * @return one byte per cell, row-major
     */
    public byte[] toBytes() {
        byte[] b = new byte[shadow.length];
        for (int i = 0; i < shadow.length; i++) {
            b[i] = (byte) Rounding.halfUp(shadow[i] * 255f);
        }
        return b;
    }

    /**
     * Number of cells whose shadowed fraction is at least one half.
     *
     * @return the count of mostly shadowed cells
     */
    public long shadowedCount() {
        long n = 0;
        for (float v : shadow) {
            if (v >= 0.5f) {
                n++;
            }
        }
        return n;
    }

    /**
     * Fraction of cells on which this mask and {@code other} disagree, a cell counting as shadowed when its
     * fraction is at least one half.
     *
     * @param other a mask of the same size
     * @return the fraction of cells, in [0, 1]
     */
    public double disagreement(ShadowMask other) {
        if (other.width != width || other.height != height) {
            throw new IllegalArgumentException("masks differ in size: " + width + "×" + height + " and "
                    + other.width + "×" + other.height);
        }
        long n = 0;
        for (int i = 0; i < shadow.length; i++) {
            if ((shadow[i] >= 0.5f) != (other.shadow[i] >= 0.5f)) {
                n++;
            }
        }
        return (double) n / shadow.length;
    }

    @Override
    public String toString() {
        return "ShadowMask[" + width + "×" + height + ", " + shadowedCount() + " shadowed]";
    }
}
