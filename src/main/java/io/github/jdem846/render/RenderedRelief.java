package io.github.jdem846.render;

import io.github.jdem846.raster.GridGeometry;
import java.awt.image.BufferedImage;

/**
 * A rendered picture: non-premultiplied ARGB pixels, row 0 = north, with the geometry of the grid they cover (for
 * world files and GeoTIFF tags).
 *
 * @param width    pixels across
 * @param height   pixels down
 * @param argb     row-major 0xAARRGGBB; no-data is 0 (fully transparent). Owned by this record; do not modify.
 * @param geometry the grid the pixels cover
 */
public record RenderedRelief(int width, int height, int[] argb, GridGeometry geometry) {

    /** {@return A new {@code TYPE_INT_ARGB} image holding a copy of the pixels} */
    public BufferedImage toBufferedImage() {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_ARGB);
        img.setRGB(0, 0, width, height, argb, 0, width);
        return img;
    }
}
