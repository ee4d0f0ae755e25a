package io.github.jdem846.io.source;

import io.github.jdem846.io.SampleType;
import java.nio.ByteBuffer;

/**
 * Converts runs of stored binary samples to float32. The bytes are taken out of the buffer, in its byte order, by
 * the JDK's bulk buffer copies (a memory copy, or a byte-swapping one for the other order), so float32 costs no
 * loop of ours at all and the other types one widening loop over an array: cheap on a cold JVM, where a
 * cell-by-cell {@code getShort}/{@code getInt} loop runs interpreted for much of a first read. One decoder per
 * reader (it keeps scratch arrays); not thread-safe.
 */
public final class SampleDecoder {

    /** Samples converted per bulk copy of the integer and float64 types: bounds the scratch arrays. */
    private static final int PIECE = 1 << 14;

    private byte[] bytes = new byte[0];
    private short[] shorts = new short[0];
    private int[] ints = new int[0];
    private double[] doubles = new double[0];

    /**
     * Decodes {@code count} samples of {@code type} from {@code b}'s position, in {@code b}'s byte order, into
     * {@code dst[at, at + count)}, and advances {@code b}'s position past them.
     *
     * @throws java.nio.BufferUnderflowException when {@code b} holds fewer samples
     * @throws IllegalArgumentException          for text samples
     */
    public void decode(ByteBuffer b, SampleType type, float[] dst, int at, int count) {
        if (type == SampleType.FLOAT32) {
            b.asFloatBuffer().get(dst, at, count);
            b.position(b.position() + 4 * count);
            return;
        }
        for (int done = 0; done < count; done += PIECE) {
            int n = Math.min(PIECE, count - done);
            piece(b, type, dst, at + done, n);
        }
    }

    private void piece(ByteBuffer b, SampleType type, float[] dst, int at, int n) {
        switch (type) {
            case INT8, UINT8 -> {
                byte[] s = bytes(n);
                b.get(s, 0, n);
                if (type == SampleType.INT8) {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i];
                    }
                } else {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i] & 0xFF;
                    }
                }
            }
            case INT16, UINT16 -> {
                short[] s = shorts(n);
                b.asShortBuffer().get(s, 0, n);
                b.position(b.position() + 2 * n);
                if (type == SampleType.INT16) {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i];
                    }
                } else {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i] & 0xFFFF;
                    }
                }
            }
            case INT32, UINT32 -> {
                int[] s = ints(n);
                b.asIntBuffer().get(s, 0, n);
                b.position(b.position() + 4 * n);
                if (type == SampleType.INT32) {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i];
                    }
                } else {
                    for (int i = 0; i < n; i++) {
                        dst[at + i] = s[i] & 0xFFFFFFFFL;
                    }
                }
            }
            case FLOAT64 -> {
                double[] s = doubles(n);
                b.asDoubleBuffer().get(s, 0, n);
                b.position(b.position() + 8 * n);
                for (int i = 0; i < n; i++) {
                    dst[at + i] = (float) s[i];
                }
            }
            default -> throw new IllegalArgumentException("no binary samples of type " + type);
        }
    }

    private byte[] bytes(int n) {
        if (bytes.length < n) {
            bytes = new byte[PIECE];
        }
        return bytes;
    }

    private short[] shorts(int n) {
        if (shorts.length < n) {
            shorts = new short[PIECE];
        }
        return shorts;
    }

    private int[] ints(int n) {
        if (ints.length < n) {
            ints = new int[PIECE];
        }
        return ints;
    }

    private double[] doubles(int n) {
        if (doubles.length < n) {
            doubles = new double[PIECE];
        }
        return doubles;
    }
}
