package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import java.io.ByteArrayOutputStream;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.PriorityQueue;
import java.util.Random;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;
import org.junit.jupiter.api.Test;

/**
 * Huffman-only deflate data ({@link HuffmanBlocks}) inflates, with zlib's {@link Inflater}, to the bytes given: on
 * a real hillshade, on data that forces codes past 15 bits, on data no code compresses, and at the edges of blocks;
 * segments ending in a sync flush concatenate into one stream; and it is about as small as zlib's own
 * {@link Deflater#HUFFMAN_ONLY}. The code lengths ({@link HuffmanLengths}) are complete, within their limit, and
 * optimal where the limit does not bind.
 */
class HuffmanBlocksTest {

    @Test
    void aRealHillshadeInflatesBackAndIsNoLargerThanZlibsHuffmanOnly() throws Exception {
        byte[] gray = leftDifferences(realHillshade());
        byte[] deflated = deflate(gray, true);
        assertArrayEquals(gray, inflate(deflated, gray.length));
        int zlib = zlibHuffmanOnly(gray);
        assertTrue(deflated.length <= zlib * 1.005, deflated.length + " bytes against zlib's " + zlib);
        assertTrue(deflated.length < gray.length * 0.75, "compressed: " + deflated.length + " of " + gray.length);
    }

    @Test
    void segmentsEndingInASyncFlushMakeOneStream() throws Exception {
        byte[] gray = realHillshade();
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        int[] cuts = {0, 1, 7, HuffmanBlocks.BLOCK_BYTES, HuffmanBlocks.BLOCK_BYTES + 3, 200_000, gray.length};
        for (int k = 0; k + 1 < cuts.length; k++) {
            int n = cuts[k + 1] - cuts[k];
            byte[] target = new byte[HuffmanBlocks.bound(n)];
            int length = new HuffmanBlocks().deflate(gray, cuts[k], n, k + 2 == cuts.length, target);
            stream.write(target, 0, length);
        }
        assertArrayEquals(gray, inflate(stream.toByteArray(), gray.length));
    }

    @Test
    void countingFirstGivesTheHistogramAndTheSameBytes() throws Exception {
        byte[] gray = leftDifferences(realHillshade());
        int from = 1000;
        int n = 3 * HuffmanBlocks.BLOCK_BYTES + 77;
        int[] histogram = new int[256];
        for (int i = from; i < from + n; i++) {
            histogram[gray[i] & 0xFF]++;
        }
        HuffmanBlocks coder = new HuffmanBlocks();
        byte[] alone = new byte[HuffmanBlocks.bound(n)];
        int aloneLength = coder.deflate(gray, from, n, true, alone);
        assertArrayEquals(histogram, coder.count(gray, from, n));
        byte[] counted = new byte[HuffmanBlocks.bound(n)];
        assertEquals(aloneLength, coder.deflate(gray, from, n, true, counted));
        assertArrayEquals(Arrays.copyOf(alone, aloneLength), Arrays.copyOf(counted, aloneLength));
        coder.count(gray, 0, 10);                        // counts of another range are not used
        assertEquals(aloneLength, coder.deflate(gray, from, n, true, counted));
        assertArrayEquals(Arrays.copyOf(alone, aloneLength), Arrays.copyOf(counted, aloneLength));
        assertArrayEquals(Arrays.copyOfRange(gray, from, from + n), inflate(Arrays.copyOf(counted, aloneLength), n));
    }

    @Test
    void blockEdgesAndTinyInputs() throws Exception {
        Random random = new Random(846);
        HuffmanBlocks coder = new HuffmanBlocks();  // one coder for all: nothing of one input stays for the next
        int b = HuffmanBlocks.BLOCK_BYTES;
        for (int n : new int[] {0, 1, 2, 3, 100, b - 1, b, b + 1, 2 * b, 2 * b + 17}) {
            byte[] data = new byte[n];
            for (int i = 0; i < n; i++) {
                data[i] = (byte) (128 + random.nextGaussian() * 6);
            }
            byte[] target = new byte[HuffmanBlocks.bound(n)];
            int length = coder.deflate(data, 0, n, true, target);
            assertArrayEquals(data, inflate(Arrays.copyOf(target, length), n), n + " bytes");
        }
    }

    @Test
    void oneRepeatedByteAndTwoValues() throws Exception {
        byte[] same = new byte[100_000];
        Arrays.fill(same, (byte) 1);
        byte[] deflated = deflate(same, true);
        assertArrayEquals(same, inflate(deflated, same.length));
        assertTrue(deflated.length < same.length / 7, "a bit per byte: " + deflated.length);
        byte[] two = new byte[100_000];
        for (int i = 0; i < two.length; i += 3) {
            two[i] = (byte) 255;
        }
        assertArrayEquals(two, inflate(deflate(two, true), two.length));
    }

    @Test
    void dataNoCodeCompressesIsStoredWithinTheBound() throws Exception {
        byte[] noise = new byte[3 * HuffmanBlocks.BLOCK_BYTES + 5];
        new Random(1).nextBytes(noise);
        byte[] deflated = deflate(noise, true);
        assertArrayEquals(noise, inflate(deflated, noise.length));
        assertTrue(deflated.length <= HuffmanBlocks.bound(noise.length), deflated.length + " bytes");
        assertTrue(deflated.length <= noise.length + 5 * 4 + 1, "stored: " + deflated.length);
    }

