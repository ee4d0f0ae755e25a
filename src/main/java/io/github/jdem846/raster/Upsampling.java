package io.github.jdem846.raster;

/**
 * How a DEM is enlarged when a picture has more pixels than the DEM has cells (docs/scale.md, "Pictures larger than
 * the DEM"): the surface the stages then read at the picture's resolution.
 */
public enum Upsampling {

    /**
     * Bilinear between cell centres: continuous heights whose slope jumps at every cell edge, so hillshade shows
     * the cells as facets and self-shadow edges follow them.
     */
    BILINEAR,

    /**
     * Catmull-Rom bicubic (the cubic convolution with a = −0.5) between cell centres, beyond the grid's edge and
     * next to no-data extended linearly: it passes through the cells, keeps planes planes, and its slope is
     * continuous across cell edges, so hillshade and shadow edges are smooth. Next to a no-data cell (inner 2 × 2
     * not all data) it is bilinear over the cells that are data. It overshoots next to steep steps: between two cells
     * at −1 m beside a 50 m drop on either side it rises to +5 m.
     */
    CATMULL_ROM,

    /**
     * Monotone bicubic: cubic Hermite pieces along x, then along y, whose tangent at a cell centre is the harmonic
     * mean of the slopes on either side, or 0 at a local extremum (Fritsch and Butland's monotone cubic). Between
     * two cells it stays within their values, so it adds no peak, pit or sea-level crossing that the cells do not
     * have, keeps planes planes, and its slope is continuous across cell edges. Next to no-data it is bilinear over
     * the cells that are data, as {@link #CATMULL_ROM}. The default ({@link DemResampler#DEFAULT_UPSAMPLING}).
     */
    MONOTONE_CUBIC
}
