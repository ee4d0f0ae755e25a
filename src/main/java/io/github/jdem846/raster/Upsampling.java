package io.github.jdem846.raster;

/**
 * How a DEM is enlarged when a picture has more pixels than the DEM has cells (docs/scale.md, "Pictures larger than
 * the DEM"): the surface the stages then read at the picture's resolution. Beyond the grid's outer cell centres
 * each goes on linearly; next to no-data (a corner of the inner 2 × 2 missing) the cubics are bilinear over the
 * corners that are data.
 */
public enum Upsampling {

    /**
     * Bilinear between cell centres: continuous heights whose slope jumps at every cell edge, so hillshade shows
     * the cells as facets and self-shadow edges follow them.
     */
    BILINEAR,

    /**
     * Catmull-Rom bicubic (the cubic convolution with a = −0.5): it passes through the cells, keeps planes planes,
     * and its slope is continuous across cell edges, so hillshade and shadow edges are smooth. It overshoots beside
     * steep steps: between two cells at −1 m with a 50 m drop on either side it rises to +5 m, an island the
     * cells do not have.
     */
    CATMULL_ROM,

    /**
     * {@link #CATMULL_ROM} kept within the lowest and highest of the 4 × 4 cells it reads: the same surface wherever
     * it stays within them (nearly everywhere on real terrain), without its overshoot beyond them. The default
     * ({@link DemResampler#DEFAULT_UPSAMPLING}).
     */
    CLAMPED_CATMULL_ROM,

    /**
     * Monotone bicubic: cubic Hermite pieces along x, then along y, whose tangent at a cell centre is the harmonic
     * mean of the slopes on either side, or 0 at a local extremum (Fritsch and Butland's monotone cubic). It never
     * overshoots, but it flattens every ridge and valley that crosses a row or a column of cells.
     */
    MONOTONE_CUBIC
}
