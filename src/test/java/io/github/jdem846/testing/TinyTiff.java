package io.github.jdem846.testing;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;

/**
 * A hand-made classic little-endian TIFF for reader tests: one image directory whose fields are set one by one
 * (any TIFF type, values written inline or after the directory), followed by the pixel data. By default a
 * {@code width × height} int16 image in one uncompressed strip of zeros; any field can then be set to a broken
 * value, and the strip offset, byte count and next-directory pointer overridden.
 */
public final class TinyTiff {

    public static final int SHORT = 3;
    public static final int LONG = 4;
    public static final int SLONG = 9;
    public static final int DOUBLE = 12;
    public static final int ASCII = 2;

    /** Stands in the StripOffsets/TileOffsets values for "where the pixel data start". */
    public static final long AT_DATA = -0x7a7a7a7aL;

    private record Field(int type, long[] values, double[] doubles, byte[] ascii) {
    }

    private final Map<Integer, Field> fields = new TreeMap<>();
    private byte[] data;
    private Long nextIfd;
    private long firstIfd = 8;

    private TinyTiff(byte[] data) {
        this.data = data;
    }

    /** A {@code width × height} int16 image, one uncompressed strip of {@code width × height × 2} zero bytes. */
    public static TinyTiff int16(long width, long height) {
        TinyTiff t = new TinyTiff(new byte[(int) Math.min(1 << 16, width * height * 2)]);
        t.set(256, LONG, width).set(257, LONG, height).set(258, SHORT, 16).set(259, SHORT, 1)
                .set(262, SHORT, 1).set(273, LONG, AT_DATA).set(277, SHORT, 1).set(278, LONG, height)
                .set(279, LONG, t.data.length).set(339, SHORT, 2);
        return t;
    }

    /** Sets a field of an integer type (SHORT, LONG, SLONG, ...). */
    public TinyTiff set(int tag, int type, long... values) {
        fields.put(tag, new Field(type, values, null, null));
        return this;
    }

    /** Sets a DOUBLE field. */
    public TinyTiff doubles(int tag, double... values) {
        fields.put(tag, new Field(DOUBLE, null, values, null));
        return this;
    }

    /** Sets an ASCII field (NUL-terminated here). */
    public TinyTiff ascii(int tag, String text) {
        fields.put(tag, new Field(ASCII, null, null, (text + "\0").getBytes(StandardCharsets.ISO_8859_1)));
        return this;
    }

    public TinyTiff remove(int tag) {
        fields.remove(tag);
        return this;
    }

    /** Replaces the pixel data. */
    public TinyTiff data(byte[] pixels) {
        this.data = pixels;
        return this;
    }

    /** Georeferences the grid: ModelPixelScale (sx, sy) and a tie point of cell (0, 0) at (x, y). */
    public TinyTiff georeferenced(double x, double y, double sx, double sy) {
        return doubles(33550, sx, sy, 0).doubles(33922, 0, 0, 0, x, y, 0);
    }

    /** Sets the pointer to the next image directory (0, none, by default). */
    public TinyTiff nextIfd(long offset) {
        this.nextIfd = offset;
        return this;
    }

    /** Sets the header's pointer to the first image directory (which is still written at byte 8). */
    public TinyTiff firstIfd(long offset) {
        this.firstIfd = offset;
        return this;
    }

    /**
     * Makes the image tiled, {@code tileWidth × tileLength} (TileWidth and TileLength as LONG, or SLONG when one
     * is negative), every tile pointing at the same data: {@code tiles} offsets and byte counts.
     */
    public TinyTiff tiled(long tileWidth, long tileLength, int tiles) {
        long[] offsets = new long[tiles];
        long[] counts = new long[tiles];
        java.util.Arrays.fill(offsets, AT_DATA);
        java.util.Arrays.fill(counts, data.length);
        int type = tileWidth < 0 || tileLength < 0 ? SLONG : LONG;
        return remove(273).remove(278).remove(279).set(322, type, tileWidth).set(323, type, tileLength)
                .set(324, LONG, offsets).set(325, LONG, counts);
    }

    public byte[] bytes() {
        int n = fields.size();
        int ifdEnd = 8 + 2 + n * 12 + 4;
        int extra = 0;
        for (Field f : fields.values()) {
            int size = size(f);
            if (size > 4) {
                extra += size + (size & 1);
            }
        }
        int dataAt = ifdEnd + extra;
        ByteBuffer b = ByteBuffer.allocate(dataAt + data.length).order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt((int) firstIfd);
        b.putShort((short) n);
        int outOfLine = ifdEnd;
        for (Map.Entry<Integer, Field> e : fields.entrySet()) {
            Field f = e.getValue();
            int count = f.values != null ? f.values.length : f.doubles != null ? f.doubles.length : f.ascii.length;
            b.putShort((short) (int) e.getKey()).putShort((short) f.type).putInt(count);
            int size = size(f);
            int at;
            if (size > 4) {
                b.putInt(outOfLine);
                at = outOfLine;
                outOfLine += size + (size & 1);
            } else {
                at = b.position();
                b.putInt(0);
            }
            int save = b.position();
            b.position(at);
            if (f.values != null) {
                for (long v : f.values) {
                    long w = v == AT_DATA ? dataAt : v;
                    if (f.type == SHORT) {
                        b.putShort((short) w);
                    } else {
                        b.putInt((int) w);
                    }
                }
            } else if (f.doubles != null) {
                for (double v : f.doubles) {
                    b.putDouble(v);
                }
            } else {
                b.put(f.ascii);
            }
            b.position(save);
        }
        b.putInt((int) (nextIfd == null ? 0 : nextIfd));
        b.position(dataAt);
        b.put(data);
        return b.array();
    }

    private static int size(Field f) {
        if (f.values != null) {
            return f.values.length * (f.type == SHORT ? 2 : 4);
        }
        return f.doubles != null ? f.doubles.length * 8 : f.ascii.length;
    }

    /** Writes the file {@code name} in {@code dir}. */
    public Path write(Path dir, String name) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes());
        return p;
    }
}
