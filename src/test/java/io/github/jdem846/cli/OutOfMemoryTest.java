package io.github.jdem846.cli;

import io.github.jdem846.testing.TestJvm;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** Running out of Java heap gives one line saying so and what to do, exit status 1 and no output file. */
class OutOfMemoryTest {

    @TempDir
    Path tmp;

    @CommandLine.Command(name = "greedy")
    static final class Greedy implements Callable<Integer> {
        @Override
        public Integer call() {
            throw new OutOfMemoryError("Java heap space");
        }
    }

    @Test
    void anOutOfMemoryErrorBecomesOneLineWithTheRemedy() {
        CommandLine cl = new CommandLine(new Greedy());
        StringWriter err = new StringWriter();
        cl.setErr(new PrintWriter(err, true));
        assertEquals(1, Main.execute(cl, new String[0]));
        String message = err.toString().strip();
        assertTrue(message.startsWith("jdem846: out of memory"), message);
        assertTrue(message.contains("--scale") && message.contains("-Xmx") && message.contains("iB)"), message);
        assertEquals(1, message.lines().count(), message);
    }

    /**
     * A real render in a JVM whose heap holds the grid but not the grid, the shadow layer and the picture, with a
     * memory budget as large as the heap ({@code --memory 64m}), so that the picture is rendered in memory (at the
     * default budget, half the heap, it would be rendered in tiles and succeed): 2360² × 12 bytes = 63.7 MiB of
     * arrays, more than a 64 MiB heap holds with anything else in it. No stack trace, exit 1, nothing written.
     * (Whether the read's own heap check or the render runs out first depends on the JVM's accounting; both must
     * end the same way.)
     */
    @Test
    void aRenderTooLargeForTheHeapEndsCleanly() throws IOException, InterruptedException {
        int n = 2360;                                       // 22 MB of float32 in a 64 MB heap
        Path flt = tmp.resolve("big.flt");
        byte[] cells = new byte[n * n * 4];
        for (int i = 0; i < n * n; i++) {
            int bits = Float.floatToIntBits(100f + (i % n) * 0.5f + (i / n) * 0.25f);
            cells[4 * i] = (byte) bits;
            cells[4 * i + 1] = (byte) (bits >>> 8);
            cells[4 * i + 2] = (byte) (bits >>> 16);
            cells[4 * i + 3] = (byte) (bits >>> 24);
        }
        Files.write(flt, cells);
        Files.writeString(tmp.resolve("big.hdr"), "ncols " + n + "\nnrows " + n
                + "\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\nbyteorder LSBFIRST\n");
        Path png = tmp.resolve("big.png");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(List.of(java, "-Xmx64m", "-cp", TestJvm.classPath(),
                Main.class.getName(), "render", flt.toString(), "-q", "--shadows", "sweep", "--memory", "64m", "-o",
                png.toString()))
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        assertEquals(1, p.exitValue(), output);
        assertTrue(output.startsWith("jdem846: ") && output.contains("heap"), output);
        assertFalse(output.contains("\tat ") || output.contains("Exception in thread"), "no stack trace: " + output);
        assertFalse(Files.exists(png), "no picture written");
        try (var files = Files.list(tmp)) {
            assertEquals(2, files.count(), "no temporary file left beside the picture");
        }
    }
}
