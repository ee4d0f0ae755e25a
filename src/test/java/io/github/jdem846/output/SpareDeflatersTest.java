package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import io.github.jdem846.testing.TestDems;
import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.zip.Deflater;
import org.junit.jupiter.api.Test;

class SpareDeflatersTest {

    @Test
    void aReusedDeflaterMakesTheBytesOfANewOne() {
        // real elevations as bytes, deflated with either strategy in turns, as PNG segments are
        float[] v = TestDems.load(TestDems.BIG_TUJUNGA).backingArray();
        ByteBuffer bytes = ByteBuffer.allocate(4 * 60_000);
        for (int i = 0; i < 60_000; i++) {
            bytes.putFloat(v[i]);
        }
        byte[] input = bytes.array();
        for (boolean nowrap : new boolean[] {true, false}) {
            SpareDeflaters spare = new SpareDeflaters(1, nowrap);
            Deflater first = spare.take();
            deflate(first, input, Deflater.HUFFMAN_ONLY);
            spare.give(first);
            int[] strategies = {Deflater.DEFAULT_STRATEGY, Deflater.HUFFMAN_ONLY, Deflater.DEFAULT_STRATEGY};
            for (int strategy : strategies) {
                Deflater reused = spare.take();
                assertSame(first, reused, "the spare one is taken");
                Deflater fresh = new Deflater(1, nowrap);
                assertArrayEquals(deflate(fresh, input, strategy), deflate(reused, input, strategy),
                        "nowrap " + nowrap + ", strategy " + strategy);
                fresh.end();
                spare.give(reused);
            }
            spare.end();
        }
    }

    private static byte[] deflate(Deflater d, byte[] input, int strategy) {
        d.setStrategy(strategy);
        d.setInput(input);
        d.finish();
        byte[] out = new byte[input.length + 1024];
        int n = 0;
        while (!d.finished()) {
            n += d.deflate(out, n, out.length - n);
        }
        return Arrays.copyOf(out, n);
    }
}
