package io.github.jdem846.output;

import com.pngencoder.PngEncoder;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Encodes 8-bit RGBA ({@code TYPE_INT_ARGB}) and 8-bit gray ({@code TYPE_BYTE_GRAY}) images as PNG with
 * {@link PngEncoder}: per-row PNG filters chosen by the encoder ("predictor encoding") and deflate split into
 * segments compressed in parallel. Measured against ImageIO's PNG writer in docs/performance.md ("PNG
 * encoding"): at level 1 with predictor it writes 18–25 % smaller files than ImageIO's default, in less time.
 */
final class PngWriter {

    private PngWriter() {
    }

    static void write(BufferedImage image, Path file, int compressionLevel, boolean parallel) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16)) {
            new PngEncoder()
                    .withBufferedImage(image)
                    .withCompressionLevel(compressionLevel)
                    .withPredictorEncoding(true)
                    .withMultiThreadedCompressionEnabled(parallel)
                    .toStream(out);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }
}
