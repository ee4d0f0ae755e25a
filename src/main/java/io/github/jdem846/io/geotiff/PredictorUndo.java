package io.github.jdem846.io.geotiff;

import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.SampleDecoder;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Undoes a TIFF predictor on one row of one strip or tile, decompressed but otherwise raw, and converts samples of
 * it to float32 (one sample per pixel); predictor 1 (none) only converts:
 * <ul>
 *   <li>predictor 2 (horizontal differencing, TIFF 6.0 §14): each integer sample is stored as its difference to the
 *       one before, modulo 2^bits, in the file's byte order;</li>
 *   <li>predictor 3 (floating point, Adobe TIFF Technical Note 3, as libtiff and GDAL write it): the row's samples
 *       are split into byte planes, most significant byte first whatever the file's byte order, and each byte
 *       stored as its difference to the byte before.</li>
 * </ul>
 * The row is undone in place. {@code TiffReferenceDecodeTest} compares the result bit for bit with TwelveMonkeys'
 * own decoding of every predictor file of testdata.
 */
final class PredictorUndo {

    private PredictorUndo() {
    }

    /**
     * Undoes the predictor on the row of {@code samples} samples at {@code raw[off…]} (for predictor 2 only as far
     * as it is needed), then writes its samples {@code [from, from + n)} as floats to {@code dst[dstOff…]};
     * without a predictor, {@code decoder} converts them in bulk.
     */
    static void row(byte[] raw, int off, int samples, int predictor, SampleType type, ByteOrder order, int from,
                    int n, float[] dst, int dstOff, SampleDecoder decoder) {
        int bytes = type.bytes();
        if (predictor == 1) {
            decoder.decode(ByteBuffer.wrap(raw, off + from * bytes, n * bytes).order(order), type, dst, dstOff, n);
            return;
        }
        if (predictor == 3) {
            int length = samples * bytes;
            for (int i = off + 1; i < off + length; i++) {
                raw[i] += raw[i - 1];
            }
            for (int k = 0; k < n; k++) {
                int at = off + from + k;
                if (bytes == 4) {
                    int bits = (raw[at] & 0xFF) << 24 | (raw[at + samples] & 0xFF) << 16
                            | (raw[at + 2 * samples] & 0xFF) << 8 | (raw[at + 3 * samples] & 0xFF);
                    dst[dstOff + k] = Float.intBitsToFloat(bits);
                } else {
                    long bits = 0;
                    for (int p = 0; p < 8; p++) {
                        bits = bits << 8 | (raw[at + p * samples] & 0xFF);
                    }
                    dst[dstOff + k] = (float) Double.longBitsToDouble(bits);
                }
            }
            return;
        }
        boolean little = order == ByteOrder.LITTLE_ENDIAN;
        switch (bytes) {
            case 1 -> {
                for (int i = off + 1; i < off + from + n; i++) {
                    raw[i] += raw[i - 1];
                }
                for (int k = 0; k < n; k++) {
                    byte v = raw[off + from + k];
                    dst[dstOff + k] = type == SampleType.INT8 ? v : v & 0xFF;
                }
            }
            case 2 -> {
                int previous = 0;
                for (int i = 0; i < from + n; i++) {
                    int at = off + 2 * i;
                    int v = (little ? (raw[at] & 0xFF) | raw[at + 1] << 8 : raw[at] << 8 | (raw[at + 1] & 0xFF))
                            + previous;
                    previous = v;
                    if (i >= from && i < from + n) {
                        dst[dstOff + i - from] = type == SampleType.INT16 ? (short) v : v & 0xFFFF;
                    }
                }
            }
            default -> {
                int previous = 0;
                for (int i = 0; i < from + n; i++) {
                    int v = int32(raw, off + 4 * i, little) + previous;
                    previous = v;
                    if (i >= from && i < from + n) {
                        dst[dstOff + i - from] = type == SampleType.UINT32 ? v & 0xFFFFFFFFL : v;
                    }
                }
            }
        }
    }

    private static int int32(byte[] raw, int at, boolean little) {
        return little
                ? (raw[at] & 0xFF) | (raw[at + 1] & 0xFF) << 8 | (raw[at + 2] & 0xFF) << 16 | raw[at + 3] << 24
                : raw[at] << 24 | (raw[at + 1] & 0xFF) << 16 | (raw[at + 2] & 0xFF) << 8 | (raw[at + 3] & 0xFF);
    }
}
