package io.github.jdem846.testing;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.zip.Deflater;

/**
 * A plain (not georeferenced) int16 TIFF of {@code n × n} zeros as ONE Deflate strip: a few kilobytes on disk that
 * decode to {@code 2 n²} bytes, the shape of file whose every read must decode the whole strip.
 */
public final class SingleStripTiff {

    private SingleStripTiff() {
    }

    /** Writes the file and returns it. */
    public static Path write(Path file, int n) throws IOException {
        byte[] strip = deflatedZeros(2L * n * n);
        return TinyTiff.int16(n, n).data(strip).set(259, TinyTiff.SHORT, 8)
                .set(279, TinyTiff.LONG, strip.length).write(file.getParent(), file.getFileName().toString());
    }

    private static byte[] deflatedZeros(long count) {
        Deflater deflater = new Deflater(1);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] zeros = new byte[1 << 16];
        byte[] buf = new byte[1 << 16];
        for (long left = count; left > 0; left -= zeros.length) {
            deflater.setInput(zeros, 0, (int) Math.min(zeros.length, left));
            while (!deflater.needsInput()) {
                out.write(buf, 0, deflater.deflate(buf));
            }
        }
        deflater.finish();
        while (!deflater.finished()) {
            out.write(buf, 0, deflater.deflate(buf));
        }
        deflater.end();
        return out.toByteArray();
    }
}
