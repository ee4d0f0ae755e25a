package io.github.jdem846.render;

import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;

/**
 * Colours laid over the tint cell by cell, before the light is applied: a draped image ({@link
 * io.github.jdem846.drape.Drape}). Each cell's colour must depend only on where the cell lies ({@link
 * GridGeometry#centerX}, {@link GridGeometry#centerY}), so that a window or a tile of a picture gets the same colours
 * as the whole picture. Implementations are immutable and thread-safe.
 */
public interface ColorLayer {

    /**
     * The colours of the cells of {@code area}: non-premultiplied 0xAARRGGBB, row-major, {@code area.width()}
     * across; alpha 0 where the layer has nothing (the tint shows), 255 where it hides the tint.
     *
     * @param grid the grid the cells belong to (its CRS and cell centres)
     * @param area the cells wanted, inside {@code grid}
     * @return one colour per cell of {@code area}
     * @throws IOException when the layer's source cannot be read; the message names the file
     */
    int[] argb(GridGeometry grid, CellWindow area) throws IOException;

    /**
     * Checks, before any cell is drawn, that the layer can be placed on a picture: it covers some of it and its
     * coordinates can be transformed into the picture's CRS. The default accepts every picture.
     *
     * @param picture the grid of the whole picture
     * @throws IllegalArgumentException when the layer cannot be placed there; the message names its source
     */
    default void requireCovers(GridGeometry picture) {
    }

    /**
     * The layer for the cells of {@code picture} when their grids are windows of a larger root grid ({@link
     * GridGeometry#placement()}), as map tiles are windows of their zoom's whole world: whatever the layer decides
     * once for a whole picture (a drape's sampling steps) is decided on {@code picture} instead of the root. Each
     * cell's colour still depends only on where it lies. The default returns this layer.
     *
     * @param picture the part of the root grid that is drawn (its cells' positions as in the root grid)
     * @return the layer to draw that picture with
     */
    default ColorLayer forPicture(GridGeometry picture) {
        return this;
    }

    /**
     * {@code over} composited over {@code under} (Porter–Duff source over, non-premultiplied ARGB, each channel
     * rounded to the nearest 8-bit value).
     *
     * @param over  the colour on top
     * @param under the colour below
     * @return the composite
     */
    static int over(int over, int under) {
        int a = over >>> 24;
        if (a == 255) {
            return over;
        }
        if (a == 0) {
            return under;
        }
        int b = under >>> 24;
        // in units of 255 × 255: outA = a·255 + b·(255 − a)
        int outA255 = a * 255 + b * (255 - a);
        if (outA255 == 0) {
            return 0;
        }
        int outA = (outA255 + 127) / 255;
        int rgb = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            long num = (long) ((over >> shift) & 0xFF) * a * 255 + (long) ((under >> shift) & 0xFF) * b * (255 - a);
            int c = (int) ((2 * num + outA255) / (2L * outA255));
            rgb |= Math.min(255, c) << shift;
        }
        return outA << 24 | rgb;
    }
}