    @Test
    void skewedCountsAreCodedInAtMost15Bits() throws Exception {
        // Fibonacci counts make an optimal code over 15 levels deep
        byte[] data = new byte[60_000];
        int p = 0;
        long a = 1;
        long b = 2;                                      // with end-of-block's 1: 1, 1, 2, 3, 5, ...
        for (int symbol = 0; symbol < 30 && p < data.length; symbol++) {
            for (int k = 0; k < a && p < data.length; k++) {
                data[p++] = (byte) symbol;
            }
            long c = a + b;
            a = b;
            b = c;
        }
        assertEquals(data.length, p);
        assertArrayEquals(data, inflate(deflate(data, true), data.length));
        int[] histogram = new int[257];
        for (byte v : data) {
            histogram[v & 0xFF]++;
        }
        histogram[256] = 1;
        int[] lengths = new int[257];
        new HuffmanLengths(257).lengths(histogram, 15, lengths);
        assertTrue(Arrays.stream(lengths).max().orElseThrow() <= 15);
        assertEquals(1.0, kraft(lengths), 0.0, "complete");
        assertTrue(optimalDepth(histogram) > 15, "the limit binds");
    }

    @Test
    void lengthsAreOptimalAndCompleteWhereTheLimitDoesNotBind() {
        Random random = new Random(19);
        HuffmanLengths huffman = new HuffmanLengths(257);
        for (int round = 0; round < 200; round++) {
            int[] counts = new int[257];
            int symbols = 2 + random.nextInt(256);
            for (int s = 0; s < symbols; s++) {
                counts[random.nextInt(257)] = 1 + random.nextInt(round % 2 == 0 ? 10 : 5000);
            }
            int[] lengths = new int[257];
            huffman.lengths(counts, 15, lengths);
            for (int s = 0; s < 257; s++) {
                assertEquals(counts[s] == 0, lengths[s] == 0, "symbol " + s);
            }
            if (Arrays.stream(counts).filter(c -> c > 0).count() >= 2) {
                assertEquals(1.0, kraft(lengths), 0.0, "complete");
            }
            if (optimalDepth(counts) <= 15) {
                assertEquals(huffmanCost(counts), cost(counts, lengths), "round " + round);
            }
        }
        int[] lone = new int[19];
        lone[7] = 40;
        int[] lengths = new int[19];
        new HuffmanLengths(19).lengths(lone, 7, lengths);
        assertEquals(1, lengths[7]);
        assertEquals(0, Arrays.stream(lengths).sum() - 1);
    }

    private static byte[] realHillshade() throws Exception {
        return new Renderer(new RenderSettings(2, 256)).hillshadeGray(
                DemReader.read(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif")), HillshadeMethod.HORN,
                HillshadeOptions.DEFAULTS, LightField.uniform(new LightDirection(315, 45)), RenderProgress.NONE);
    }

    /** PNG's Sub filter on rows of Big Tujunga's width: what a hillshade's bytes look like to the coder. */
    private static byte[] leftDifferences(byte[] gray) {
        int width = 1197;
        byte[] out = new byte[gray.length];
        for (int i = 0; i < gray.length; i++) {
            out[i] = (byte) (gray[i] - (i % width == 0 ? 0 : gray[i - 1]));
        }
        return out;
    }

    private static byte[] deflate(byte[] data, boolean last) {
        byte[] target = new byte[HuffmanBlocks.bound(data.length)];
        int length = new HuffmanBlocks().deflate(data, 0, data.length, last, target);
        return Arrays.copyOf(target, length);
    }

    private static byte[] inflate(byte[] deflated, int expected) throws DataFormatException {
        Inflater inflater = new Inflater(true);
        inflater.setInput(deflated);
        byte[] out = new byte[expected + 1];
        int n = 0;
        while (!inflater.finished() && n < out.length) {
            int k = inflater.inflate(out, n, out.length - n);
            if (k == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                break;
            }
            n += k;
        }
        assertTrue(inflater.finished(), "the stream ends with a final block");
        assertEquals(0, inflater.getRemaining(), "nothing after the final block");
        inflater.end();
        return Arrays.copyOf(out, n);
    }

    private static int zlibHuffmanOnly(byte[] data) {
        Deflater deflater = new Deflater(1, true);
        deflater.setStrategy(Deflater.HUFFMAN_ONLY);
        deflater.setInput(data);
        deflater.finish();
        byte[] buffer = new byte[data.length + 1024];
        int n = 0;
        while (!deflater.finished()) {
            n += deflater.deflate(buffer, n, buffer.length - n);
        }
        deflater.end();
        return n;
    }

    private static double kraft(int[] lengths) {
        double sum = 0;
        for (int l : lengths) {
            if (l > 0) {
                sum += Math.pow(2, -l);
            }
        }
        return sum;
    }

    private static long cost(int[] counts, int[] lengths) {
        long total = 0;
        for (int s = 0; s < counts.length; s++) {
            total += (long) counts[s] * lengths[s];
        }
        return total;
    }

    /** The cost of an unlimited Huffman code: the sum of the merged weights. */
    private static long huffmanCost(int[] counts) {
        PriorityQueue<Long> queue = new PriorityQueue<>();
        for (int c : counts) {
            if (c > 0) {
                queue.add((long) c);
            }
        }
        long total = 0;
        while (queue.size() > 1) {
            long merged = queue.poll() + queue.poll();
            total += merged;
            queue.add(merged);
        }
        return total;
    }

    /** The depth of an unlimited Huffman code's longest codeword. */
    private static int optimalDepth(int[] counts) {
        PriorityQueue<long[]> queue = new PriorityQueue<>((x, y) -> x[0] != y[0] ? Long.compare(x[0], y[0])
                : Long.compare(x[1], y[1]));
        for (int c : counts) {
            if (c > 0) {
                queue.add(new long[] {c, 0});
            }
        }
        while (queue.size() > 1) {
            long[] x = queue.poll();
            long[] y = queue.poll();
            queue.add(new long[] {x[0] + y[0], Math.max(x[1], y[1]) + 1});
        }
        return (int) queue.poll()[1];
    }
}
