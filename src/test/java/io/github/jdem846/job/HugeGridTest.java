package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.TestJvm;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A GridFloat of 46 341 × 46 341 = 2 147 488 281 cells, more than one Java array holds (a sparse file of 8.6 GB of
 * zeros, which takes no disk space), is rendered at full resolution in a JVM of 96 MB: in tiles, the progress
 * counting all its pixels, each band right as it arrives ({@link HugeGridRender}). The whole run takes minutes on two
 * cores (docs/scale.md gives the figures); the test checks the first two bands, then interrupts the job, which stops
 * without committing its output.
 */
class HugeGridTest {

    private static final int SIDE = 46_341;

    @TempDir
    Path tmp;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aGridOfMoreCellsThanAJavaArrayRendersInTilesInASmallHeap() throws IOException, InterruptedException {
        Path huge = flat("huge", SIDE);
        Path small = flat("small", 5);
        Process p = new ProcessBuilder(List.of(TestJvm.java(), "-Xmx96m", "-cp", TestJvm.classPath(),
                HugeGridRender.class.getName(), huge.toString(), small.toString(), "2"))
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(100, TimeUnit.SECONDS), "finished");
        assertEquals(0, p.exitValue(), output);
        String[] f = output.split(" ");
        assertEquals(9, f.length, output);
        assertEquals("ok", f[0], output);
        assertEquals(SIDE, Integer.parseInt(f[1]), "width: " + output);
        assertEquals(SIDE, Integer.parseInt(f[2]), "height: " + output);
        int rows = Integer.parseInt(f[3]);
        assertTrue(rows >= 32 && rows < SIDE / 10, "two bands of rows checked: " + output);
        assertEquals((long) SIDE * SIDE, Long.parseLong(f[4]), "progress counts every pixel: " + output);
        assertTrue(Long.parseLong(f[4]) > Integer.MAX_VALUE);
        assertTrue(Integer.parseInt(f[5]) <= 96, "peak heap in MiB: " + output);
        assertEquals(1, Integer.parseInt(f[6]), "full-width bands: " + output);
        assertTrue(Integer.parseInt(f[7]) > 100, "bands: " + output);
        assertEquals("false", f[8], "an interrupted job commits nothing: " + output);
    }

    /** A flat GridFloat of {@code side}² zeros, 30 m cells, unknown CRS; sparse on disk. */
    private Path flat(String name, int side) throws IOException {
        Path flt = tmp.resolve(name + ".flt");
        try (RandomAccessFile f = new RandomAccessFile(flt.toFile(), "rw")) {
            f.setLength((long) side * side * Float.BYTES);
        } catch (IOException e) {
            Assumptions.assumeTrue(false, "this file system cannot hold a sparse file of "
                    + (long) side * side * Float.BYTES + " bytes: " + e.getMessage());
        }
        Files.writeString(tmp.resolve(name + ".hdr"), "ncols " + side + "\nnrows " + side + "\nxllcorner 0\n"
                + "yllcorner 0\ncellsize 30\nbyteorder LSBFIRST\n");
        return flt;
    }
}
