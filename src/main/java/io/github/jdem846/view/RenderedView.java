package io.github.jdem846.view;

import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

/**
 * A perspective view: opaque ARGB pixels, row 0 at the top.
 *
 * @param width  pixels across
 * @param height pixels down
 * @param argb   row-major 0xAARRGGBB. Owned by this record; do not modify.
 */
public record RenderedView(int width, int height, int[] argb) {

    /** {@return a {@code TYPE_INT_ARGB} image backed by the pixels (no copy)} */
    public BufferedImage toBufferedImage() {
        return ImageOutput.toBufferedImage(argb, width, height);
    }

    /**
     * Writes the picture as PNG (or an RGBA TIFF without georeferencing), all or nothing.
     *
     * @param file    the image file; its extension chooses the format
     * @param options how to write it
     * @return the files written
     * @throws IOException naming the file when it cannot be written
     */
    public WriteResult write(Path file, WriteOptions options) throws IOException {
        return ImageOutput.writeRgba(file, argb, width, height, null, options);
    }
}
