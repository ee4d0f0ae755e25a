package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.PngFilterReference;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The word-wise PNG filter chooses the same filter as the byte-wise definition ({@link PngFilterReference}) and
 * writes the same bytes, for every row length (the head without a left pixel, whole words, the tail), 1, 3 and 4
 * bytes per pixel, and rows where filters tie; its Paeth predictor is the spec's for every input.
 */
class PngRowFilterTest {

    @Test
    void paethOfFourLanesIsTheSpecsForAllInputs() {
        for (int a = 0; a < 256; a++) {
            for (int b = 0; b < 256; b++) {
                long la = 0;
                long lb = 0;
                long ld = 0;
                for (int d = 0; d < 256; d++) {
                    int lane = d & 3;
                    la |= (long) a << 16 * lane;
                    lb |= (long) b << 16 * lane;
                    ld |= (long) d << 16 * lane;
                    if (lane == 3) {
                        long p = PngRowFilter.paeth4(la, lb, ld);
                        for (int k = 0; k < 4; k++) {
                            int dk = d - 3 + k;
                            int expected = PngFilterReference.paeth(a, b, dk);
                            if ((p >>> 16 * k & 0xFFFF) != expected) {
                                assertEquals(expected, p >>> 16 * k & 0xFFFF, "paeth(" + a + ", " + b + ", " + dk
                                        + ")");
                            }
                            assertEquals(expected, PngRowFilter.paeth(a, b, dk));
                        }
                        la = 0;
                        lb = 0;
                        ld = 0;
                    }
                }
            }
        }
    }

    @Test
    void byteWiseDifferenceAndAverageForAllPairs() {
        Random random = new Random(5);
        for (int x = 0; x < 256; x++) {
            for (int y = 0; y < 256; y++) {
                int lane = random.nextInt(8);
                long noiseX = random.nextLong() & ~(0xFFL << 8 * lane);
                long noiseY = random.nextLong() & ~(0xFFL << 8 * lane);
                long wx = noiseX | (long) x << 8 * lane;
                long wy = noiseY | (long) y << 8 * lane;
                assertEquals((x - y) & 0xFF, PngRowFilter.minus(wx, wy) >>> 8 * lane & 0xFF, x + " − " + y);
                assertEquals((x + y) >> 1, PngRowFilter.average(wx, wy) >>> 8 * lane & 0xFF, x + " avg " + y);
            }
        }
    }

    @ParameterizedTest(name = "{0} bytes per pixel")
    @ValueSource(ints = {1, 3, 4})
    void filtersRowsOfEveryLengthAsTheDefinition(int bpp) {
        Random random = new Random(bpp);
        int[] chosen = new int[5];
        int ties = 0;
        for (int width = 1; width <= 1100; width += width < 40 ? 1 : 97) {
            int sampleBytes = width * bpp;
            PngRowFilter filter = new PngRowFilter(sampleBytes, bpp);
            PngFilterReference reference = new PngFilterReference(sampleBytes, bpp);
            byte[] above = new byte[1 + sampleBytes];
            int rows = Kind.values().length * (width < 40 ? 12 : 3);      // short rows tie more often
            for (int kind = 0; kind < rows; kind++) {
                byte[] row = Kind.values()[kind % Kind.values().length].row(above, bpp, random);
                byte[] expected = new byte[3 + sampleBytes];
                byte[] actual = new byte[3 + sampleBytes];
                int type = reference.filterRow(row, above, expected, 2);
                assertEquals(type, filter.filterRow(row, above, actual, 2), "type, width " + width);
                assertArrayEquals(expected, actual, "filtered row, width " + width + ", type " + type);
                if (sampleBytes >= 16) {
                    chosen[type]++;
                }
                long[] sums = reference.sums(row, above);
                long min = Arrays.stream(sums).min().orElseThrow();
                ties += Arrays.stream(sums).filter(s -> s == min).count() > 1 ? 1 : 0;
                above = row;
            }
        }
        for (int type = 0; type < 5; type++) {
            assertTrue(chosen[type] > 0, "filter " + type + " chosen for some row of whole words");
        }
        assertTrue(ties > 10, ties + " rows where the smallest sum is shared");
    }

    @Test
    void rowsWithoutVariationTieAndTakeTheFirstFilter() {
        for (int bpp : new int[] {1, 3, 4}) {
            for (int width : new int[] {1, 2, 3, 7, 64, 333}) {
                int sampleBytes = width * bpp;
                byte[] zeros = new byte[1 + sampleBytes];
                byte[] out = new byte[1 + sampleBytes];
                // all zeros: none sums to 0, the others to their type number
                assertEquals(0, new PngRowFilter(sampleBytes, bpp).filterRow(zeros, zeros, out, 0));
                byte[] ones = new byte[1 + sampleBytes];
                Arrays.fill(ones, 1, ones.length, (byte) 1);
                // ones under ones: none sums to the row's length, sub to 1 + bpp (the first pixel), up to 2;
                // 2 bytes of gray tie all three at 2 and take none, longer gray rows tie sub and up and take sub
                int expected = sampleBytes <= 2 ? 0 : bpp == 1 ? 1 : 2;
                assertEquals(expected, new PngRowFilter(sampleBytes, bpp).filterRow(ones, ones, out, 0),
                        width + " pixels of " + bpp);
                assertEquals(expected, new PngFilterReference(sampleBytes, bpp).filterRow(ones, ones, out, 0));
            }
        }
    }

    /** Kinds of rows under the previous one, so that every filter wins some and some tie. */
    private enum Kind {
        NOISE, SMALL_NOISE, TWO_VALUES, RAMP, ABOVE_PLUS_NOISE, SMOOTH, CONSTANT, FLAT_LEFT_OF_ABOVE;

        byte[] row(byte[] above, int bpp, Random random) {
            byte[] row = new byte[above.length];
            for (int i = 1; i < row.length; i++) {
                int left = i > bpp ? row[i - bpp] & 0xFF : 0;
                row[i] = (byte) switch (this) {
                    case NOISE -> random.nextInt(256);
                    case SMALL_NOISE -> random.nextInt(3);
                    case TWO_VALUES -> random.nextBoolean() ? 0 : 255;
                    case RAMP -> i * 3;
                    case ABOVE_PLUS_NOISE -> above[i] + random.nextInt(3) - 1;
                    case SMOOTH -> ((above[i] & 0xFF) + left) / 2 + random.nextInt(5) - 2;
                    case CONSTANT -> 200;
                    case FLAT_LEFT_OF_ABOVE -> (above[i] & 0xFF) + left - (i > bpp ? above[i - bpp] & 0xFF : 0);
                };
            }
            return row;
        }
    }
}
