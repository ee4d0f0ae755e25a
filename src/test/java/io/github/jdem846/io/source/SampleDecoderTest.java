package io.github.jdem846.io.source;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.github.jdem846.io.SampleType;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The bulk conversion gives, bit for bit, what reading each sample with the buffer's own getters gives, in both
 * byte orders, from heap and direct buffers, at any position, across its scratch pieces, and leaves the buffer
 * right after the samples.
 */
class SampleDecoderTest {

    private static final SampleType[] BINARY = {SampleType.INT8, SampleType.UINT8, SampleType.INT16,
        SampleType.UINT16, SampleType.INT32, SampleType.UINT32, SampleType.FLOAT32, SampleType.FLOAT64};

    @Test
    void everyTypeAndOrderEqualsTheGetters() {
        Random random = new Random(846);
        SampleDecoder decoder = new SampleDecoder();
        for (SampleType type : BINARY) {
            for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
                for (boolean direct : new boolean[] {false, true}) {
                    // odd counts, one across several scratch pieces (2¹⁴ samples each)
                    for (int count : new int[] {0, 1, 7, 16_385, 40_001}) {
                        int skip = 3;
                        byte[] bytes = new byte[(skip + count) * type.bytes() + 5];
                        random.nextBytes(bytes);
                        ByteBuffer b = direct ? ByteBuffer.allocateDirect(bytes.length) : ByteBuffer.allocate(
                                bytes.length);
                        b.put(bytes).clear().order(order).position(skip * type.bytes());
                        float[] expected = bySampleGetters(b.duplicate().order(order), type, count);
                        float[] got = new float[count + 4];
                        decoder.decode(b, type, got, 2, count);
                        String what = type + " " + order + (direct ? " direct " : " heap ") + count;
                        assertEquals((skip + count) * type.bytes(), b.position(), what + ": position after");
                        float[] inPlace = java.util.Arrays.copyOfRange(got, 2, 2 + count);
                        assertBitsEqual(expected, inPlace, what);
                        assertEquals(0f, got[0], what + ": nothing written before");
                        assertEquals(0f, got[count + 2], what + ": nothing written after");
                    }
                }
            }
        }
    }

    @Test
    void tooFewBytesOrTextAreRefused() {
        SampleDecoder decoder = new SampleDecoder();
        ByteBuffer b = ByteBuffer.allocate(10);
        assertThrows(BufferUnderflowException.class, () -> decoder.decode(b, SampleType.FLOAT32, new float[3], 0, 3));
        assertThrows(BufferUnderflowException.class, () -> decoder.decode(b, SampleType.INT16, new float[6], 0, 6));
        assertThrows(IllegalArgumentException.class, () -> decoder.decode(b, SampleType.TEXT, new float[1], 0, 1));
    }

    private static float[] bySampleGetters(ByteBuffer b, SampleType type, int count) {
        float[] out = new float[count];
        for (int i = 0; i < count; i++) {
            out[i] = switch (type) {
                case INT8 -> b.get();
                case UINT8 -> b.get() & 0xFF;
                case INT16 -> b.getShort();
                case UINT16 -> b.getShort() & 0xFFFF;
                case INT32 -> b.getInt();
                case UINT32 -> b.getInt() & 0xFFFFFFFFL;
                case FLOAT32 -> b.getFloat();
                case FLOAT64 -> (float) b.getDouble();
                default -> throw new IllegalArgumentException(type.toString());
            };
        }
        return out;
    }

    private static void assertBitsEqual(float[] expected, float[] got, String what) {
        int[] e = new int[expected.length];
        int[] g = new int[got.length];
        for (int i = 0; i < e.length; i++) {
            e[i] = Float.floatToRawIntBits(expected[i]);
            g[i] = Float.floatToRawIntBits(got[i]);
        }
        assertArrayEquals(e, g, what);
    }
}
