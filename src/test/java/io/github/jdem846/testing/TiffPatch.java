package io.github.jdem846.testing;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Patches fields of the first image directory of a classic TIFF (a real file's bytes), for tests of corrupt
 * headers: a field's value (inline, or one element of its array), the next-directory pointer, raw bytes.
 */
public final class TiffPatch {

    /** TIFF field types. */
    private static final int SHORT = 3;
    private static final int LONG = 4;
    private static final int DOUBLE = 12;

    private final byte[] bytes;
    private final ByteBuffer buffer;
    private final int ifd;

    private TiffPatch(byte[] bytes) {
        this.bytes = bytes;
        this.buffer = ByteBuffer.wrap(bytes).order(bytes[0] == 'M' ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
        if (buffer.getShort(2) != 42) {
            throw new IllegalArgumentException("not a classic TIFF");
        }
        this.ifd = buffer.getInt(4);
    }

    /**
     * The bytes of a file, to patch.
     *
     * @param tif a classic TIFF
     * @return the patcher
     * @throws IOException when the file cannot be read
     */
    public static TiffPatch of(Path tif) throws IOException {
        return new TiffPatch(Files.readAllBytes(tif));
    }

    /** The byte offset of the entry of {@code tag} in the first directory. */
    private int entry(int tag) {
        int count = buffer.getShort(ifd) & 0xFFFF;
        for (int i = 0; i < count; i++) {
            int at = ifd + 2 + 12 * i;
            if ((buffer.getShort(at) & 0xFFFF) == tag) {
                return at;
            }
        }
        throw new IllegalArgumentException("no tag " + tag + " in the first directory");
    }

    /**
     * The number of values of a field.
     *
     * @param tag the tag
     * @return its count
     */
    public long count(int tag) {
        return buffer.getInt(entry(tag) + 4) & 0xFFFFFFFFL;
    }

    /**
     * Element {@code index} of a SHORT or LONG field.
     *
     * @param tag   the tag
     * @param index the element
     * @return its value
     */
    public long get(int tag, int index) {
        int at = valueAt(tag, index);
        return type(tag) == SHORT ? buffer.getShort(at) & 0xFFFF : buffer.getInt(at) & 0xFFFFFFFFL;
    }

    /**
     * Sets a one-value field; a SHORT field becomes a LONG one when the value needs it.
     *
     * @param tag   the tag
     * @param value the new value (its low 32 bits)
     * @return this
     */
    public TiffPatch set(int tag, long value) {
        int at = entry(tag);
        if (type(tag) == SHORT && (value < 0 || value > 0xFFFF)) {
            buffer.putShort(at + 2, (short) LONG);
        }
        buffer.putInt(at + 8, 0);
        return set(tag, 0, value);
    }

    /**
     * Sets element {@code index} of a SHORT or LONG field.
     *
     * @param tag   the tag
     * @param index the element
     * @param value the new value (its low 16 or 32 bits)
     * @return this
     */
    public TiffPatch set(int tag, int index, long value) {
        int at = valueAt(tag, index);
        if (type(tag) == SHORT) {
            buffer.putShort(at, (short) value);
        } else {
            buffer.putInt(at, (int) value);
        }
        return this;
    }

    /**
     * Sets element {@code index} of a DOUBLE field (ModelPixelScale, ModelTiepoint).
     *
     * @param tag   the tag
     * @param index the element
     * @param value the new value
     * @return this
     */
    public TiffPatch setDouble(int tag, int index, double value) {
        int at = entry(tag);
        if (type(tag) != DOUBLE || index >= count(tag)) {
            throw new IllegalArgumentException("tag " + tag + " has no DOUBLE value " + index);
        }
        buffer.putDouble(buffer.getInt(at + 8) + 8 * index, value);
        return this;
    }

    /**
     * Points the first directory's next-directory offset somewhere.
     *
     * @param offset the next directory's offset (the first one's own makes a loop)
     * @return this
     */
    public TiffPatch nextDirectory(long offset) {
        int count = buffer.getShort(ifd) & 0xFFFF;
        buffer.putInt(ifd + 2 + 12 * count, (int) offset);
        return this;
    }

    /**
     * The offset of the first directory.
     *
     * @return it
     */
    public int firstDirectory() {
        return ifd;
    }

    /**
     * Overwrites bytes.
     *
     * @param offset where
     * @param length how many
     * @param value  the byte written
     * @return this
     */
    public TiffPatch fill(int offset, int length, int value) {
        java.util.Arrays.fill(bytes, offset, offset + length, (byte) value);
        return this;
    }

    /**
     * Writes the patched bytes.
     *
     * @param file where
     * @return the file
     * @throws IOException when it cannot be written
     */
    public Path write(Path file) throws IOException {
        return Files.write(file, bytes);
    }

    private int type(int tag) {
        return buffer.getShort(entry(tag) + 2) & 0xFFFF;
    }

    private int valueAt(int tag, int index) {
        int at = entry(tag);
        int size = type(tag) == SHORT ? 2 : 4;
        long count = count(tag);
        if (index >= count) {
            throw new IllegalArgumentException("tag " + tag + " has " + count + " values");
        }
        return count * size <= 4 ? at + 8 + index * size : buffer.getInt(at + 8) + index * size;
    }
}
