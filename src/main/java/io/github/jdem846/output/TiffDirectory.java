package io.github.jdem846.output;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * One TIFF image file directory, little-endian: its fields by tag, laid out as a classic TIFF (TIFF 6.0: 12-byte
 * entries, 4-byte offsets) or a BigTIFF (20-byte entries, 8-byte counts and offsets) directory, entries ascending
 * by tag, with the values that do not fit in an entry right after it, each on a word boundary. Also the file
 * headers of both.
 */
final class TiffDirectory {

    static final short ASCII = 2;
    static final short SHORT = 3;
    static final short LONG = 4;
    static final short DOUBLE = 12;
    static final short LONG8 = 16;

    /** Bytes of a classic header ("II", 42, first IFD offset) and of a BigTIFF one ("II", 43, 8, 0, offset). */
    static final int CLASSIC_HEADER_BYTES = 8;
    static final int BIG_HEADER_BYTES = 16;

    /** The largest offset a classic TIFF can hold. */
    static final long CLASSIC_LIMIT = 0xFFFF_FFFFL;

    private final Map<Integer, Field> fields = new TreeMap<>();

    /** Sets {@code tag} to {@code field}, replacing an earlier value. */
    TiffDirectory put(int tag, Field field) {
        fields.put(tag, field);
        return this;
    }

    /** @return the bytes of the directory and its out-of-line values */
    long size(boolean big) {
        long size = entriesBytes(big);
        for (Field field : fields.values()) {
            if (field.bytes().length > inlineBytes(big)) {
                size += align(field.bytes().length);
            }
        }
        return size;
    }

    /**
     * The directory as written at {@code offset} (even), its out-of-line values after it.
     *
     * @param next the offset of the next directory, 0 for none
     */
    ByteBuffer layOut(long offset, long next, boolean big) {
        long size = size(big);
        ByteBuffer buf = ByteBuffer.allocate(Math.toIntExact(size)).order(ByteOrder.LITTLE_ENDIAN);
        int inline = inlineBytes(big);
        long valueOffset = offset + entriesBytes(big);
        List<byte[]> extras = new ArrayList<>();
        if (big) {
            buf.putLong(fields.size());
        } else {
            buf.putShort((short) fields.size());
        }
        for (Map.Entry<Integer, Field> e : fields.entrySet()) {
            Field field = e.getValue();
            buf.putShort((short) (int) e.getKey()).putShort(field.type());
            if (big) {
                buf.putLong(field.count());
            } else {
                buf.putInt((int) field.count());
            }
            if (field.bytes().length <= inline) {
                byte[] value = new byte[inline];
                System.arraycopy(field.bytes(), 0, value, 0, field.bytes().length);
                buf.put(value);
            } else {
                if (big) {
                    buf.putLong(valueOffset);
                } else {
                    buf.putInt((int) valueOffset);
                }
                valueOffset += align(field.bytes().length);
                extras.add(field.bytes());
            }
        }
        if (big) {
            buf.putLong(next);
        } else {
            buf.putInt((int) next);
        }
        for (byte[] extra : extras) {
            buf.put(extra);
            if (extra.length % 2 != 0) {
                buf.put((byte) 0);
            }
        }
        return buf.flip();
    }

    /** The file header pointing at the first directory. */
    static ByteBuffer header(boolean big, long firstIfd) {
        ByteBuffer b = ByteBuffer.allocate(big ? BIG_HEADER_BYTES : CLASSIC_HEADER_BYTES)
                .order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) 'I').put((byte) 'I');
        if (big) {
            b.putShort((short) 43).putShort((short) 8).putShort((short) 0).putLong(firstIfd);
        } else {
            b.putShort((short) 42).putInt((int) firstIfd);
        }
        return b.flip();
    }

    static long align(long offset) {
        return offset + (offset & 1);
    }

    private long entriesBytes(boolean big) {
        return big ? 8 + 20L * fields.size() + 8 : 2 + 12L * fields.size() + 4;
    }

    private static int inlineBytes(boolean big) {
        return big ? 8 : 4;
    }

    /** One entry's type, count and little-endian value bytes. */
    record Field(short type, long count, byte[] bytes) {

        static Field shorts(int... values) {
            ByteBuffer b = ByteBuffer.allocate(2 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (int v : values) {
                b.putShort((short) v);
            }
            return new Field(SHORT, values.length, b.array());
        }

        static Field longs(long... values) {
            ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (long v : values) {
                b.putInt((int) v);
            }
            return new Field(LONG, values.length, b.array());
        }

        /** File offsets or byte counts: LONG in a classic TIFF, LONG8 in a BigTIFF. */
        static Field offsets(long[] values, boolean big) {
            if (!big) {
                return longs(values);
            }
            ByteBuffer b = ByteBuffer.allocate(8 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (long v : values) {
                b.putLong(v);
            }
            return new Field(LONG8, values.length, b.array());
        }

        static Field doubles(double... values) {
            ByteBuffer b = ByteBuffer.allocate(8 * values.length).order(ByteOrder.LITTLE_ENDIAN);
            for (double v : values) {
                b.putDouble(v);
            }
            return new Field(DOUBLE, values.length, b.array());
        }

        static Field ascii(String text) {
            byte[] s = (text + '\0').getBytes(StandardCharsets.US_ASCII);
            return new Field(ASCII, s.length, s);
        }
    }
}
