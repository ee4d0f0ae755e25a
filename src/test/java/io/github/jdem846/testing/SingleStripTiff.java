package io.github.jdem846.testing;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.Deflater;

/**
 * Writes a plain (not georeferenced) int16 TIFF of {@code n × n} zeros as ONE Deflate strip: a few kilobytes on disk
 * that decode to {@code 2 n²} bytes, the shape of file whose every read must decode the whole strip.
 */
public final class SingleStripTiff {

    private SingleStripTiff() {
    }

    /** Writes the file and returns it. */
    public static Path write(Path file, int n) throws IOException {
        Deflater deflater = new Deflater(1);
        ByteArrayOutputStream strip = new ByteArrayOutputStream();
        byte[] row = new byte[2 * n];
        byte[] buf = new byte[1 << 16];
        for (int y = 0; y < n; y++) {
            deflater.setInput(row);
            while (!deflater.needsInput()) {
                strip.write(buf, 0, deflater.deflate(buf));
            }
        }
        deflater.finish();
        while (!deflater.finished()) {
            strip.write(buf, 0, deflater.deflate(buf));
        }
        deflater.end();
        byte[] data = strip.toByteArray();
        int[][] entries = {{256, 4, n}, {257, 4, n}, {258, 3, 16}, {259, 3, 8}, {262, 3, 1}, {273, 4, 8},
            {277, 3, 1}, {278, 4, n}, {279, 4, data.length}, {339, 3, 2}};
        ByteBuffer ifd = ByteBuffer.allocate(2 + 12 * entries.length + 4).order(ByteOrder.LITTLE_ENDIAN);
        ifd.putShort((short) entries.length);
        for (int[] e : entries) {
            ifd.putShort((short) e[0]).putShort((short) e[1]).putInt(1);
            if (e[1] == 3) {
                ifd.putShort((short) e[2]).putShort((short) 0);
            } else {
                ifd.putInt(e[2]);
            }
        }
        ifd.putInt(0);
        ByteBuffer head = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN);
        head.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt(8 + data.length);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(head.array());
        out.write(data);
        out.write(ifd.array());
        return Files.write(file, out.toByteArray());
    }
}
