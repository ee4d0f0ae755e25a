package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;

/**
 * A hillshade method as a stage of the renderer: for a rectangle of a DEM, the cosine of the angle between each
 * cell's surface normal and the light (eq. 7's dot product, in [−1, 1]; NaN for no-data cells).
 *
 * <p>Implementations are pure and thread-safe; they read neighbours outside the rectangle from the DEM (the halo),
 * so any tiling gives the same result.
 */
public interface IlluminationStage {

    /**
     * Writes the illumination of cells [{@code col0}, {@code col0 + w}) × [{@code row0}, {@code row0 + h}) into
     * {@code out}, row-major with row length {@code w}.
     *
     * @param dem the elevations
     * @param light where the light comes from, in the grid's frame
     * @param col0 first column
     * @param row0 first row
     * @param w number of columns
     * @param h number of rows
     * @param out receives {@code w × h} values, NaN for no-data
     */
    void illuminate(Dem dem, LightDirection light, int col0, int row0, int w, int h, float[] out);
}
