package io.github.jdem846.view;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;

/**
 * The terrain of a view at any resolution, for levels of detail: parts of a full-resolution grid, box-averaged as
 * {@link io.github.jdem846.io.ReadRequest} reads them (each output cell the mean of the valid cells of a block,
 * blocks starting at the part's first cell, the last ones partial).
 */
interface TerrainSource {

    /** @return the full-resolution grid's columns */
    int width();

    /** @return the full-resolution grid's rows */
    int height();

    /**
     * Cells {@code col ..< col + w} and {@code row ..< row + h} of the full-resolution grid, box-averaged by
     * {@code factor}, with their geometry.
     *
     * @throws IOException when the grid cannot be read
     */
    Dem read(int col, int row, int w, int h, int factor) throws IOException;

    /** A grid in memory. */
    static TerrainSource of(Dem full) {
        return new TerrainSource() {
            @Override
            public int width() {
                return full.width();
            }

            @Override
            public int height() {
                return full.height();
            }

            @Override
            public Dem read(int col, int row, int w, int h, int factor) {
                int ow = (w + factor - 1) / factor;
                int oh = (h + factor - 1) / factor;
                float[] out = new float[ow * oh];
                for (int r = 0; r < oh; r++) {
                    for (int c = 0; c < ow; c++) {
                        double sum = 0;
                        int count = 0;
                        for (int rr = row + r * factor; rr < Math.min(row + h, row + (r + 1) * factor); rr++) {
                            for (int cc = col + c * factor; cc < Math.min(col + w, col + (c + 1) * factor); cc++) {
                                float value = full.get(cc, rr);
                                if (!Float.isNaN(value)) {
                                    sum += value;
                                    count++;
                                }
                            }
                        }
                        out[r * ow + c] = count > 0 ? (float) (sum / count) : Float.NaN;
                    }
                }
                GridGeometry g = full.geometry().window(col, row, w, h);
                return new Dem(out, factor > 1 ? g.decimate(factor, factor) : g);
            }
        };
    }
}
