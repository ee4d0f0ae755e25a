package io.github.jdem846.output;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * Small pictures (map tiles) encoded in memory as PNG by the same deterministic writer as {@link ImageOutput}'s
 * files: the same pixels always give the same bytes.
 */
public final class PngBytes {

    private PngBytes() {
    }

    /**
     * The PNG of an ARGB picture (8-bit RGBA, non-premultiplied; alpha 0 stays transparent).
     *
     * @param argb             pixels, row-major, {@code width × height}
     * @param width pixels per row
     * @param height rows
     * @param compressionLevel deflate level 0 to 9
     * @return the file's bytes
     */
    public static byte[] rgba(int[] argb, int width, int height, int compressionLevel) {
        if (argb.length != (long) width * height) {
            throw new IllegalArgumentException(argb.length + " pixels for a " + width + "×" + height + " picture");
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(Math.max(64, argb.length));
        try {
            PngWriter.write(ImageOutput.toBufferedImage(argb, width, height), out, compressionLevel, false);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // not for memory
        }
        return out.toByteArray();
    }
}
