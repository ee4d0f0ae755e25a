package io.github.jdem846.shadow;

/** How a ray reads the terrain between cell centres. */
public enum Sampling {
    /** The algorithm's own choice: nearest cell for {@code march} (as the article), bilinear for the others. */
    AUTO,
    /** The elevation of the cell whose area contains the point (the article's and the original's lookup). */
    NEAREST,
    /** Bilinear interpolation between the four surrounding cell centres (no-data corners left out). */
    BILINEAR
}
