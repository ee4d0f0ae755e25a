package io.github.jdem846.cli;

import io.github.jdem846.testing.TestJvm;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.testing.SingleStripTiff;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The start-up warm-up reads within a small memory budget and never prints: on a file whose first rows need a
 * huge strip decoded, in a small heap, the user sees the command's own one-line refusal and nothing else.
 */
class WarmUpMemoryTest {

    @TempDir
    Path tmp;

    @Test
    void aHugeStripInASmallHeapGivesOnlyTheCommandsOwnLine() throws IOException, InterruptedException {
        Path tif = SingleStripTiff.write(tmp.resolve("strip.tif"), 6000);   // 72 MB decoded, a 48 MB heap
        Path png = tmp.resolve("hs.png");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(List.of(java, "-Xmx48m", "-D" + WarmUpThread.PROPERTY + "=on", "-cp",
                TestJvm.classPath(), Main.class.getName(), "hillshade", tif.toString(), "-q", "-o", png.toString()))
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "finished");
        assertEquals(1, p.exitValue(), output);
        assertEquals(1, output.lines().count(), "one line: " + output);
        assertTrue(output.startsWith("jdem846: ") && output.contains("heap"), output);
        assertFalse(output.contains("Exception") || output.contains("Error"), output);
        assertFalse(Files.exists(png));
    }

    @Test
    void theWarmUpDoesNotDecodeAStripLargerThanItsBudgetWhereTheHeapWouldAllowIt() throws IOException {
        long limit = InputWarmUp.warmUpMemoryLimit();
        assertTrue(limit > 0 && limit <= 64L << 20 && limit <= Runtime.getRuntime().maxMemory() / 16, "" + limit);
        Path huge = SingleStripTiff.write(tmp.resolve("huge.tif"), 6000);    // 72 MB decoded
        ReadRequest hugeFirstRows = InputWarmUp.firstRows(DemReader.inspect(huge));
        assertEquals(new ReadRequest(Window.cells(0, 0, 512, 256), 1, limit), hugeFirstRows);
        assertThrows(DemFormatException.class, () -> DemReader.read(huge, hugeFirstRows));
        assertEquals(512, DemReader.read(huge, ReadRequest.of(hugeFirstRows.window())).width(), "the heap allows it");
        Path small = SingleStripTiff.write(tmp.resolve("small.tif"), 1000);  // 2 MB decoded
        assertEquals(512, DemReader.read(small, InputWarmUp.firstRows(DemReader.inspect(small))).width());
    }
}
